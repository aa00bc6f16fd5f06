#include "core/symbolic/compiled_expressions.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace ll::symbolic {
namespace {

using Op = ExpressionTape::Op;
using Instruction = ExpressionTape::Instruction;

double apply(Op op, double a, double b, double c) { return ExpressionTape::apply(op, a, b, c); }
bool binary(Op op) { return ExpressionTape::binary(op); }
bool commutative(Op op) { return op == Op::Add || op == Op::Mul; }

const std::map<std::string, Op>& functions() {
    static const std::map<std::string, Op> table = {{"sin", Op::Sin},   {"cos", Op::Cos},   {"tan", Op::Tan},   {"exp", Op::Exp},
                                                    {"log", Op::Log},   {"tanh", Op::Tanh}, {"sinh", Op::Sinh}, {"cosh", Op::Cosh},
                                                    {"asin", Op::Asin}, {"acos", Op::Acos}, {"atan", Op::Atan}, {"atan2", Op::Atan2},
                                                    {"abs", Op::Abs},   {"step", Op::Step}, {"sqrt", Op::Sqrt}, {"csgn", Op::Sign}};
    return table;
}

}  // namespace

// Builds one tape: registers are numbered as they are made (inputs first), each
// operation is looked up before it is emitted.
class TapeBuilder {
public:
    explicit TapeBuilder(const std::vector<GiNaC::symbol>& inputs) : inputs_(static_cast<int>(inputs.size())) {
        for (const GiNaC::symbol& s : inputs) {
            memo_[s] = newRegister(false, 0.0);
        }
    }

    // `symbol` stands for the register of `value` from now on.
    void define(const GiNaC::ex& symbol, const GiNaC::ex& value) { memo_[symbol] = compile(value); }

    int compile(const GiNaC::ex& e) {
        if (const auto found = memo_.find(e); found != memo_.end()) return found->second;
        const int r = build(e);
        memo_[e] = r;
        return r;
    }

    // Constants in place; inputs and results are overwritten per call.
    ExpressionTape finish(std::vector<int> outputs) { return ExpressionTape(inputs_, std::move(tape_), std::move(outputs), values_); }

private:
    int newRegister(bool isConstant, double value) {
        constant_.push_back(isConstant);
        values_.push_back(value);
        return static_cast<int>(values_.size()) - 1;
    }

    int constant(double value) {
        const auto key = std::bit_cast<std::uint64_t>(value);
        if (const auto found = constants_.find(key); found != constants_.end()) return found->second;
        return constants_[key] = newRegister(true, value);
    }

    bool isConstant(int r, double value) const { return constant_[r] && values_[r] == value; }

    int emit(Op op, int a, int b = -1, double c = 0.0) {
        if (commutative(op) && b < a) std::swap(a, b);
        // Identities that need no instruction.
        if ((op == Op::Add && isConstant(a, 0.0)) || (op == Op::Mul && isConstant(a, 1.0))) return b;
        if ((op == Op::Sub || op == Op::Add) && isConstant(b, 0.0)) return a;
        if ((op == Op::Mul || op == Op::Div) && isConstant(b, 1.0)) return a;
        if (op == Op::Mul && isConstant(a, -1.0)) return emit(Op::Neg, b);
        if (constant_[a] && (!binary(op) || constant_[b]))  // folded now
            return constant(apply(op, values_[a], binary(op) ? values_[b] : 0.0, c));
        const auto key = std::make_tuple(op, a, binary(op) ? b : -1, std::bit_cast<std::uint64_t>(c));
        if (const auto found = operations_.find(key); found != operations_.end()) return found->second;
        const int r = newRegister(false, 0.0);
        tape_.push_back({op, r, a, binary(op) ? b : a, c});
        return operations_[key] = r;
    }

