#include "core/symbolic/function_identity.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace ll::symbolic {

using GiNaC::ex;
using GiNaC::numeric;

std::uint64_t IdentitySampler::residue() { return next() % ((std::uint64_t(1) << 61) - 1); }

std::uint64_t IdentitySampler::next() {  // xorshift64*: reproducible for a seed, no global state
    state_ ^= state_ >> 12;
    state_ ^= state_ << 25;
    state_ ^= state_ >> 27;
    return state_ * 0x2545F4914F6CDD1DULL;
}

numeric IdentitySampler::rational() {
    const long top = static_cast<long>(next() % 2000001ULL) - 1000000L;
    const long bottom = static_cast<long>(next() % 999983ULL) + 17L;
    if (top == 0) return numeric(7, 13);
    return numeric(top, bottom);
}

namespace {

bool isSin(const ex& e) { return GiNaC::is_the_function<GiNaC::sin_SERIAL>(e); }
bool isCos(const ex& e) { return GiNaC::is_the_function<GiNaC::cos_SERIAL>(e); }
bool isTan(const ex& e) { return GiNaC::is_the_function<GiNaC::tan_SERIAL>(e); }

// sin or cos of an expanded argument, written out over sums and integer multiples.
ex trigOf(bool sine, const ex& argument) {
    if (GiNaC::is_a<GiNaC::add>(argument)) {
        const ex first = argument.op(0);
        const ex rest = argument - first;
        const ex sa = trigOf(true, first), ca = trigOf(false, first);
        const ex sb = trigOf(true, rest), cb = trigOf(false, rest);
        return sine ? sa * cb + ca * sb : ca * cb - sa * sb;
    }
    if (GiNaC::is_a<GiNaC::mul>(argument)) {
        numeric k = 1;
        ex rest = 1;
        for (std::size_t i = 0; i < argument.nops(); ++i) {
            if (GiNaC::is_a<numeric>(argument.op(i))) k *= GiNaC::ex_to<numeric>(argument.op(i));
            else rest *= argument.op(i);
        }
        if (k.is_integer() && k != 1 && k != -1 && GiNaC::abs(k) <= 64) {
            if (k.is_negative()) return sine ? -trigOf(true, -argument) : trigOf(false, -argument);
            const ex s1 = trigOf(true, rest), c1 = trigOf(false, rest);
            ex s = s1, c = c1;
            for (int m = 1; m < k.to_int(); ++m) {
                const ex sn = (s * c1 + c * s1).expand();
                const ex cn = (c * c1 - s * s1).expand();
                s = sn;
                c = cn;
            }
            return sine ? s : c;
        }
        if (k == -1) return sine ? -trigOf(true, -argument) : trigOf(false, -argument);
    }
    return sine ? GiNaC::sin(argument) : GiNaC::cos(argument);
}

struct TrigExpander : GiNaC::map_function {
    ex operator()(const ex& e) override {
        if (isSin(e) || isCos(e) || isTan(e)) {
            const ex argument = e.op(0).map(*this).expand();
            if (isTan(e)) return trigOf(true, argument) / trigOf(false, argument);
            return trigOf(isSin(e), argument);
        }
        return e.map(*this);
    }
};

// The symbols standing alone and the symbols that are the argument of a sin or cos.
struct Variables {
    std::set<ex, GiNaC::ex_is_less> symbols, angles;
};

void collect(const ex& e, Variables& v) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        v.symbols.insert(e);
        return;
    }
    if ((isSin(e) || isCos(e)) && GiNaC::is_a<GiNaC::symbol>(e.op(0))) {
        v.angles.insert(e.op(0));
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) collect(e.op(i), v);
}

template <class N>
struct PointOf {
    std::map<ex, N, GiNaC::ex_is_less> value, t;  // a symbol's value alone; an angle's t
};
using Point = PointOf<numeric>;

// ---- The same test in the integers modulo the prime 2⁶¹ − 1 --------------------------------
// Two values that differ there differ as rationals, so most "different" verdicts (the
// feedback asks many) are settled in microseconds; "the same" is always confirmed in
// GiNaC's rationals.

using Residue = std::uint64_t;
constexpr Residue kPrime = (Residue(1) << 61) - 1;
using ModPoint = PointOf<Residue>;

