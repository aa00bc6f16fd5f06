#include "core/symbolic/readable_numbers.hpp"

namespace ll::symbolic {

bool isDecimalFraction(const GiNaC::numeric& v) {
    if (!v.is_rational() || v.is_integer()) return false;
    GiNaC::numeric d = v.denom();
    for (int p : {2, 5})
        while (GiNaC::irem(d, p).is_zero()) d = d / p;
    return d.is_equal(1) && v.denom() > 8;
}

GiNaC::ex readableNumbers(const GiNaC::ex& e) {
    struct : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            if (GiNaC::is_a<GiNaC::numeric>(x))
                return isDecimalFraction(GiNaC::ex_to<GiNaC::numeric>(x)) ? GiNaC::ex(GiNaC::ex_to<GiNaC::numeric>(x).evalf()) : x;
            return x.map(*this);
        }
    } map;
    return map(e);
}

}  // namespace ll::symbolic