    double number(const GiNaC::ex& e) const {
        const GiNaC::ex value = e.evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real())
            throw std::invalid_argument("cannot compile the non-real number " + text(e));
        return GiNaC::ex_to<GiNaC::numeric>(value).to_double();
    }

    static std::string text(const GiNaC::ex& e) {
        std::ostringstream out;
        out << e;
        return out.str();
    }

    // b^n for an integer n >= 1 by repeated squaring.
    int integerPower(int base, long n) {
        if (n == 1) return base;
        if (n == 2) return emit(Op::Square, base);
        const int half = integerPower(base, n / 2);
        const int square = emit(Op::Square, half);
        return n % 2 ? emit(Op::Mul, square, base) : square;
    }

    int power(const GiNaC::ex& e) {
        const int base = compile(e.op(0));
        const GiNaC::ex& exponent = e.op(1);
        if (!GiNaC::is_a<GiNaC::numeric>(exponent)) return emit(Op::Pow, base, compile(exponent));
        const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(exponent);
        if (n.is_integer() && GiNaC::abs(n) < 1 << 30) {
            const long k = n.to_long();
            if (k == 0) return constant(1.0);
            const int p = integerPower(base, std::abs(k));
            return k > 0 ? p : emit(Op::Recip, p);
        }
        if (n == GiNaC::numeric(1, 2)) return emit(Op::Sqrt, base);
        if (n == GiNaC::numeric(-1, 2)) return emit(Op::Recip, emit(Op::Sqrt, base));
        return emit(Op::PowConst, base, -1, number(n));
    }

    // Σ c_i t_i as a chain of + and −, a coefficient ±1 costing nothing; the constant
    // terms (sin(1) + 2) are summed at compile time and added last.
    int sum(const GiNaC::ex& e) {
        int acc = -1;
        double constantPart = 0.0;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const GiNaC::ex& term = e.op(i);
            double c = 1.0;
            GiNaC::ex rest = term;
            if (GiNaC::is_a<GiNaC::mul>(term) && GiNaC::is_a<GiNaC::numeric>(term.op(term.nops() - 1))) {
                c = number(term.op(term.nops() - 1));
                rest = term / term.op(term.nops() - 1);
            }
            const int t = compile(rest);
            if (constant_[t]) {
                constantPart += c * values_[t];
                continue;
            }
            const int scaled = std::abs(c) == 1.0 ? t : emit(Op::Mul, t, constant(std::abs(c)));
            if (acc < 0) acc = c < 0 ? emit(Op::Neg, scaled) : scaled;
            else acc = emit(c < 0 ? Op::Sub : Op::Add, acc, scaled);
        }
        if (acc < 0) return constant(constantPart);
        return constantPart < 0 ? emit(Op::Sub, acc, constant(-constantPart)) : emit(Op::Add, acc, constant(constantPart));
    }

    // Constant factors first (folded into one), then the others by register, so that
    // a*b is shared by a*b*c and a*b*d.
    int product(std::vector<int> factors) {
        std::sort(factors.begin(), factors.end(), [&](int a, int b) { return constant_[a] != constant_[b] ? bool(constant_[a]) : a < b; });
        int acc = factors.front();
        for (std::size_t i = 1; i < factors.size(); ++i) acc = emit(Op::Mul, acc, factors[i]);
        return acc;
    }

    // coefficient · Π numerators / Π denominators, with one division.
    int quotient(const GiNaC::ex& e) {
        double coefficient = 1.0;
        std::vector<int> numerators, denominators;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const GiNaC::ex& f = e.op(i);
            if (GiNaC::is_a<GiNaC::numeric>(f)) {
                coefficient *= number(f);
            } else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
                       GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative()) {
                denominators.push_back(compile(GiNaC::pow(f.op(0), -f.op(1))));
            } else {
                numerators.push_back(compile(f));
            }
        }
        int r = numerators.empty() ? constant(coefficient) : product(numerators);
        if (!numerators.empty() && coefficient != 1.0) r = coefficient == -1.0 ? emit(Op::Neg, r) : emit(Op::Mul, r, constant(coefficient));
        if (denominators.empty()) return r;
        const int d = product(denominators);
        return isConstant(r, 1.0) ? emit(Op::Recip, d) : emit(Op::Div, r, d);
    }

    int call(const GiNaC::ex& e) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
        // The inputs are real: GiNaC's abs(x)^2 = x conjugate(x) and the like.
        if ((name == "conjugate" || name == "real_part") && e.nops() == 1) return compile(e.op(0));
        if (name == "imag_part" && e.nops() == 1) return constant(0.0);
        const auto found = functions().find(name);
        if (found == functions().end() || e.nops() != (found->second == Op::Atan2 ? 2u : 1u))
            throw std::invalid_argument("cannot compile the function " + name + " in " + text(e));
        const int a = compile(e.op(0));
        return found->second == Op::Atan2 ? emit(Op::Atan2, a, compile(e.op(1))) : emit(found->second, a);
    }

    int build(const GiNaC::ex& e) {
        if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return constant(number(e));
        if (GiNaC::is_a<GiNaC::symbol>(e)) throw std::invalid_argument("cannot compile " + text(e) + ": it is not one of the inputs");
        if (GiNaC::is_a<GiNaC::add>(e)) return sum(e);
        if (GiNaC::is_a<GiNaC::mul>(e)) return quotient(e);
        if (GiNaC::is_a<GiNaC::power>(e)) return power(e);
        if (GiNaC::is_a<GiNaC::function>(e)) return call(e);
        throw std::invalid_argument("cannot compile " + text(e) + " (not a number, symbol, +, *, ^ or function)");
    }

    int inputs_;
    std::vector<Instruction> tape_;
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> memo_;
    std::map<std::tuple<Op, int, int, std::uint64_t>, int> operations_;
    std::map<std::uint64_t, int> constants_;
    std::vector<bool> constant_;
    std::vector<double> values_;
};

ExpressionTape compileExpressions(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs) {
    return compileExpressions(outputs, inputs, {});
}

ExpressionTape compileExpressions(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::symbol>& inputs,
                                  const std::vector<TapeDefinition>& definitions) {
    TapeBuilder builder(inputs);
    for (const TapeDefinition& d : definitions) builder.define(d.symbol, d.value);
    std::vector<int> registers;
    for (const GiNaC::ex& e : outputs) registers.push_back(builder.compile(e));
    return builder.finish(std::move(registers));
}

}  // namespace ll::symbolic
