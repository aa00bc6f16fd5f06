#pragma once
// How numbers read. A scene's decimals became exact rationals for the derivation
// (0.4318 → 2159/5000); they are shown as decimals again, and once one decimal shows in
// an expression every fraction with a finite decimal form shows as one too (0.2, not 1/5
// beside 0.1). Other fractions (1/2, 1/24) stay fractions, as a textbook has them.
// Decimals show at most 6 significant digits (the Panda's products of identified
// inertials: 0.00796990221726315 → 0.0079699); Plain keeps 17, so what is re-parsed is
// exact. Call with the GiNaC lock held.
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/present/display_tree.hpp"

namespace ll::present {

// The node of a number: an integer, a fraction (a Fraction node), a decimal (with a
// power of ten when %g would use one: 1e-05 → 1·10⁻⁵), a negative one as a negated Sum.
DisplayPtr numberNode(const GiNaC::numeric& n);

// An exponent's node: its digits (3/2, 0.5) in every style, Plain with 17 digits.
DisplayPtr exponentNode(const GiNaC::numeric& k);

// Whether v is a decimal fraction a scene could have typed: 2^a 5^b in the denominator
// (a finite decimal) and more than 8 of it (1/2, 3/8 stay fractions unless another
// decimal shows).
bool isDecimalFraction(const GiNaC::numeric& v);

// Whether a number may stand in front of a sum as a common factor: a small rational as
// formulas make them (½, ⅓, 2/5, 1/12, 3), never a decimal or a power of ten
// (−5·10⁻¹⁰ (8347998 + …) is not how anyone writes c₁₁).
bool formulaFactor(const GiNaC::numeric& c);

// e with every fraction that has a finite decimal form as a float, when e holds at least
// one decimal fraction or one of the numbers the scene typed as decimals (`typed`, as
// positive rationals: 1.375 typed is 11/8 and reads 1.375 again; a typed 0.5 or 0.25 only
// when it is all of e, as ½ and ¼ are the formulas' too); else e itself. For showing only.
GiNaC::ex readableNumbers(const GiNaC::ex& e, const std::vector<GiNaC::numeric>& typed = {});

}  // namespace ll::present