Residue addMod(Residue a, Residue b) { return (a + b) % kPrime; }
Residue subMod(Residue a, Residue b) { return (a + kPrime - b) % kPrime; }
__extension__ typedef unsigned __int128 Wide;  // GCC's 128-bit integer: a product of two residues
Residue mulMod(Residue a, Residue b) { return static_cast<Residue>((static_cast<Wide>(a) * b) % kPrime); }
Residue powMod(Residue a, std::uint64_t n) {
    Residue r = 1;
    for (; n; n >>= 1, a = mulMod(a, a))
        if (n & 1) r = mulMod(r, a);
    return r;
}
Residue inverseMod(Residue a) { return powMod(a, kPrime - 2); }  // Fermat; a ≠ 0

std::optional<Residue> residueOf(const numeric& n) {
    if (!n.is_rational()) return std::nullopt;
    const numeric P(static_cast<long>(kPrime));
    const Residue top = static_cast<Residue>(GiNaC::mod(n.numer(), P).to_long());
    const Residue bottom = static_cast<Residue>(GiNaC::mod(n.denom(), P).to_long());
    if (bottom == 0) return std::nullopt;
    return mulMod(top, inverseMod(bottom));
}

struct Pole {};

// A value that is not a real number (the answer's √ of a negative value, log of one): the
// answer is not a function the test can compare.
struct NotARealValue : std::domain_error {
    using std::domain_error::domain_error;
};

struct Value {
    numeric number;
    bool exact = true;
    bool pole = false;
};

class DigitsScope {
public:
    explicit DigitsScope(long digits) : saved_(GiNaC::Digits) { GiNaC::Digits = digits; }
    ~DigitsScope() { GiNaC::Digits = saved_; }

private:
    long saved_;
};

}  // namespace

// The expression in post-order, for evaluating modulo the prime at many points without
// walking GiNaC's tree: constants reduced once, symbols and angles by index.
struct SampledFunction::ModTape {
    enum class Kind : unsigned char { Constant, Symbol, Cos, Sin, Add, Mul, Power };
    struct Op {
        Kind kind;
        std::uint32_t operand;  // Constant: index into constants; Symbol, Cos, Sin: variable; Add, Mul: operand count
        long exponent;          // Power
    };
    std::vector<Op> ops;
    std::vector<Residue> constants;
    std::vector<ex> symbols, angles;  // the variables by index

