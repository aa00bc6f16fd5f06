// libFuzzer: any bytes as an expression of the parameters (the text of a numeric
// field), evaluated as a length (degrees refused) and as an angle, and parsed with
// extra symbols as a Lagrangian's field would be. A value is finite and not subnormal.
#include <cmath>
#include <cstdint>
#include <string>

#include "core/symbolic/expression.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "fuzz_support.hpp"

namespace {

const ll::ParameterTable& table() {
    static const ll::ParameterTable t = [] {
        ll::ParameterTable p;
        p.define("parameters.a1", "a1", 0.4318);
        p.define("parameters.m", "m", 2.0);
        p.define("parameters.tiny", "tiny", 1e-300);
        p.define("parameters.huge", "huge", 1e300);
        p.define("parameters.k", "k", "2*m + a1^2");
        return p;
    }();
    return t;
}

}  // namespace

int ll::fuzz::expression(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto lock = ll::symbolic::lockGinac();
    for (const ll::AngleUnits units : {ll::AngleUnits::Refused, ll::AngleUnits::Allowed}) {
        try {
            const double value = table().evaluate("robot.joints[0].a", text, units);
            ll::fuzz::require(std::isfinite(value) && std::fpclassify(value) != FP_SUBNORMAL, "an unusable value");
        } catch (const ll::InputError& e) {
            ll::fuzz::checkRefusal(e);
        }
    }
    try {
        (void)table().parse("lagrangian.kinetic", text, {GiNaC::symbol("x"), GiNaC::symbol("x_dot")});
    } catch (const ll::InputError& e) {
        ll::fuzz::checkRefusal(e);
    }
    return 0;
}
