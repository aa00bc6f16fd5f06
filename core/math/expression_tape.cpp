#include "core/math/expression_tape.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace ll {

ExpressionTape::ExpressionTape(int inputCount, std::vector<Instruction> tape, std::vector<int> outputs, std::vector<double> registers)
    : inputs_(inputCount), tape_(std::move(tape)), outputs_(std::move(outputs)), registers_(std::move(registers)) {
    const int size = static_cast<int>(registers_.size());
    const auto valid = [&](int r) { return r >= 0 && r < size; };
    bool ok = inputs_ >= 0 && inputs_ <= size;
    for (const Instruction& in : tape_) ok = ok && valid(in.result) && valid(in.a) && valid(in.b);
    for (int r : outputs_) ok = ok && valid(r);
    if (!ok) throw std::invalid_argument("ExpressionTape: a register index outside the " + std::to_string(size) + " registers");
}

double ExpressionTape::apply(Op op, double a, double b, double c) {
    switch (op) {
        case Op::Add: return a + b;
        case Op::Sub: return a - b;
        case Op::Mul: return a * b;
        case Op::Div: return a / b;
        case Op::Neg: return -a;
        case Op::Recip: return 1.0 / a;
        case Op::Square: return a * a;
        case Op::PowConst: return std::pow(a, c);
        case Op::Pow: return std::pow(a, b);
        case Op::Sqrt: return std::sqrt(a);
        case Op::Sin: return std::sin(a);
        case Op::Cos: return std::cos(a);
        case Op::Tan: return std::tan(a);
        case Op::Exp: return std::exp(a);
        case Op::Log: return std::log(a);
        case Op::Tanh: return std::tanh(a);
        case Op::Sinh: return std::sinh(a);
        case Op::Cosh: return std::cosh(a);
        case Op::Asin: return std::asin(a);
        case Op::Acos: return std::acos(a);
        case Op::Atan: return std::atan(a);
        case Op::Atan2: return std::atan2(a, b);
        case Op::Abs: return std::abs(a);
        case Op::Step: return a > 0.0 ? 1.0 : a < 0.0 ? 0.0 : 0.5;
        case Op::Sign: return a > 0.0 ? 1.0 : a < 0.0 ? -1.0 : 0.0;
    }
    return 0.0;
}

bool ExpressionTape::binary(Op op) {
    return op == Op::Add || op == Op::Sub || op == Op::Mul || op == Op::Div || op == Op::Pow || op == Op::Atan2;
}

void ExpressionTape::evaluate(const double* input, double* output) const {
    double* r = registers_.data();
    std::copy(input, input + inputs_, r);
    for (const Instruction& in : tape_) r[in.result] = apply(in.op, r[in.a], r[in.b], in.c);
    for (std::size_t k = 0; k < outputs_.size(); ++k) output[k] = r[outputs_[k]];
}

}  // namespace ll
