#pragma once
// GiNaC keeps a sum as (rest, coefficient) pairs and a number, a product as (base,
// exponent) pairs and a coefficient; op(i) makes each term or power anew (for a sum of
// thousands of terms, a product allocated and evaluated per term, then split again by
// whoever rebuilds the sum). The printers read the pairs in place: a pointer to
// expairseq's protected members, formed through this derived class as the language
// allows, applies to any sum or product. No object is ever cast to this class, or made.
// Call with the GiNaC lock held.
#include <ginac/ginac.h>

#include "core/symbolic/ginac_kind.hpp"

namespace ll::symbolic {

struct GinacPairs : GiNaC::expairseq {
    // In op()'s order: op(i) is pairs[i] recombined, then the number when it is not the
    // neutral one (0 for a sum, 1 for a product).
    static const GiNaC::epvector& of(const GiNaC::expairseq& e) { return e.*(&GinacPairs::seq); }
    static const GiNaC::ex& number(const GiNaC::expairseq& e) { return e.*(&GinacPairs::overall_coeff); }
};

// Whether visit(node, its GinacKind) is true for any node of e, visited parents first,
// stopping at the first. A sum's or product's children are its pairs' rests and
// coefficients (a product's exponents) and its number, read in place; any other node's
// are its op(i).
// The walk of every printer and lookup that asks what occurs in an expression: the
// symbols in it, whether it holds a number, a sine or a cosine.
template <class Visit>
bool anyNode(const GiNaC::ex& e, Visit& visit) {
    const GinacKind kind = ginacKind(e);
    if (visit(e, kind)) return true;
    switch (kind) {
        case GinacKind::Symbol:
        case GinacKind::Numeric:
        case GinacKind::Constant: return false;
        case GinacKind::Add:
        case GinacKind::Mul: {
            // A pair's coefficient and the number are numerics (GiNaC's invariant).
            const auto& seq = GiNaC::ex_to<GiNaC::expairseq>(e);
            for (const GiNaC::expair& p : GinacPairs::of(seq))
                if (anyNode(p.rest, visit) || visit(p.coeff, GinacKind::Numeric)) return true;
            return visit(GinacPairs::number(seq), GinacKind::Numeric);
        }
        default:
            for (std::size_t i = 0; i < e.nops(); ++i)
                if (anyNode(e.op(i), visit)) return true;
            return false;
    }
}

}  // namespace ll::symbolic
