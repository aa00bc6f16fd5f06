#pragma once
// Decimal scene numbers became exact rationals (0.4318 → 2159/5000); for display they
// are shown as decimals again. Other fractions (1/2, 1/24) stay fractions, as a
// textbook has them. Call with the GiNaC lock held.
#include <ginac/ginac.h>

namespace ll::symbolic {

bool isDecimalFraction(const GiNaC::numeric& v);

// e with every decimal fraction as a float (for printing only).
GiNaC::ex readableNumbers(const GiNaC::ex& e);

// What readableNumbers changes in e: nothing (no decimal fraction in it); only the
// coefficients and the number of a sum (no finite fraction in its terms' rests, as in
// every named quantity and expanded entry); or every finite fraction anywhere.
enum class ReadableChange { None, Coefficients, Everywhere };
ReadableChange readableChange(const GiNaC::ex& e);

// v as readableNumbers shows it where it changes numbers: a finite fraction as a float.
GiNaC::numeric readableNumber(const GiNaC::numeric& v);

}  // namespace ll::symbolic
