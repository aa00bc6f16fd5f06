#include "core/present/expression_printer.hpp"

#include "core/present/symbol_names.hpp"

namespace ll::present {

DisplayStyle displayStyle(Style s) {
    return s == Style::Plain ? DisplayStyle::Plain : s == Style::Latex ? DisplayStyle::Latex : DisplayStyle::Text;
}

DisplayOptions displayOptions(const PrintOptions& options) {
    DisplayOptions out;
    out.names.coordinateNames = options.coordinateNames;
    out.names.trigSymbols = options.trigSymbols;
    return out;
}

std::string textCoordinateName(const std::string& name, int dots) {
    return renderDisplay(*displaySymbolName(name, dots), DisplayStyle::Text);
}

PrintOptions printOptionsFor(const symbolic::Derivation& derivation, Style style) {
    PrintOptions o;
    o.style = style;
    o.coordinateNames = derivation.coordinateNames;
    if (o.coordinateNames.empty())
        for (const GiNaC::symbol& q : derivation.q) o.coordinateNames.push_back(q.get_name());
    o.trigSymbols = derivation.system == symbolic::SystemKind::Robot;
    return o;
}

std::string print(const GiNaC::ex& e, const PrintOptions& options) {
    return renderDisplay(*buildDisplay(e, displayOptions(options)), displayStyle(options.style));
}

std::string printEquation(const std::string& lhs, const GiNaC::ex& rhs, const PrintOptions& options) {
    const DisplayPtr left = displayRaw(lhs, lhs, lhs);
    return renderDisplay(*displayEquation(left, buildDisplay(rhs, displayOptions(options))), displayStyle(options.style));
}

std::string printEquation(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const PrintOptions& options) {
    return printEquation(print(lhs, options), rhs, options);
}

}  // namespace ll::present
