#pragma once
// Whether two expressions are the same function, decided exactly and without relying on a
// simplification that may give up: a probabilistic identity test in exact arithmetic.
//
// Sines and cosines are first written as products of sin x and cos x of single symbols
// (angle sums and integer multiples expanded). Then, at each of several random points,
// every such pair is replaced by the rational parametrisation of the circle,
//   cos x = (1 − t²)/(1 + t²),  sin x = 2t/(1 + t²),  t a random rational,
// every symbol outside a sine or cosine (a length, a mass, a prismatic coordinate, an angle
// standing on its own: x is algebraically independent of cos x and sin x) by a random
// rational, and the two values compared exactly (GiNaC's rationals). Two different
// rational functions of degree d agree at a random point drawn from N values per
// coordinate with probability at most d/N (Schwartz–Zippel); with N about 2·10⁶ and at
// least 6 independent points, more for higher degrees, a wrong "same" is out of reach.
// Where a value is not rational (√ of a symbol, exp), the values are compared to 60 digits
// instead, which the result says. Before that, two points in the integers modulo the prime
// 2⁶¹ − 1: values that differ there differ as rationals, so "different" is usually known
// at once; "the same" is only ever concluded in the rationals.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <ginac/ginac.h>

namespace ll::symbolic {

// The random points: each call draws new values for every symbol and angle it meets.
class IdentitySampler {
public:
    explicit IdentitySampler(std::uint64_t seed = 0x5eedULL) : state_(seed ? seed : 1) {}
    GiNaC::numeric rational();  // numerator and denominator up to about 10⁶, never 0
    std::uint64_t residue();    // modulo 2⁶¹ − 1 (the fast pre-check of sameFunction)

private:
    std::uint64_t next();
    std::uint64_t state_;
};

enum class Exactness { Exact, SixtyDigits };

struct IdentityResult {
    bool same = false;
    Exactness exactness = Exactness::Exact;
    int points = 0;  // how many points were compared
};

// sin and cos of sums and integer multiples written out (cos(q1 + q2) → c1 c2 − s1 s2
// as functions of q1, q2), tan as sin/cos. Keeps everything else.
GiNaC::ex expandedTrigonometry(const GiNaC::ex& e);

// A degree that bounds the answer's as a rational function of the random values (each
// sin or cos counts 2): what decides how many points are compared.
int identityDegree(const GiNaC::ex& e);

// An expression made ready to be sampled: its trigonometry expanded once, its symbols and
// angles listed. Comparisons of one big expression against many (the feedback's) prepare it
// once.
class SampledFunction {
public:
    explicit SampledFunction(const GiNaC::ex& e);
    const GiNaC::ex& expression() const { return e_; }
    int degree() const { return degree_; }
    const std::vector<GiNaC::ex>& symbols() const { return symbols_; }  // standing alone
    const std::vector<GiNaC::ex>& angles() const { return angles_; }    // inside a sin or cos

    struct ModTape;  // the expression as a list of operations modulo the prime (function_identity.cpp)
    const ModTape* modTape() const { return tape_.get(); }  // null: not every value is rational there

private:
    GiNaC::ex e_;
    int degree_ = 0;
    std::vector<GiNaC::ex> symbols_, angles_;
    std::shared_ptr<const ModTape> tape_;
};

// A linear combination of one function's values with some symbols set to zero: a link's
// part of a sum over links is {+1, the other links' masses and inertias}, {−1, every link's}.
struct MaskedValue {
    int coefficient = 1;
    std::vector<GiNaC::symbol> zeros;
    // each first symbol takes the second's value: f with a1 written where ℓc1 belongs is f at
    // a point where ℓc1 has a1's value
    std::vector<std::pair<GiNaC::symbol, GiNaC::symbol>> copies;
};
using Combination = std::vector<MaskedValue>;

// a ≡ b as functions of every symbol in them. The caller holds the GiNaC lock. Throws
// std::domain_error when the values are not real numbers (√ of a negative value) at every
// point tried.
IdentityResult sameFunction(const GiNaC::ex& a, const GiNaC::ex& b, IdentitySampler& sampler);
// The same of Σ c·a|zeros ≡ Σ c·b|zeros over `combination` (empty: a ≡ b).
IdentityResult sameFunction(const SampledFunction& a, const SampledFunction& b, IdentitySampler& sampler,
                            const Combination& combination = {}, bool rationals = true);
// Σ a's combination ≡ Σ b's combination. With `rationals` false, "the same" may also be
// concluded modulo the prime (as many points, the same bound: a degree over 2⁶¹ per
// point): what the feedback's many comparisons use; a verdict is always decided in the rationals.
IdentityResult sameFunction(const SampledFunction& a, const Combination& ofA, const SampledFunction& b, const Combination& ofB,
                            IdentitySampler& sampler, bool rationals = true);

// a ≡ k·b for one constant k (nullopt: none; b ≡ 0 gives none). Sign and factor slips.
std::optional<GiNaC::numeric> constantRatio(const GiNaC::ex& a, const GiNaC::ex& b, IdentitySampler& sampler);
std::optional<GiNaC::numeric> constantRatio(const SampledFunction& a, const SampledFunction& b, IdentitySampler& sampler);

// Whether e changes when only `x` changes (the other symbols kept at random values); with
// `combination`, whether that combination of e's values does.
bool dependsOn(const GiNaC::ex& e, const GiNaC::symbol& x, IdentitySampler& sampler);
bool dependsOn(const SampledFunction& e, const GiNaC::symbol& x, IdentitySampler& sampler, const Combination& combination = {});

// Whether a ≡ b on the set where the `atZero` symbols are 0 (for an angle: cos = 1,
// sin = 0), the other symbols random: "right at the home pose q = 0".
bool sameWhere(const SampledFunction& a, const SampledFunction& b, const std::vector<GiNaC::symbol>& atZero, IdentitySampler& sampler);

}  // namespace ll::symbolic
