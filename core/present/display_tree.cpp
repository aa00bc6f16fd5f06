#include "core/present/display_tree.hpp"

#include <algorithm>
#include <sstream>
#include <string_view>

namespace ll::present {
namespace {

// Digits (and a minus) as Unicode superscripts, added to out.
void appendSuperscript(std::string_view digits, std::string& out) {
    static constexpr std::string_view sup[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    for (char c : digits) {
        if (c == '-') out += "⁻";
        else if (c >= '0' && c <= '9') out += sup[c - '0'];
        else out += c;
    }
}

std::string superscript(const std::string& digits) {
    std::string out;
    appendSuperscript(digits, out);
    return out;
}

bool allDigits(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A combining mark after the first code point, added to out: q̇, θ̈, ĝ.
void appendWithDots(std::string_view text, int dots, std::string& out, bool hat = false) {
    if (dots == 0 && !hat) {
        out += text;
        return;
    }
    std::size_t first = 1;
    while (first < text.size() && (static_cast<unsigned char>(text[first]) & 0xC0) == 0x80) ++first;
    first = std::min(first, text.size());
    out += text.substr(0, first);
    if (hat) out += "\u0302";
    if (dots) out += dots == 1 ? "\u0307" : "\u0308";
    out += text.substr(first);
}

// Code points on screen: combining marks (U+0300–U+036F) take no column.
std::size_t columns(const std::string& s) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char b = static_cast<unsigned char>(s[i]);
        const std::size_t len = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;
        if (!(len == 2 && (b == 0xCC || (b == 0xCD && static_cast<unsigned char>(s[i + 1]) < 0xB0)))) ++n;
        i += len;
    }
    return n;
}

std::vector<std::string> lines(const std::string& s) {
    std::vector<std::string> out;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    if (out.empty()) out.emplace_back();
    return out;
}

std::string rtrim(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

bool isIntegerExponent(const DisplayNode& x) { return x.kind == DisplayKind::Number && allDigits(x.text); }

// LaTeX wants \, beside upright words and function names.
bool isWord(const DisplayNode& n) {
    if (n.kind == DisplayKind::Symbol) return n.upright;
    if (n.kind == DisplayKind::Function) return true;
    if (n.kind == DisplayKind::Power) return n.children[0]->kind == DisplayKind::Function;
    return false;
}

class Renderer {
public:
    Renderer(DisplayStyle style, bool keyNames) : style_(style), key_(keyNames) {}

    std::string operator()(const DisplayNode& n) const {
        switch (n.kind) {
            case DisplayKind::Symbol:
            case DisplayKind::Number:
            case DisplayKind::Sum:
            case DisplayKind::Product:
            case DisplayKind::Power:
            case DisplayKind::Fence: {
                std::string s;
                append(n, s);
                return s;
            }
            case DisplayKind::Fraction: return fraction(n);
            case DisplayKind::Root: {
                const std::string c = (*this)(*n.children[0]);
                if (style_ == DisplayStyle::Latex) return "\\sqrt{" + c + "}";
                if (style_ == DisplayStyle::Plain) return "sqrt(" + c + ")";
                return "√" + (displayPrecedence(*n.children[0]) < 3 ? "(" + c + ")" : c);
            }
            case DisplayKind::Function: return function(n, "");
            case DisplayKind::Matrix: return matrix(n);
            case DisplayKind::Equation: return equation(n);
            case DisplayKind::List: {
                std::string items;
                for (const DisplayPtr& c : n.children) items += (items.empty() ? "" : (plain() ? "," : ", ")) + (*this)(*c);
                return style_ == DisplayStyle::Latex ? "\\left\\{" + items + "\\right\\}" : "{" + items + "}";
            }
            case DisplayKind::Raw: return style_ == DisplayStyle::Latex ? n.latex : plain() ? n.plain : n.text;
        }
        return {};
    }

    // n's rendering added to out. Sums and products, the bulk of an expanded entry, go
    // into one buffer: returning a string per node copied each term's text once per level.
    void append(const DisplayNode& n, std::string& out) const {
        switch (n.kind) {
            case DisplayKind::Symbol: return symbol(n, out);
            case DisplayKind::Number: return number(n, out);
            case DisplayKind::Sum: return sum(n, out);
            case DisplayKind::Product: return product(n, out);
            case DisplayKind::Power: return power(n, out);
            case DisplayKind::Fence:
                out += style_ == DisplayStyle::Latex ? "\\left(" : "(";
                append(*n.children[0], out);
                out += style_ == DisplayStyle::Latex ? "\\right)" : ")";
                return;
            default: out += (*this)(n);
        }
    }

private:
    DisplayStyle style_;
    bool key_;

    bool plain() const { return style_ == DisplayStyle::Plain; }

    void symbol(const DisplayNode& n, std::string& out) const {
        if (plain()) {
            out += key_ ? n.name : n.plain;
        } else if (style_ == DisplayStyle::Text) {
            appendWithDots(n.text, n.dots, out, n.hat);
            if (!n.subText.empty()) out += n.subText;
            if (!n.supText.empty()) out += n.supText;
        } else {
            if (n.hat) out += "\\hat{";
            if (n.dots) out += n.dots == 1 ? "\\dot{" : "\\ddot{";
            out += n.latex;
            if (n.dots) out += '}';
            if (n.hat) out += '}';
            if (!n.subLatex.empty()) {
                out += "_{";
                out += n.subLatex;
                out += '}';
            }
            if (!n.supLatex.empty()) {
                out += "^{";
                out += n.supLatex;
                out += '}';
            }
        }
    }

    void number(const DisplayNode& n, std::string& out) const {
        if (plain()) {
            out += n.plain;
        } else if (n.exponent.empty()) {
            out += style_ == DisplayStyle::Latex ? n.latex : n.text;
        } else if (style_ == DisplayStyle::Latex) {
            out += (n.latex.empty() ? "" : n.latex + " \\cdot ") + "10^{" + n.exponent + "}";  // an empty mantissa: 1, left out
        } else {
            out += (n.text.empty() ? "" : n.text + "·") + "10" + superscript(n.exponent);
        }
    }

    void sum(const DisplayNode& n, std::string& out) const {
        const std::string_view minus = style_ == DisplayStyle::Text ? "−" : "-";
        for (std::size_t i = 0; i < n.children.size(); ++i) {
            const bool neg = n.negative[i];
            if (i == 0) {
                if (neg) out += minus;
            } else if (plain()) {
                out += neg ? '-' : '+';
            } else if (neg) {
                out += ' ';
                out += minus;
                out += ' ';
            } else {
                out += " + ";
            }
            append(*n.children[i], out);
        }
    }

    // * in Plain; a space (· before a digit) in Text; in LaTeX a space, \, beside
    // functions and words, \cdot before a digit. The separator for a factor that does
    // not start with a digit goes in before it; when the factor turns out to start with
    // one (seldom: numbers come first), it is replaced. (Inserting it after every factor
    // moved each factor's text.)
    void product(const DisplayNode& n, std::string& out) const {
        for (std::size_t i = 0; i < n.children.size(); ++i) {
            if (i == 0) {
                append(*n.children[i], out);
                continue;
            }
            std::string_view separator;
            if (plain()) separator = "*";
            else if (style_ == DisplayStyle::Text) separator = " ";
            else separator = isWord(*n.children[i]) || isWord(*n.children[i - 1]) ? "\\, " : " ";
            const std::size_t at = out.size();
            out += separator;
            const std::size_t first = out.size();
            append(*n.children[i], out);
            const bool digit = out.size() > first && out[first] >= '0' && out[first] <= '9';
            if (digit && !plain()) out.replace(at, separator.size(), style_ == DisplayStyle::Text ? "·" : " \\cdot ");
        }
    }

    std::string fraction(const DisplayNode& n) const {
        const DisplayNode &num = *n.children[0], &den = *n.children[1];
        if (style_ == DisplayStyle::Latex) {
            // A lone sum needs no parentheses inside \frac.
            auto side = [&](const DisplayNode& x) { return x.kind == DisplayKind::Fence ? (*this)(*x.children[0]) : (*this)(x); };
            return "\\frac{" + side(num) + "}{" + side(den) + "}";
        }
        const std::string bottom = (*this)(den);
        return (*this)(num) + "/" + (displayPrecedence(den) >= 2 ? bottom : "(" + bottom + ")");
    }

    // A power added to out (c2², q̇1², x^(1/2)): the most frequent node after symbols.
    void power(const DisplayNode& n, std::string& out) const {
        const DisplayNode &base = *n.children[0], &x = *n.children[1];
        const bool integer = isIntegerExponent(x);
        if (!plain() && integer && base.kind == DisplayKind::Function) {
            out += function(base, style_ == DisplayStyle::Text ? superscript(x.text) : "^{" + x.text + "}");
            return;
        }
        if (style_ == DisplayStyle::Latex) {
            const bool braced = base.kind == DisplayKind::Fence;
            if (braced) out += '{';
            append(base, out);
            if (braced) out += '}';
            out += "^{";
            append(x, out);
            out += '}';
            return;
        }
        append(base, out);
        if (x.kind == DisplayKind::Number) {
            if (!integer) {
                out += "^(";
                out += x.plain;
                out += ')';
            } else if (plain()) {
                out += '^';
                out += x.text;
            } else {
                appendSuperscript(x.text, out);
            }
            return;
        }
        out += '^';
        const bool parenthesised = displayPrecedence(x) < 3;
        if (parenthesised) out += '(';
        append(x, out);
        if (parenthesised) out += ')';
    }

    std::string function(const DisplayNode& n, const std::string& power) const {
        std::string args;
        for (const DisplayPtr& a : n.children) args += (args.empty() ? "" : (plain() ? "," : ", ")) + (*this)(*a);
        if (n.plain == "abs" && !plain()) return (style_ == DisplayStyle::Latex ? "\\left|" + args + "\\right|" : "|" + args + "|") + power;
        const std::string& name = style_ == DisplayStyle::Latex ? n.latex : plain() ? n.plain : n.text;
        return name + power + "(" + args + ")";
    }

    std::string matrix(const DisplayNode& n) const {
        const std::size_t rows = n.rows.size(), cols = rows ? n.rows[0].size() : 0;
        std::vector<std::vector<std::string>> cell(rows, std::vector<std::string>(cols));
        for (std::size_t i = 0; i < rows; ++i)
            for (std::size_t j = 0; j < cols; ++j) cell[i][j] = (*this)(*n.rows[i][j]);
        std::string s;
        if (plain()) {
            s = "[";
            for (std::size_t i = 0; i < rows; ++i) {
                s += i ? ",[" : "[";
                for (std::size_t j = 0; j < cols; ++j) s += (j ? "," : "") + cell[i][j];
                s += "]";
            }
            return s + "]";
        }
        if (style_ == DisplayStyle::Latex) {
            s = "\\begin{bmatrix} ";
            for (std::size_t i = 0; i < rows; ++i) {
                if (i) s += " \\\\ ";
                for (std::size_t j = 0; j < cols; ++j) s += (j ? " & " : "") + cell[i][j];
            }
            return s + " \\end{bmatrix}";
        }
        if (rows == 0) return "[ ]";
        std::vector<std::size_t> width(cols, 0);
        for (std::size_t i = 0; i < rows; ++i)
            for (std::size_t j = 0; j < cols; ++j) width[j] = std::max(width[j], columns(cell[i][j]));
        for (std::size_t i = 0; i < rows; ++i) {
            const bool top = i == 0, bottom = i + 1 == rows;
            s += rows == 1 ? "[ " : top ? "⎡ " : bottom ? "⎣ " : "⎢ ";
            for (std::size_t j = 0; j < cols; ++j) s += (j ? "  " : "") + cell[i][j] + std::string(width[j] - columns(cell[i][j]), ' ');
            s += rows == 1 ? " ]" : top ? " ⎤" : bottom ? " ⎦" : " ⎥";
            if (!bottom) s += "\n";
        }
        return s;
    }

    std::string equation(const DisplayNode& n) const {
        const std::string lhs = (*this)(*n.children[0]), rhs = (*this)(*n.children[1]);
        const std::string& op = style_ == DisplayStyle::Latex ? n.latex : plain() ? n.plain : n.text;
        if (style_ != DisplayStyle::Text || (lhs.find('\n') == std::string::npos && rhs.find('\n') == std::string::npos))
            return lhs + op + rhs;
        // Blocks side by side, each centred on the middle line.
        const std::vector<std::string> a = lines(lhs), b = lines(rhs);
        const std::size_t h = std::max(a.size(), b.size()), mid = (h - 1) / 2;
        std::size_t wa = 0;
        for (const auto& l : a) wa = std::max(wa, columns(l));
        auto at = [h](const std::vector<std::string>& block, std::size_t i) -> std::string {
            const std::size_t top = (h - block.size()) / 2;
            return i >= top && i - top < block.size() ? block[i - top] : std::string();
        };
        std::string s;
        const std::string gap(columns(op), ' ');
        for (std::size_t i = 0; i < h; ++i) {
            const std::string left = at(a, i);
            s += rtrim(left + std::string(wa - columns(left), ' ') + (i == mid ? op : gap) + at(b, i));
            if (i + 1 < h) s += "\n";
        }
        return s;
    }
};

}  // namespace

int displayPrecedence(const DisplayNode& n) {
    switch (n.kind) {
        case DisplayKind::Sum:
        case DisplayKind::Equation: return 0;
        case DisplayKind::Product:
        case DisplayKind::Fraction: return 1;
        case DisplayKind::Power:
            return n.children[0]->kind == DisplayKind::Function && n.children[0]->plain != "abs" && isIntegerExponent(*n.children[1]) ? 3
                                                                                                                                      : 2;
        default: return 3;
    }
}

std::string renderDisplay(const DisplayNode& node, DisplayStyle style, bool keyNames) { return Renderer(style, keyNames)(node); }

DisplayPtr displayNumber(std::string text, std::string latex, std::string plain, std::string exponent) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Number;
    n->text = std::move(text);
    n->latex = std::move(latex);
    n->plain = std::move(plain);
    n->exponent = std::move(exponent);
    return n;
}

DisplayPtr displayNode(DisplayKind kind, std::vector<DisplayPtr> children) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = kind;
    n->children = std::move(children);
    return n;
}