    // False when a part has no value modulo the prime (π, √, a non-integer power, exp).
    bool add(const ex& e) {
        if (GiNaC::is_exactly_a<numeric>(e)) {
            const auto r = residueOf(GiNaC::ex_to<numeric>(e));
            if (!r) return false;
            ops.push_back({Kind::Constant, static_cast<std::uint32_t>(constants.size()), 0});
            constants.push_back(*r);
            return true;
        }
        if (GiNaC::is_exactly_a<GiNaC::symbol>(e)) {
            ops.push_back({Kind::Symbol, index(symbols, e), 0});
            return true;
        }
        if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
            for (std::size_t i = 0; i < e.nops(); ++i)
                if (!add(e.op(i))) return false;
            ops.push_back({GiNaC::is_exactly_a<GiNaC::add>(e) ? Kind::Add : Kind::Mul, static_cast<std::uint32_t>(e.nops()), 0});
            return true;
        }
        if (GiNaC::is_exactly_a<GiNaC::power>(e)) {
            const ex n = e.op(1);
            if (!GiNaC::is_exactly_a<numeric>(n) || !GiNaC::ex_to<numeric>(n).is_integer() || !add(e.op(0))) return false;
            ops.push_back({Kind::Power, 0, GiNaC::ex_to<numeric>(n).to_long()});
            return true;
        }
        if ((isSin(e) || isCos(e)) && GiNaC::is_exactly_a<GiNaC::symbol>(e.op(0))) {
            ops.push_back({isCos(e) ? Kind::Cos : Kind::Sin, index(angles, e.op(0)), 0});
            return true;
        }
        return false;
    }

    static std::uint32_t index(std::vector<ex>& list, const ex& x) {
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list[i].is_equal(x)) return static_cast<std::uint32_t>(i);
        list.push_back(x);
        return static_cast<std::uint32_t>(list.size() - 1);
    }

    // The value at p; nothing at a pole.
    std::optional<Residue> value(const ModPoint& p, std::vector<Residue>& stack) const {
        std::vector<Residue> symbolValue(symbols.size()), angleT(angles.size());
        for (std::size_t i = 0; i < symbols.size(); ++i) {
            auto it = p.value.find(symbols[i]);
            symbolValue[i] = it == p.value.end() ? 0 : it->second;
        }
        for (std::size_t i = 0; i < angles.size(); ++i) {
            auto it = p.t.find(angles[i]);
            angleT[i] = it == p.t.end() ? 0 : it->second;
        }
        stack.clear();
        for (const Op& op : ops) {
            switch (op.kind) {
                case Kind::Constant: stack.push_back(constants[op.operand]); break;
                case Kind::Symbol: stack.push_back(symbolValue[op.operand]); break;
                case Kind::Cos:
                case Kind::Sin: {
                    const Residue t = angleT[op.operand], t2 = mulMod(t, t), one_t2 = addMod(1, t2);
                    if (one_t2 == 0) return std::nullopt;
                    stack.push_back(mulMod(op.kind == Kind::Cos ? subMod(1, t2) : mulMod(2, t), inverseMod(one_t2)));
                    break;
                }
                case Kind::Add:
                case Kind::Mul: {
                    const bool sum = op.kind == Kind::Add;
                    Residue r = sum ? 0 : 1;
                    for (std::uint32_t k = 0; k < op.operand; ++k) {
                        r = sum ? addMod(r, stack.back()) : mulMod(r, stack.back());
                        stack.pop_back();
                    }
                    stack.push_back(r);
                    break;
                }
                case Kind::Power: {
                    const Residue base = stack.back();
                    stack.pop_back();
                    if (op.exponent < 0 && base == 0) return std::nullopt;
                    stack.push_back(op.exponent >= 0 ? powMod(base, static_cast<std::uint64_t>(op.exponent))
                                                     : powMod(inverseMod(base), static_cast<std::uint64_t>(-op.exponent)));
                    break;
                }
            }
        }
        return stack.back();
    }
};

namespace {

// e's value where every number met is rational, by walking the expression once (no
// substituted copy is built); nothing when a value on the way is not rational (π, √2, the
// sine of anything but a symbol), which the caller then evaluates the slow way.
std::optional<numeric> exactValue(const ex& e, const Point& p) {
    if (GiNaC::is_exactly_a<numeric>(e)) {
        const numeric& n = GiNaC::ex_to<numeric>(e);
        if (!n.is_rational()) return std::nullopt;
        return n;
    }
    if (GiNaC::is_exactly_a<GiNaC::symbol>(e)) {
        auto it = p.value.find(e);
        if (it == p.value.end()) return std::nullopt;
        return it->second;
    }
    if (GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e)) {
        const bool sum = GiNaC::is_exactly_a<GiNaC::add>(e);
        numeric total = sum ? 0 : 1;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const auto v = exactValue(e.op(i), p);
            if (!v) return std::nullopt;
            total = sum ? total + *v : total * *v;
        }
        return total;
    }
    if (GiNaC::is_exactly_a<GiNaC::power>(e)) {
        const ex exponent = e.op(1);
        if (!GiNaC::is_exactly_a<numeric>(exponent) || !GiNaC::ex_to<numeric>(exponent).is_integer()) return std::nullopt;
        const auto base = exactValue(e.op(0), p);
        if (!base) return std::nullopt;
        const numeric& n = GiNaC::ex_to<numeric>(exponent);
        if (base->is_zero() && n.is_negative()) throw Pole();
        return base->power(n);
    }
    if ((isSin(e) || isCos(e)) && GiNaC::is_exactly_a<GiNaC::symbol>(e.op(0))) {
        auto it = p.t.find(e.op(0));
        if (it == p.t.end()) return std::nullopt;
        const numeric& t = it->second;
        const numeric one_t2 = 1 + t * t;
        return isCos(e) ? (1 - t * t) / one_t2 : 2 * t / one_t2;
    }
    return std::nullopt;
}

