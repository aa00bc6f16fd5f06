#include "core/symbolic/expression_printer.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "core/symbolic/display_builder.hpp"

namespace ll::symbolic {
namespace {

using GiNaC::ex, GiNaC::ex_to, GiNaC::is_a, GiNaC::numeric;

// m, m1, m_cart: a mass, by the naming rules of derivation.hpp.
bool isMassName(const std::string& name, std::string& digits) {
    digits = name.substr(std::min<std::size_t>(1, name.size()));
    const bool numbered = !digits.empty() && digits.size() < 9 &&
                          std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!numbered) digits.clear();
    return name == "m" || (name[0] == 'm' && (name[1] == '_' || numbered));
}

}  // namespace

DisplayStyle displayStyle(Style s) {
    return s == Style::Plain ? DisplayStyle::Plain : s == Style::Latex ? DisplayStyle::Latex : DisplayStyle::Text;
}

DisplayOptions displayOptions(const PrintOptions& options) {
    DisplayOptions out;
    out.coordinateNames = options.coordinateNames;
    out.trigSymbols = options.trigSymbols;
    return out;
}

std::string textCoordinateName(const std::string& name, int dots) {
    return renderDisplay(*displaySymbolName(name, dots), DisplayStyle::Text);
}

PrintOptions printOptionsFor(const Derivation& derivation, Style style) {
    PrintOptions o;
    o.style = style;
    o.coordinateNames = derivation.coordinateNames;
    if (o.coordinateNames.empty())
        for (const GiNaC::symbol& q : derivation.q) o.coordinateNames.push_back(q.get_name());
    o.trigSymbols = derivation.trigToFunctions.nops() > 0;
    return o;
}

std::string print(const ex& e, const PrintOptions& options) {
    return renderDisplay(*buildDisplay(e, displayOptions(options)), displayStyle(options.style));
}

std::string printMatrix(const GiNaC::matrix& m, const PrintOptions& options) { return print(m, options); }

std::string printEquation(const std::string& lhs, const ex& rhs, const PrintOptions& options) {
    const DisplayPtr left = displayRaw(lhs, lhs, lhs);
    return renderDisplay(*displayEquation(left, buildDisplay(rhs, displayOptions(options))), displayStyle(options.style));
}

std::string printEquation(const ex& lhs, const ex& rhs, const PrintOptions& options) {
    return printEquation(print(lhs, options), rhs, options);
}

GiNaC::ex collectForDisplay(const ex& e, const std::vector<GiNaC::symbol>& groupBy) {
    if (is_a<GiNaC::matrix>(e)) {
        GiNaC::matrix m = ex_to<GiNaC::matrix>(e);
        for (unsigned i = 0; i < m.rows(); ++i)
            for (unsigned j = 0; j < m.cols(); ++j) m(i, j) = collectForDisplay(m(i, j), groupBy);
        return m;
    }
    const ex x = e.expand();
    if (groupBy.empty()) return x;
    // Exponents of the groupBy symbols → cofactors. A std::map of exponent vectors
    // makes the grouping independent of GiNaC's term order.
    std::map<std::vector<int>, std::vector<ex>> groups;
    ex single = 0;
    auto addTerm = [&](const ex& term) {
        std::vector<int> key(groupBy.size(), 0);
        ex cofactor = term;
        for (std::size_t g = 0; g < groupBy.size(); ++g) {
            const ex& s = groupBy[g];
            for (const ex& f : is_a<GiNaC::mul>(term) ? term : GiNaC::lst{term}) {
                if (f.is_equal(s)) key[g] = 1;
                else if (is_a<GiNaC::power>(f) && f.op(0).is_equal(s) && f.op(1).info(GiNaC::info_flags::posint))
                    key[g] = ex_to<numeric>(f.op(1)).to_int();
            }
            if (key[g]) cofactor = cofactor * GiNaC::pow(s, -key[g]);
        }
        if (std::all_of(key.begin(), key.end(), [](int k) { return k == 0; }))
            single += term;
        else
            groups[key].push_back(cofactor);
    };
    if (is_a<GiNaC::add>(x))
        for (const ex& t : x) addTerm(t);
    else
        addTerm(x);
    ex result = single;
    for (const auto& [key, cofactors] : groups) {
        ex monomial = 1;
        for (std::size_t g = 0; g < groupBy.size(); ++g) monomial *= GiNaC::pow(groupBy[g], key[g]);
        if (cofactors.size() == 1) {
            result += monomial * cofactors[0];
            continue;
        }
        // The common rational factor of the cofactors goes in front: 1/2*m1*(…).
        numeric gcdNum = 0, lcmDen = 1;
        bool rational = true, allNegative = true;
        for (const ex& c : cofactors) {
            numeric k = 1;
            if (is_a<numeric>(c)) k = ex_to<numeric>(c);
            else if (is_a<GiNaC::mul>(c) && is_a<numeric>(c.op(c.nops() - 1))) k = ex_to<numeric>(c.op(c.nops() - 1));
            if (!k.is_rational()) rational = false;
            if (!rational) break;
            gcdNum = GiNaC::gcd(gcdNum, k.numer());
            lcmDen = GiNaC::lcm(lcmDen, k.denom());
            allNegative = allNegative && k.is_negative();
        }
        numeric content = rational ? gcdNum / lcmDen : numeric(1);
        if (allNegative && rational) content = -content;
        ex sum = 0;
        for (const ex& c : cofactors) sum += c / content;
        result += content * monomial * sum;
    }
    return result;
}

std::vector<GiNaC::symbol> massSymbols(const ex& e) {
    std::map<std::pair<long, std::string>, GiNaC::symbol> found;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!is_a<GiNaC::symbol>(*it)) continue;
        const std::string& name = ex_to<GiNaC::symbol>(*it).get_name();
        std::string digits;
        if (!name.empty() && isMassName(name, digits))
            found.emplace(std::pair{digits.empty() ? -1L : std::stol(digits), name}, ex_to<GiNaC::symbol>(*it));
    }
    std::vector<GiNaC::symbol> out;
    for (auto& [key, s] : found) out.push_back(s);
    return out;
}

}  // namespace ll::symbolic