DisplayPtr displayRaw(std::string text, std::string latex, std::string plain) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Raw;
    n->text = std::move(text);
    n->latex = std::move(latex);
    n->plain = std::move(plain);
    return n;
}

DisplayPtr displayMoreTerms(std::size_t count) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Raw;
    n->text = n->plain = "⋯ (" + std::to_string(count) + " more terms)";
    n->latex = "\\cdots";
    n->moreTerms = static_cast<std::uint32_t>(std::min<std::size_t>(count, UINT32_MAX));
    return n;
}

std::size_t moreTermsCount(const DisplayNode& node) { return node.moreTerms; }

DisplayPtr displayEquation(DisplayPtr lhs, DisplayPtr rhs) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Equation;
    n->children = {std::move(lhs), std::move(rhs)};
    n->text = n->latex = n->plain = " = ";
    return n;
}

void displayLeaves(const DisplayNode& node, std::vector<std::string>& out) {
    switch (node.kind) {
        case DisplayKind::Symbol:
        case DisplayKind::Number:
        case DisplayKind::Raw: out.push_back(renderDisplay(node, DisplayStyle::Text)); return;
        case DisplayKind::Function: out.push_back(node.text); break;
        case DisplayKind::Matrix:
            for (const auto& row : node.rows)
                for (const DisplayPtr& c : row) displayLeaves(*c, out);
            return;
        default: break;
    }
    for (const DisplayPtr& c : node.children) displayLeaves(*c, out);
}