Value evaluate(const ex& e, const Point& p) {
    Value out;
    try {
        if (const auto exact = exactValue(e, p)) {
            out.number = *exact;
            return out;
        }
    } catch (const Pole&) {
        out.pole = true;
        return out;
    }
    try {
        GiNaC::exmap functions, symbols;
        for (const auto& [angle, t] : p.t) {
            const numeric one_t2 = 1 + t * t;
            functions[GiNaC::cos(angle)] = (1 - t * t) / one_t2;
            functions[GiNaC::sin(angle)] = 2 * t / one_t2;
        }
        for (const auto& [symbol, value] : p.value) symbols[symbol] = value;
        ex v = e.subs(functions, GiNaC::subs_options::no_pattern).subs(symbols, GiNaC::subs_options::no_pattern);
        if (!GiNaC::is_a<numeric>(v)) v = v.expand();
        if (GiNaC::is_a<numeric>(v) && GiNaC::ex_to<numeric>(v).is_rational()) {
            out.number = GiNaC::ex_to<numeric>(v);
            return out;
        }
        DigitsScope digits(60);
        const ex f = v.evalf();
        if (!GiNaC::is_a<numeric>(f)) throw NotARealValue("not a number");
        out.number = GiNaC::ex_to<numeric>(f);
        out.exact = false;
        if (!out.number.is_real()) throw NotARealValue("not real");
    } catch (const NotARealValue&) {
        throw;
    } catch (const std::exception&) {  // a pole (division by zero) at this point
        out.pole = true;
    }
    return out;
}

bool isZero(const Value& v, const numeric& scale) {
    if (v.exact) return v.number.is_zero();
    const numeric tolerance = GiNaC::ex_to<numeric>(GiNaC::pow(numeric(10), -40)) * (1 + GiNaC::abs(scale));
    return GiNaC::abs(v.number) <= tolerance;
}

int degreeOf(const ex& e) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) return 1;
    if (GiNaC::is_a<numeric>(e)) return 0;
    if (isSin(e) || isCos(e)) return 2;
    if (GiNaC::is_a<GiNaC::power>(e)) {
        const ex n = e.op(1);
        const int base = degreeOf(e.op(0));
        if (GiNaC::is_a<numeric>(n) && GiNaC::ex_to<numeric>(n).is_integer())
            return base * std::min(64, std::abs(GiNaC::ex_to<numeric>(n).to_int()));
        return base * 2;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        int d = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) d += degreeOf(e.op(i));
        return d;
    }
    int d = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) d = std::max(d, degreeOf(e.op(i)));
    return d;
}

}  // namespace

ex expandedTrigonometry(const ex& e) {
    TrigExpander expander;
    return expander(e);
}

int identityDegree(const ex& e) { return degreeOf(e); }

SampledFunction::SampledFunction(const ex& e) : e_(expandedTrigonometry(e)), degree_(degreeOf(e_)) {
    Variables v;
    collect(e_, v);
    symbols_.assign(v.symbols.begin(), v.symbols.end());
    angles_.assign(v.angles.begin(), v.angles.end());
    auto tape = std::make_shared<ModTape>();
    if (tape->add(e_)) tape_ = std::move(tape);
}

