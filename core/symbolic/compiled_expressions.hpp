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
// evaluate() writes into registers sized at construction: no allocation per call. The
// registers make an object single-threaded; copy it for another thread.
#include <cstdint>
#include <vector>

#include <ginac/ginac.h>

namespace ll::symbolic {

class CompiledExpressions {
public:
    CompiledExpressions() = default;
    // Throws std::invalid_argument naming the symbol or function it cannot compile (a
    // symbol not among `inputs`, a complex number, an unsupported function).
    CompiledExpressions(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs);

    int inputCount() const { return inputs_; }
    int outputCount() const { return static_cast<int>(outputs_.size()); }
    int instructionCount() const { return static_cast<int>(tape_.size()); }

    // output[k] = outputs[k](input); input holds inputCount() values in the order of
    // `inputs`, output room for outputCount().
    void evaluate(const double* input, double* output) const;

    enum class Op : std::uint8_t {
        Add, Sub, Mul, Div, Neg, Recip, Square, PowConst, Pow, Sqrt,
        Sin, Cos, Tan, Exp, Log, Tanh, Sinh, Cosh, Asin, Acos, Atan, Atan2, Abs, Step, Sign
    };

private:
    struct Instruction {
        Op op;
        int result, a, b;  // register indices (b unused by one-operand operations)
        double c;          // PowConst's exponent
    };
    friend class TapeBuilder;

    int inputs_ = 0;
    std::vector<Instruction> tape_;
    std::vector<int> outputs_;              // register of each output
    mutable std::vector<double> registers_;  // inputs, constants (set once), results
};

}  // namespace ll::symbolic
