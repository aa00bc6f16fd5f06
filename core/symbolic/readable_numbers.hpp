#pragma once
// Decimal scene numbers became exact rationals (0.4318 → 2159/5000); for display they
// are shown as decimals again. Other fractions (1/2, 1/24) stay fractions, as a
// textbook has them. Call with the GiNaC lock held.
#include <ginac/ginac.h>

namespace ll::symbolic {

bool isDecimalFraction(const GiNaC::numeric& v);

// e with every decimal fraction as a float (for printing only).
GiNaC::ex readableNumbers(const GiNaC::ex& e);

}  // namespace ll::symbolic
