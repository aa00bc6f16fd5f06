#include "core/present/number_spelling.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>

namespace ll::present {
namespace {

using GiNaC::numeric;

std::string str(const numeric& n) { return (std::ostringstream() << n).str(); }

// The shortest decimal that reads back as the same double.
std::string shortest(double v) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, r.ptr);
}

// As people read it: the shortest form when it has at most 6 significant digits (a
// scene's 0.15005), else rounded to 6 (%g, which may write 1e-05).
constexpr int shownDigits = 6;
std::string shown(double v) {
    const std::string s = shortest(v);
    int digits = 0;
    bool leading = true;
    for (char c : s) {
        if (c == 'e' || c == 'E') break;
        if (c < '0' || c > '9') continue;
        if (leading && c == '0') continue;
        leading = false;
        ++digits;
    }
    if (digits <= shownDigits) return s;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", shownDigits, v);
    return buffer;
}

// 17 significant digits, always a float literal for GiNaC's parser (2.0, not 2).
std::string seventeen(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    std::string s = buffer;
    if (s.find_first_of(".ni") == std::string::npos) {
        const auto e = s.find('e');
        s.insert(e == std::string::npos ? s.size() : e, ".0");
    }
    return s;
}

// `exact`: the Plain spelling when it is not the 17-digit float (an integer's digits, a
// rational's (num/den)).
DisplayPtr decimalNode(double v, const std::string& exact = {}) {
    const std::string s = shown(v), plain = exact.empty() ? seventeen(v) : exact;
    const auto e = s.find('e');
    if (e == std::string::npos) return displayNumber(s, s, plain);
    const std::string exponent = std::to_string(std::stoi(s.substr(e + 1)));
    const std::string mantissa = s.substr(0, e) == "1" ? "" : s.substr(0, e);  // 10⁻⁵, never 1·10⁻⁵
    return displayNumber(mantissa, mantissa, plain, exponent);
}

}  // namespace

DisplayPtr numberNode(const numeric& n) {
    if (!n.is_real()) {  // not expected in mechanics; GiNaC's form, parenthesised
        std::ostringstream plain, latex;
        plain << n;
        latex << GiNaC::latex << n;
        return displayRaw("(" + plain.str() + ")", "(" + latex.str() + ")", "(" + plain.str() + ")");
    }
    if (n.is_negative()) return displayNegated(numberNode(-n));
    if (n.is_integer()) {
        const std::string s = str(n);
        if (s.size() > 6) return decimalNode(n.to_double(), s);  // 3650000 reads 3.65·10⁶; Plain keeps every digit
        return displayNumber(s, s, s);
    }
    if (n.is_rational()) return displayNode(DisplayKind::Fraction, {numberNode(n.numer()), numberNode(n.denom())});
    return decimalNode(n.to_double());
}

DisplayPtr exponentNode(const numeric& k) {
    const std::string text = str(k);
    return displayNumber(text, text, k.is_rational() ? text : seventeen(k.to_double()));
}

bool formulaFactor(const numeric& c) {
    if (!c.is_rational()) return false;
    const numeric n = GiNaC::abs(c.numer()), d = c.denom();
    return n <= 12 && d <= 12 && !GiNaC::irem(d, 10).is_zero();
}

bool formulaMade(const numeric& v) {
    if (!v.is_rational()) return false;
    if (GiNaC::abs(v.numer()) > 12 || v.denom() > 240) return false;
    numeric d = v.denom();
    int fives = 0;
    for (int p : {2, 3, 5, 7})
        while (GiNaC::irem(d, p).is_zero()) {
            d = d / p;
            fives += p == 5;
        }
    if (!d.is_equal(1) || fives > 1) return false;
    // A 5 in the denominator comes from a sphere's 2/5 times ½s and ⅓s: 1/5, 1/10, 4/5,
    // 2/15; 9/10 and 3/10 are a scene's decimals.
    const numeric n = GiNaC::abs(v.numer());
    return fives == 0 || n == 1 || n == 2 || n == 4 || n == 8;
}

NumberSpelling::NumberSpelling(std::vector<numeric> typed, bool allDigits) : typed_(std::move(typed)), allDigits_(allDigits) {}

namespace {

// Every digit of a positive rational whose denominator has no factor but 2 and 5
// (2159/5000 → 0.4318); empty for any other.
std::string allDigitsOf(const numeric& n) {
    numeric d = n.denom();
    int twos = 0, fives = 0;
    while (GiNaC::irem(d, 2).is_zero()) d = d / 2, ++twos;
    while (GiNaC::irem(d, 5).is_zero()) d = d / 5, ++fives;
    if (d != 1) return "";
    const int places = std::max(twos, fives);
    std::string digits = str(n * numeric(10).power(places));
    if (static_cast<int>(digits.size()) <= places) digits.insert(0, static_cast<std::size_t>(places) + 1 - digits.size(), '0');
    digits.insert(digits.size() - static_cast<std::size_t>(places), ".");
    return digits;
}

}  // namespace

bool NumberSpelling::decimal(const numeric& n, bool standalone) const {
    if (!n.is_rational() || n.is_integer()) return false;
    const numeric a = GiNaC::abs(n);
    if (!formulaMade(a)) return true;
    return std::any_of(typed_.begin(), typed_.end(), [&](const numeric& t) {
        if (!standalone && (t.is_equal(numeric(1, 2)) || t.is_equal(numeric(1, 4)))) return false;
        const numeric k = a / t;
        return k.is_equal(1) || k.is_equal(2) || k.is_equal(numeric(1, 2)) || k.is_equal(4) || k.is_equal(numeric(1, 4));
    });
}

DisplayPtr NumberSpelling::node(const numeric& n, bool standalone) const {
    if (!n.is_real() || !decimal(n, standalone)) return numberNode(n);
    if (n.is_negative()) return displayNegated(node(-n, standalone));
    if (allDigits_) {
        const std::string all = allDigitsOf(n);
        return all.empty() ? numberNode(n) : displayNumber(all, all, "(" + str(n) + ")");
    }
    return decimalNode(n.to_double(), "(" + str(n) + ")");
}

}  // namespace ll::present
