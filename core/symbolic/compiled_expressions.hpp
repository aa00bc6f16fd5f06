#pragma once
// GiNaC expressions compiled once into a flat instruction tape evaluated with doubles:
// what a simulation needs from a derivation thousands of times per simulated second,
// without GiNaC (whose substitution and evalf allocate and run exact arithmetic).
//
// Compilation walks each expression once. Every operation is hash-consed on (operation,
// operands, constant), so a subtree that occurs twice (within one output or across
// outputs, e.g. cos(theta1 - theta2) in B, C and g) is computed once; operations on
// constants are folded at compile time. Sums become chains of + and −, products split
// into numerator and denominator (one division), integer powers become multiplications
// by repeated squaring, x^(1/2) a square root. Supported: numbers, symbols listed as
// inputs, + * ^ (integer, rational, real and symbolic exponents), π and GiNaC's other
// constants, sin cos tan exp log sqrt tanh sinh cosh asin acos atan atan2 abs step
// (step(0) = 1/2 as in GiNaC) csgn; the inputs are real, so conjugate(x) and
// real_part(x) are x and imag_part(x) is 0 (GiNaC writes abs(x)^2 as x conjugate(x)).
//
// The result is an ExpressionTape (core/math): plain data with no GiNaC inside, so it
// can be evaluated on any thread while GiNaC is busy elsewhere.
#include <vector>

#include <ginac/ginac.h>

#include "core/math/expression_tape.hpp"

namespace ll::symbolic {

// Throws std::invalid_argument naming the symbol or function it cannot compile (a
// symbol not among `inputs`, a complex number, an unsupported function). Call with
// the GiNaC lock held (ginac_lock.hpp).
ExpressionTape compileExpressions(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs);

// A named quantity: `symbol` stands for `value` in later definitions and in the outputs
// (the structured form's table of names, c_i for cos q_i), computed once, in order.
struct TapeDefinition {
    GiNaC::ex symbol;
    GiNaC::ex value;
};
ExpressionTape compileExpressions(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs,
                                  const std::vector<TapeDefinition>& definitions);

}  // namespace ll::symbolic
