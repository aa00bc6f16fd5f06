#pragma once
// GiNaC keeps a sum as (rest, coefficient) pairs and a number, a product as (base,
// exponent) pairs and a coefficient; op(i) makes each term or power anew (for a sum of
// thousands of terms, a product allocated and evaluated per term, then split again by
// whoever rebuilds the sum). The printers read the pairs in place: a pointer to
// expairseq's protected members, formed through this derived class as the language
// allows, applies to any sum or product. No object is ever cast to this class, or made.
// Call with the GiNaC lock held.
#include <ginac/ginac.h>

namespace ll::symbolic {

struct GinacPairs : GiNaC::expairseq {
    // In op()'s order: op(i) is pairs[i] recombined, then the number when it is not the
    // neutral one (0 for a sum, 1 for a product).
    static const GiNaC::epvector& of(const GiNaC::expairseq& e) { return e.*(&GinacPairs::seq); }
    static const GiNaC::ex& number(const GiNaC::expairseq& e) { return e.*(&GinacPairs::overall_coeff); }
};

}  // namespace ll::symbolic
