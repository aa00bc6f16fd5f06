#include "core/symbolic/readable_numbers.hpp"

#include "core/symbolic/ginac_kind.hpp"
#include "core/symbolic/ginac_pairs.hpp"

namespace ll::symbolic {

namespace {

// Whether a positive integer has no prime factor but 2 and 5. Denominators are checked
// for every number of every printed expression (thousands of terms in an expanded
// entry), so those that fit a machine word are not divided as bignums.
bool onlyTwosAndFives(const GiNaC::numeric& d) {
    if (d.int_length() < 63) {
        unsigned long long n = static_cast<unsigned long long>(d.to_long());
        while (n % 2 == 0) n /= 2;
        while (n % 5 == 0) n /= 5;
        return n == 1;
    }
    GiNaC::numeric r = d;
    for (int p : {2, 5})
        while (GiNaC::irem(r, p).is_zero()) r = r / p;
    return r.is_equal(1);
}

// A fraction whose decimal expansion ends (denominator 2^a 5^b): 1/5 = 0.2, 3/8 = 0.375.
bool terminates(const GiNaC::numeric& v) {
    return !v.is_integer() && v.is_rational() && onlyTwosAndFives(v.denom());  // integers first: most exponents
}

}  // namespace

bool isDecimalFraction(const GiNaC::numeric& v) { return terminates(v) && v.denom() > 8; }

namespace {

// Whether a number that is(number) occurs anywhere in e (a coefficient, an exponent, a
// number inside a function), read through sums' and products' pairs (ginac_pairs.hpp).
bool anyNumber(const GiNaC::ex& e, bool (*is)(const GiNaC::numeric&)) {
    // Both tests (terminates, isDecimalFraction) are false for integers, so GiNaC's
    // shared 1 (most exponents, many coefficients) is passed by its address.
    auto number = [is](const GiNaC::ex& node, GinacKind kind) {
        return kind == GinacKind::Numeric && !isSharedOne(GiNaC::ex_to<GiNaC::basic>(node)) && is(GiNaC::ex_to<GiNaC::numeric>(node));
    };
    return anyNode(e, number);
}

// A sum whose terms' rests hold no such number (an expanded entry, or a named quantity:
// monomials with integer powers), with only its coefficients and number made decimal:
// the pairs and the constructor GiNaC's map would end with, without making a product
// per term and splitting it again (map's cost on a sum of thousands of terms).
GiNaC::ex withReadableCoefficients(const GiNaC::add& sum) {
    const GiNaC::epvector& pairs = GinacPairs::of(sum);
    GiNaC::epvector shown;
    shown.reserve(pairs.size() + 1);
    for (const GiNaC::expair& p : pairs) shown.emplace_back(p.rest, readableNumber(GiNaC::ex_to<GiNaC::numeric>(p.coeff)));
    return GiNaC::ex(GiNaC::dynallocate<GiNaC::add>(std::move(shown), readableNumber(GiNaC::ex_to<GiNaC::numeric>(GinacPairs::number(sum)))));
}

}  // namespace

GiNaC::numeric readableNumber(const GiNaC::numeric& v) { return terminates(v) ? GiNaC::ex_to<GiNaC::numeric>(v.evalf()) : v; }

ReadableChange readableChange(const GiNaC::ex& e) {
    // Without a scene decimal nothing changes (only decimal fractions would): GiNaC's map
    // rebuilds every sum and product it walks, so not walking is most of the saving.
    // A sum (most expressions printed) is read in one walk: its rests for any finite
    // fraction (when there is none, none is a decimal one either), its numbers apart.
    if (ginacKind(e) == GinacKind::Add) {
        const auto& sum = GiNaC::ex_to<GiNaC::add>(e);
        bool restsTerminate = false;
        for (const GiNaC::expair& p : GinacPairs::of(sum))
            if (anyNumber(p.rest, terminates)) {
                restsTerminate = true;
                break;
            }
        if (!restsTerminate) {
            if (isDecimalFraction(GiNaC::ex_to<GiNaC::numeric>(GinacPairs::number(sum)))) return ReadableChange::Coefficients;
            for (const GiNaC::expair& p : GinacPairs::of(sum))
                if (isDecimalFraction(GiNaC::ex_to<GiNaC::numeric>(p.coeff))) return ReadableChange::Coefficients;
            return ReadableChange::None;
        }
    }
    return anyNumber(e, isDecimalFraction) ? ReadableChange::Everywhere : ReadableChange::None;
}

GiNaC::ex readableNumbers(const GiNaC::ex& e) {
    // One number style per expression: once a scene decimal shows (0.1), every fraction
    // that has a finite decimal form shows as one too (0.2, not 1/5 beside 0.1).
    struct Map : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            if (GiNaC::is_a<GiNaC::numeric>(x)) return readableNumber(GiNaC::ex_to<GiNaC::numeric>(x));
            return x.map(*this);
        }
    } map;
    switch (readableChange(e)) {
        case ReadableChange::None: return e;
        case ReadableChange::Coefficients: return withReadableCoefficients(GiNaC::ex_to<GiNaC::add>(e));
        case ReadableChange::Everywhere: break;
    }
    return map(e);
}

}  // namespace ll::symbolic