namespace {

bool has(const std::vector<ex>& list, const ex& x) {
    return std::any_of(list.begin(), list.end(), [&](const ex& e) { return e.is_equal(x); });
}

// The values of a and b are drawn at the same points: one point over both's variables and
// the symbols the combinations copy from; rationals, or residues modulo the prime.
template <class N, class Draw>
PointOf<N> pointFor(Draw draw, const SampledFunction& a, const SampledFunction* b, const Combination& c1 = {}, const Combination& c2 = {}) {
    PointOf<N> p;
    for (const SampledFunction* f : {&a, b}) {
        if (!f) continue;
        for (const ex& s : f->symbols())
            if (!p.value.count(s)) p.value[s] = draw();
        for (const ex& s : f->angles())
            if (!p.t.count(s)) p.t[s] = draw();
    }
    for (const Combination* c : {&c1, &c2})
        for (const MaskedValue& m : *c)
            for (const auto& [to, from] : m.copies)
                if (!p.value.count(from)) p.value[from] = draw();
    return p;
}
Point pointFor(const SampledFunction& a, const SampledFunction* b, IdentitySampler& sampler, const Combination& c1 = {},
               const Combination& c2 = {}) {
    return pointFor<numeric>([&] { return sampler.rational(); }, a, b, c1, c2);
}

template <class N>
PointOf<N> edited(PointOf<N> p, const MaskedValue& m) {
    for (const auto& [to, from] : m.copies) {
        if (auto it = p.value.find(to); it != p.value.end()) it->second = p.value[from];
        if (auto it = p.t.find(to); it != p.t.end()) it->second = p.t.count(from) ? p.t[from] : p.value[from];
    }
    for (const GiNaC::symbol& s : m.zeros) {
        if (auto it = p.value.find(s); it != p.value.end()) it->second = N(0);
        if (auto it = p.t.find(s); it != p.t.end()) it->second = N(0);
    }
    return p;
}

template <class N>
PointOf<N> masked(const PointOf<N>& p, const std::vector<GiNaC::symbol>& zeros) {
    MaskedValue m;
    m.zeros = zeros;
    return edited(p, m);
}

// Σ c·f|edits modulo the prime; nothing where a value is not rational or is a pole there.
std::optional<Residue> combinedMod(const SampledFunction& f, const ModPoint& p, const Combination& combination) {
    const SampledFunction::ModTape* tape = f.modTape();
    if (!tape) return std::nullopt;
    std::vector<Residue> stack;
    try {
        if (combination.empty()) return tape->value(p, stack);
        Residue sum = 0;
        for (const MaskedValue& m : combination) {
            const auto v = tape->value(edited(p, m), stack);
            if (!v) return std::nullopt;
            const Residue c = m.coefficient >= 0 ? Residue(m.coefficient) : kPrime - Residue(-m.coefficient);
            sum = addMod(sum, mulMod(c, *v));
        }
        return sum;
    } catch (const Pole&) {
        return std::nullopt;
    }
}

// a's and b's combinations compared at `points` residue points: Different proves they are
// different functions; Same is "the same modulo the prime at every point"; Unknown: a value
// was not rational or a pole there.
enum class ModVerdict { Different, Same, Unknown };
ModVerdict compareModPrime(const SampledFunction& a, const Combination& ofA, const SampledFunction& b, const Combination& ofB,
                           IdentitySampler& sampler, int points) {
    for (int k = 0; k < points; ++k) {
        const ModPoint p = pointFor<Residue>([&] { return sampler.residue(); }, a, &b, ofA, ofB);
        const auto va = combinedMod(a, p, ofA), vb = combinedMod(b, p, ofB);
        if (!va || !vb) return ModVerdict::Unknown;
        if (*va != *vb) return ModVerdict::Different;
    }
    return ModVerdict::Same;
}

// Σ c·f|edits at p (f itself when the combination is empty).
Value combined(const SampledFunction& f, const Point& p, const Combination& combination) {
    if (combination.empty()) return evaluate(f.expression(), p);
    Value sum;
    sum.number = 0;
    for (const MaskedValue& m : combination) {
        const Value v = evaluate(f.expression(), edited(p, m));
        if (v.pole) return v;
        sum.number += m.coefficient * v.number;
        sum.exact = sum.exact && v.exact;
    }
    return sum;
}

}  // namespace

IdentityResult sameFunction(const SampledFunction& a, const Combination& ofA, const SampledFunction& b, const Combination& ofB,
                            IdentitySampler& sampler, bool rationals) {
    IdentityResult result;
    if (ofA.empty() && ofB.empty() && a.expression().is_equal(b.expression())) {
        result.same = true;
        return result;
    }
    const int points = 6 + std::max(0, std::max(a.degree(), b.degree()) - 20) / 10;
    const ModVerdict modular = compareModPrime(a, ofA, b, ofB, sampler, rationals ? 2 : points);
    if (modular == ModVerdict::Different) {
        result.points = 1;
        return result;
    }
    if (!rationals && modular == ModVerdict::Same) {
        result.same = true;
        result.points = points;
        return result;
    }
    for (int k = 0; k < points; ++k) {
        Value va, vb;
        for (int attempt = 0;; ++attempt) {
            if (attempt == 20) throw NotARealValue("a pole at every point tried");
            const Point p = pointFor(a, &b, sampler, ofA, ofB);
            va = combined(a, p, ofA);
            vb = combined(b, p, ofB);
            if (!va.pole && !vb.pole) break;
        }
        ++result.points;
        const Value d{va.number - vb.number, va.exact && vb.exact, false};
        if (!d.exact) result.exactness = Exactness::SixtyDigits;
        if (!isZero(d, va.number)) return result;
    }
    result.same = true;
    return result;
}

