#include "core/present/number_style.hpp"

#include <algorithm>
#include <string>

namespace ll::present {
namespace {

constexpr int kMostPlaces = 8;  // after the point, in a plain decimal (0.0110055, 0.00841985; not 0.000138535)

// A Number node's decimal: its mantissa's digits and the power of ten it stands at.
struct Decimal {
    std::string digits;  // significant digits, no point, no leading zeros ("500861"); "1" for an empty mantissa
    int exponent = 0;    // the value is 0.d1d2d3… · 10^(exponent + 1), i.e. d1 stands at 10^exponent
};

bool isDecimal(const DisplayNode& n) {
    return n.kind == DisplayKind::Number && (!n.exponent.empty() || n.text.find('.') != std::string::npos);
}

Decimal decimalOf(const DisplayNode& n) {
    const std::string mantissa = n.text.empty() ? "1" : n.text;
    const int power = n.exponent.empty() ? 0 : std::stoi(n.exponent);
    const auto point = mantissa.find('.');
    const std::string whole = mantissa.substr(0, point), fraction = point == std::string::npos ? "" : mantissa.substr(point + 1);
    std::string digits = whole + fraction;
    int first = int(whole.size()) - 1;  // the power of ten of digits[0], before the exponent
    std::size_t lead = 0;
    while (lead + 1 < digits.size() && digits[lead] == '0') ++lead;
    first -= int(lead);
    digits = digits.substr(lead);
    while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
    return {digits, first + power};
}

// Places after the point the plain decimal needs.
int placesOf(const Decimal& d) { return std::max(0, int(d.digits.size()) - 1 - d.exponent); }

std::string plainText(const Decimal& d) {  // for exponent < 0: 0.000…digits
    return "0." + std::string(std::size_t(-d.exponent - 1), '0') + d.digits;
}

DisplayPtr restyled(const DisplayNode& n, NumberStyle style) {
    const Decimal d = decimalOf(n);
    if (d.exponent >= 0 || d.digits == "0") return nullptr;  // 1 or more: as it is
    auto out = std::make_shared<DisplayNode>(n);
    if (style == NumberStyle::Plain) {
        if (n.exponent.empty()) return nullptr;
        out->text = out->latex = plainText(d);
        out->exponent.clear();
    } else {
        if (!n.exponent.empty()) return nullptr;
        const std::string mantissa = d.digits.size() == 1 ? d.digits : d.digits.substr(0, 1) + "." + d.digits.substr(1);
        out->text = out->latex = mantissa == "1" ? "" : mantissa;
        out->exponent = std::to_string(d.exponent);
    }
    return out;
}

void scan(const DisplayNode& n, bool& scientific) {
    if (isDecimal(n) && placesOf(decimalOf(n)) > kMostPlaces) scientific = true;
    for (const DisplayPtr& c : n.children)
        if (c) scan(*c, scientific);
    for (const auto& row : n.rows)
        for (const DisplayPtr& c : row)
            if (c) scan(*c, scientific);
}

}  // namespace

NumberStyle numberStyleOf(const DisplayNode& node) {
    bool scientific = false;
    scan(node, scientific);
    return scientific ? NumberStyle::Scientific : NumberStyle::Plain;
}

DisplayPtr withNumberStyle(const DisplayPtr& node, NumberStyle style) {
    if (!node) return node;
    if (isDecimal(*node)) {
        DisplayPtr changed = restyled(*node, style);
        return changed ? changed : node;
    }
    std::shared_ptr<DisplayNode> copy;  // made at the first child that changes
    for (std::size_t i = 0; i < node->children.size(); ++i) {
        const DisplayPtr now = withNumberStyle(node->children[i], style);
        if (now != node->children[i]) {
            if (!copy) copy = std::make_shared<DisplayNode>(*node);
            copy->children[i] = now;
        }
    }
    for (std::size_t r = 0; r < node->rows.size(); ++r)
        for (std::size_t c = 0; c < node->rows[r].size(); ++c) {
            const DisplayPtr now = withNumberStyle(node->rows[r][c], style);
            if (now != node->rows[r][c]) {
                if (!copy) copy = std::make_shared<DisplayNode>(*node);
                copy->rows[r][c] = now;
            }
        }
    return copy ? DisplayPtr(copy) : node;
}

void useOneNumberStyle(DisplayItem& item) {
    if (item.value && item.value->kind == DisplayKind::Matrix) {  // each entry its own style
        auto matrix = std::make_shared<DisplayNode>(*item.value);
        for (auto& row : matrix->rows)
            for (DisplayPtr& cell : row)
                if (cell) cell = withNumberStyle(cell, numberStyleOf(*cell));
        if (item.equation) {  // label = the matrix: the same matrix in it
            auto equation = std::make_shared<DisplayNode>(*item.equation);
            for (DisplayPtr& child : equation->children)
                if (child == item.value) child = matrix;
            item.equation = equation;
        }
        item.value = matrix;
        return;
    }
    const DisplayPtr& whole = item.equation ? item.equation : item.value;  // an equation of motion: both sides
    if (!whole) return;
    const NumberStyle style = numberStyleOf(*whole);
    item.equation = withNumberStyle(item.equation, style);
    item.value = withNumberStyle(item.value, style);
}

}  // namespace ll::present
