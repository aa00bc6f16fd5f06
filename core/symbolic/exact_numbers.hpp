#pragma once
// Numbers from a scene as exact GiNaC numbers, so symbolic cancellation is exact
// (0.4318 becomes 2159/5000, not a float that leaves 1e-17 residues), and angles that
// are multiples of π/12 become exact multiples of Pi (cos(π/2) is then exactly 0).
#include <ginac/ginac.h>

namespace ll::symbolic {

// The rational with the shortest decimal expansion that reads back as `value`.
GiNaC::ex exactNumber(double value);

// exactNumber, but a multiple of π/12 (to 1e-12) becomes k/12·Pi.
GiNaC::ex exactAngle(double value);

// `e` with every floating-point number in it made exact by exactNumber: a field typed as
// "0.5*m1" keeps m1 and gets 1/2 (the derivation's polynomial reductions refuse floats).
GiNaC::ex exactFloats(const GiNaC::ex& e);

}  // namespace ll::symbolic