IdentityResult sameFunction(const SampledFunction& a, const SampledFunction& b, IdentitySampler& sampler, const Combination& combination,
                            bool rationals) {
    return sameFunction(a, combination, b, combination, sampler, rationals);
}

IdentityResult sameFunction(const ex& a, const ex& b, IdentitySampler& sampler) {
    if ((a - b).is_zero()) return {true, Exactness::Exact, 0};
    return sameFunction(SampledFunction(a), SampledFunction(b), sampler);
}

std::optional<numeric> constantRatio(const SampledFunction& a, const SampledFunction& b, IdentitySampler& sampler) {
    for (int attempt = 0; attempt < 4; ++attempt) {
        const Point p = pointFor(a, &b, sampler);
        const Value va = evaluate(a.expression(), p), vb = evaluate(b.expression(), p);
        if (va.pole || vb.pole || !va.exact || !vb.exact) continue;
        if (vb.number.is_zero()) continue;
        const numeric k = va.number / vb.number;
        if (sameFunction(a, SampledFunction(k * b.expression()), sampler).same) return k;
        return std::nullopt;
    }
    return std::nullopt;
}

std::optional<numeric> constantRatio(const ex& a, const ex& b, IdentitySampler& sampler) {
    return constantRatio(SampledFunction(a), SampledFunction(b), sampler);
}

bool dependsOn(const SampledFunction& e, const GiNaC::symbol& x, IdentitySampler& sampler, const Combination& combination) {
    if (!has(e.symbols(), x) && !has(e.angles(), x)) return false;
    for (int attempt = 0; attempt < 3; ++attempt) {  // modulo the prime: a change there is a change
        const ModPoint p = pointFor<Residue>([&] { return sampler.residue(); }, e, nullptr, combination);
        ModPoint moved = p;
        if (moved.value.count(x)) moved.value[x] = sampler.residue();
        if (moved.t.count(x)) moved.t[x] = sampler.residue();
        const auto a = combinedMod(e, p, combination), b = combinedMod(e, moved, combination);
        if (!a || !b) break;
        if (*a != *b) return true;
        if (attempt == 2) return false;
    }
    for (int attempt = 0; attempt < 3; ++attempt) {
        const Point p = pointFor(e, nullptr, sampler, combination);
        Point moved = p;
        if (moved.value.count(x)) moved.value[x] = sampler.rational();
        if (moved.t.count(x)) moved.t[x] = sampler.rational();
        const Value a = combined(e, p, combination), b = combined(e, moved, combination);
        if (a.pole || b.pole) continue;
        if (a.exact && b.exact) {
            if (a.number != b.number) return true;
        } else if (!isZero(Value{a.number - b.number, false, false}, a.number)) {
            return true;
        }
    }
    return false;
}

bool dependsOn(const ex& e, const GiNaC::symbol& x, IdentitySampler& sampler) { return dependsOn(SampledFunction(e), x, sampler); }

bool sameWhere(const SampledFunction& a, const SampledFunction& b, const std::vector<GiNaC::symbol>& atZero, IdentitySampler& sampler) {
    for (int k = 0; k < 6; ++k) {
        Value va, vb;
        for (int attempt = 0;; ++attempt) {
            if (attempt == 20) return false;
            const Point p = masked(pointFor(a, &b, sampler), atZero);
            va = evaluate(a.expression(), p);
            vb = evaluate(b.expression(), p);
            if (!va.pole && !vb.pole) break;
        }
        if (!isZero(Value{va.number - vb.number, va.exact && vb.exact, false}, va.number)) return false;
    }
    return true;
}

}  // namespace ll::symbolic