bool isZeroNumber(const DisplayNode& node) { return node.kind == DisplayKind::Number && node.text == "0" && node.exponent.empty(); }

bool hasZeroEntry(const DisplayNode& matrix) {
    for (const auto& row : matrix.rows)
        for (const auto& cell : row)
            if (isZeroNumber(*cell)) return true;
    return false;
}

DisplayPtr displayNegated(DisplayPtr magnitude) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Sum;
    n->children = {std::move(magnitude)};
    n->negative = {true};
    return n;
}

DisplayPtr displaySumOf(const std::vector<DisplayPtr>& parts) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Sum;
    // Parts built for pages may be cut already ("⋯ (N more terms)" last: cutLongSums).
    // Joined, the whole is cut as the typesetter cuts the sum of every term: its first
    // keptTypesetTerms, then the count of the rest. (A cut part shows its first
    // keptTypesetTerms terms, so those are always among the shown ones.)
    std::size_t total = 0;
    bool cut = false;
    for (const DisplayPtr& p : parts) {
        const std::size_t more = p->kind == DisplayKind::Sum && !p->children.empty() ? moreTermsCount(*p->children.back()) : 0;
        cut = cut || more > 0;
        total += p->kind != DisplayKind::Sum ? 1 : more > 0 ? p->children.size() - 1 + more : p->children.size();
    }
    if (cut) {
        for (const DisplayPtr& p : parts) {
            const std::size_t shown = p->kind == DisplayKind::Sum ? p->children.size() : 1;
            for (std::size_t i = 0; i < shown && n->children.size() < keptTypesetTerms; ++i) {
                const DisplayPtr& term = p->kind == DisplayKind::Sum ? p->children[i] : p;
                if (moreTermsCount(*term)) break;
                n->children.push_back(term);
                n->negative.push_back(p->kind == DisplayKind::Sum && p->negative[i]);
            }
        }
        n->children.push_back(displayMoreTerms(total - n->children.size()));
        n->negative.push_back(false);
        return n;
    }
    for (const DisplayPtr& p : parts) {
        if (p->kind == DisplayKind::Sum) {
            n->children.insert(n->children.end(), p->children.begin(), p->children.end());
            n->negative.insert(n->negative.end(), p->negative.begin(), p->negative.end());
        } else {
            n->children.push_back(p);
            n->negative.push_back(false);
        }
    }
    if (n->children.empty()) return displayNumber("0", "0", "0");
    return n;
}

}  // namespace ll::present
