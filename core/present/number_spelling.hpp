#pragma once
// How numbers read. A scene's decimals became exact rationals for the derivation
// (0.4318 → 2159/5000); they are shown as decimals again (NumberSpelling), while the
// formulas' own fractions (1/2, 1/24) stay fractions, as a textbook has them.
// Decimals show at most 6 significant digits (the Panda's products of identified
// inertials: 0.00796990221726315 → 0.0079699); Plain keeps a float's 17 digits and a
// rational's exact value, so what is re-parsed is the same number. Call with the GiNaC
// lock held.
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/present/display_tree.hpp"

namespace ll::present {

// The node of a number as GiNaC holds it: an integer, a fraction (a Fraction node), a
// float as a decimal (with a power of ten when %g would use one: 1e-05 → 1·10⁻⁵), a
// negative one as a negated Sum.
DisplayPtr numberNode(const GiNaC::numeric& n);

// An exponent's node: its digits (3/2, 0.5) in every style, Plain with 17 digits.
DisplayPtr exponentNode(const GiNaC::numeric& k);

// Whether a number may stand in front of a sum as a common factor: a small rational as
// formulas make them (½, ⅓, 2/5, 1/12, 3), never a decimal or a power of ten
// (−5·10⁻¹⁰ (8347998 + …) is not how anyone writes c₁₁).
bool formulaFactor(const GiNaC::numeric& c);

// Whether a rational could come from the formulas alone: the ½ of E_kin, the Christoffel
// ½, a rod's 1/12, a cylinder's ¼, a sphere's 2/5, and their products (1/10, 1/24, 4/3):
// a numerator of at most 12 and a denominator of at most 240 made of 2, 3, 5 and 7, with
// at most one 5 and then a numerator 1, 2, 4 or 8 (2/5 times halves). A typed decimal's
// arithmetic leaves larger numerators, a 25 in the denominator or tenths (9.8 is 49/5,
// 0.3·0.2 is 3/50, 0.4318 is 2159/5000, 0.7 + 0.2 is 9/10).
bool formulaMade(const GiNaC::numeric& v);

// How the numbers of one derivation read, from what the scene typed (`typed`: the values
// typed as decimals, as positive exact rationals: 1.375 typed is 11/8).
// A rational reads as a decimal (at most 6 significant digits) when it is not formula
// made, or when it is a typed value or a half, quarter, twice or four times one, as the
// ½ of E_kin, the Christoffel ½ and squares make them (1.375 → 1.375, ½·1.375 → 0.6875,
// 0.2 typed → 0.2 and 0.1 wherever ⅕ and 1/10 show); other rationals stay fractions (½,
// 2/5, 1/12), also when a typed 2.5 times ⅕ happens to make ½. A typed 0.5 or 0.25 reads as a decimal only standing alone (a DH entry 0.5): ½
// and ¼ are the formulas' own. The rule is per number, so one value reads the same in
// every entry of a matrix and every term of an equation. Plain keeps the exact rational
// ((2159/5000)), so JSON and re-parsing stay exact.
class NumberSpelling {
public:
    // allDigits: a decimal shows every digit it has (a rational whose denominator is made of
    // 2s and 5s), and one with endless digits stays a fraction: an answer key's right answer,
    // which a student may copy back and must find right, not 6 rounded digits.
    explicit NumberSpelling(std::vector<GiNaC::numeric> typed = {}, bool allDigits = false);
    // Whether n (real) reads as a decimal.
    bool decimal(const GiNaC::numeric& n, bool standalone = false) const;
    // The node of n as this derivation spells it.
    DisplayPtr node(const GiNaC::numeric& n, bool standalone = false) const;

private:
    std::vector<GiNaC::numeric> typed_;
    bool allDigits_ = false;
};

}  // namespace ll::present
