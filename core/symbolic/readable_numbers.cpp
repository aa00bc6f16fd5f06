#include "core/symbolic/readable_numbers.hpp"

namespace ll::symbolic {

bool isDecimalFraction(const GiNaC::numeric& v) {
    if (!v.is_rational() || v.is_integer()) return false;
    GiNaC::numeric d = v.denom();
    for (int p : {2, 5})
        while (GiNaC::irem(d, p).is_zero()) d = d / p;
    return d.is_equal(1) && v.denom() > 8;
}

namespace {

// A fraction whose decimal expansion ends (denominator 2^a 5^b): 1/5 = 0.2, 3/8 = 0.375.
bool terminates(const GiNaC::numeric& v) {
    if (!v.is_rational() || v.is_integer()) return false;
    GiNaC::numeric d = v.denom();
    for (int p : {2, 5})
        while (GiNaC::irem(d, p).is_zero()) d = d / p;
    return d.is_equal(1);
}

bool hasDecimal(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return isDecimalFraction(GiNaC::ex_to<GiNaC::numeric>(e));
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (hasDecimal(e.op(i))) return true;
    return false;
}

}  // namespace

GiNaC::ex readableNumbers(const GiNaC::ex& e) {
    // One number style per expression: once a scene decimal shows (0.1), every fraction
    // that has a finite decimal form shows as one too (0.2, not 1/5 beside 0.1).
    struct Map : GiNaC::map_function {
        bool decimals = false;
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            if (GiNaC::is_a<GiNaC::numeric>(x)) {
                const GiNaC::numeric& v = GiNaC::ex_to<GiNaC::numeric>(x);
                return (decimals ? terminates(v) : isDecimalFraction(v)) ? GiNaC::ex(v.evalf()) : x;
            }
            return x.map(*this);
        }
    } map;
    // Without a scene decimal nothing changes (only decimal fractions would): GiNaC's map
    // rebuilds every sum and product it walks, so not walking is most of the saving.
    if (!hasDecimal(e)) return e;
    map.decimals = true;
    return map(e);
}

}  // namespace ll::symbolic
