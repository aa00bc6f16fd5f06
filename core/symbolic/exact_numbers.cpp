#include "core/symbolic/exact_numbers.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace ll::symbolic {

GiNaC::ex exactNumber(double value) {
    if (value == 0.0) return 0;
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
    const std::string text(buffer, result.ptr);  // e.g. "-4.318e-01", shortest round trip
    const size_t e = text.find('e');
    std::string mantissa = text.substr(0, e);
    int exponent = std::stoi(text.substr(e + 1));
    const size_t dot = mantissa.find('.');
    if (dot != std::string::npos) {
        exponent -= static_cast<int>(mantissa.size() - dot - 1);
        mantissa.erase(dot, 1);
    }
    const GiNaC::numeric digits(mantissa.c_str());
    return exponent >= 0 ? digits * GiNaC::pow(GiNaC::numeric(10), exponent) : digits / GiNaC::pow(GiNaC::numeric(10), -exponent);
}

GiNaC::ex exactAngle(double value) {
    const double twelfths = value / (std::numbers::pi / 12);
    const double k = std::round(twelfths);
    if (std::abs(k) < 1e15 && std::abs(twelfths - k) < 1e-12 * std::max(1.0, std::abs(k)))  // k fits a long
        return GiNaC::numeric(static_cast<long>(k), 12) * GiNaC::Pi;
    return exactNumber(value);
}

GiNaC::ex exactFloats(const GiNaC::ex& e) {
    struct Exact : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            if (!GiNaC::is_a<GiNaC::numeric>(x)) return x.map(*this);
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(x);
            return n.is_real() && !n.is_rational() ? exactNumber(n.to_double()) : x;
        }
    } exact;
    return exact(e);
}

}  // namespace ll::symbolic
