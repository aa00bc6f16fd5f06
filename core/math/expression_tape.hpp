#pragma once
// A flat instruction tape evaluated with doubles: the numeric form of expressions that
// the symbolic layer compiled once (core/symbolic/compiled_expressions). Plain data: it
// holds no GiNaC object, so a simulation worker can own a copy and evaluate it while
// another thread derives.
//
// Registers hold the inputs first, then constants (set once) and the results of the
// instructions in order. evaluate() writes into registers sized at construction: no
// allocation per call. The registers make an object single-threaded; copy it for
// another thread.
#include <cstdint>
#include <vector>

namespace ll {

class ExpressionTape {
public:
    enum class Op : std::uint8_t {
        Add,
        Sub,
        Mul,
        Div,
        Neg,
        Recip,
        Square,
        PowConst,
        Pow,
        Sqrt,
        Sin,
        Cos,
        Tan,
        Exp,
        Log,
        Tanh,
        Sinh,
        Cosh,
        Asin,
        Acos,
        Atan,
        Atan2,
        Abs,
        Step,
        Sign
    };
    struct Instruction {
        Op op;
        int result, a, b;  // register indices (b = a for one-operand operations)
        double c;          // PowConst's exponent
    };

    ExpressionTape() = default;
    // `registers` holds inputCount inputs (any value), the constants in place, and room
    // for every result; `outputs` names the register of each output.
    ExpressionTape(int inputCount, std::vector<Instruction> tape, std::vector<int> outputs, std::vector<double> registers);

    int inputCount() const { return inputs_; }
    int outputCount() const { return static_cast<int>(outputs_.size()); }
    int instructionCount() const { return static_cast<int>(tape_.size()); }

    // output[k] = outputs[k](input); input holds inputCount() values, output room for
    // outputCount().
    void evaluate(const double* input, double* output) const;

    // The one definition of every operation: used by evaluate() and by the compiler's
    // constant folding. step(0) = 1/2 as in GiNaC.
    static double apply(Op op, double a, double b, double c);
    static bool binary(Op op);

private:
    int inputs_ = 0;
    std::vector<Instruction> tape_;
    std::vector<int> outputs_;
    mutable std::vector<double> registers_;
};

}  // namespace ll
