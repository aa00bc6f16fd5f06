#include "core/present/latex_formula.hpp"

#include <cctype>
#include <map>
#include <memory>
#include <vector>

namespace ll::present {
namespace {

const std::map<std::string, std::string>& letters() {
    static const std::map<std::string, std::string> m = {{"alpha", "α"}, {"beta", "β"},   {"gamma", "γ"}, {"delta", "δ"},  {"epsilon", "ε"},
                                                         {"theta", "θ"}, {"lambda", "λ"}, {"mu", "μ"},    {"pi", "π"},     {"rho", "ρ"},
                                                         {"sigma", "σ"}, {"tau", "τ"},    {"phi", "φ"},   {"omega", "ω"},  {"Omega", "Ω"},
                                                         {"Gamma", "Γ"}, {"Delta", "Δ"},  {"ell", "ℓ"},   {"partial", "∂"}};
    return m;
}

// What a script or a word reads as, flattened to characters: {\omega,i} → ω,i, {j \le i} → j≤i.
std::string flat(const std::string& latex) {
    std::string out;
    for (std::size_t i = 0; i < latex.size();) {
        const char c = latex[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < latex.size() && std::isalpha(static_cast<unsigned char>(latex[j]))) ++j;
            const std::string command = latex.substr(i + 1, j - i - 1);
            if (auto it = letters().find(command); it != letters().end()) out += it->second;
            else if (command == "le") out += "≤";
            else if (command == "ge") out += "≥";
            else if (command.empty() && j < latex.size()) ++j;  // \, \  \;
            i = j;
            continue;
        }
        if (c == '-') out += "−";
        else if (c != '{' && c != '}' && c != ' ') out += c;
        ++i;
    }
    return out;
}

std::shared_ptr<DisplayNode> symbol(const std::string& text, bool upright = false) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Symbol;
    n->text = n->latex = n->plain = n->name = text;
    n->upright = upright;
    return n;
}

DisplayPtr row(std::vector<DisplayPtr> children) {
    if (children.size() == 1) return children[0];
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Raw;
    n->children = std::move(children);
    return n;
}

class Parser {
public:
    explicit Parser(const std::string& s) : s_(s) {}

    // Atoms up to the end, a closing brace, \right, & or \\ (or a top-level \quad when
    // `parts` is given: each part's atoms go there).
    std::vector<DisplayPtr> atoms(std::vector<DisplayPtr>* parts = nullptr) {
        std::vector<DisplayPtr> out;
        while (at_ < s_.size()) {
            const char c = s_[at_];
            if (c == '}' || c == '&') break;
            if (startsWith("\\right") || startsWith("\\\\") || startsWith("\\end")) break;
            if (parts && startsWith("\\quad")) {
                at_ += 5;
                if (!out.empty() && out.back()->kind == DisplayKind::Raw && out.back()->text == ", ") out.pop_back();
                if (!out.empty()) parts->push_back(row(std::move(out)));
                out.clear();
                continue;
            }
            if (c == '_' || c == '^') {
                ++at_;
                const std::string source = group();
                attach(out, c == '_', flat(source), source.find("\\mathrm") != std::string::npos);
                continue;
            }
            if (DisplayPtr a = atom()) out.push_back(a);
        }
        if (parts && !out.empty()) parts->push_back(row(std::move(out)));
        return out;
    }

private:
    const std::string& s_;
    std::size_t at_ = 0;

    bool startsWith(const char* p) const { return s_.compare(at_, std::char_traits<char>::length(p), p) == 0; }

    // {…} as its source, or a single character or command.
    std::string group() {
        while (at_ < s_.size() && s_[at_] == ' ') ++at_;
        if (at_ >= s_.size()) return {};
        if (s_[at_] == '\\') {
            std::size_t j = at_ + 1;
            while (j < s_.size() && std::isalpha(static_cast<unsigned char>(s_[j]))) ++j;
            std::string g = s_.substr(at_, j - at_);
            at_ = j;
            return g;
        }
        if (s_[at_] != '{') return std::string(1, s_[at_++]);
        int depth = 0;
        const std::size_t start = at_ + 1;
        for (; at_ < s_.size(); ++at_) {
            depth += s_[at_] == '{' ? 1 : s_[at_] == '}' ? -1 : 0;
            if (depth == 0) break;
        }
        return s_.substr(start, at_++ - start);
    }

    DisplayPtr parsed(const std::string& source) {
        Parser inner(source);
        return row(inner.atoms());
    }

    void attach(std::vector<DisplayPtr>& out, bool sub, const std::string& script, bool upright) {
        if (!out.empty() && out.back()->kind == DisplayKind::Symbol) {
            auto n = std::make_shared<DisplayNode>(*out.back());
            if (sub && n->subShown.empty() && n->supText.empty()) {
                n->subShown = n->subText = script;
                n->subUpright = upright;  // E_{\mathrm{pot}}
                out.back() = n;
                return;
            }
            if (!sub && n->supText.empty()) {
                n->supText = script;
                out.back() = n;
                return;
            }
        }
        if (out.empty()) return;
        // A script on anything else (a parenthesis, a fence): a power of it.
        out.back() = displayNode(DisplayKind::Power, {out.back(), symbol(script)});
    }

    DisplayPtr atom() {
        const char c = s_[at_];
        if (c == ' ' || c == '{') {
            if (c == '{') {
                const std::string inner = group();
                return parsed(inner);
            }
            ++at_;
            return nullptr;
        }
        if (std::isalpha(static_cast<unsigned char>(c))) return ++at_, symbol(std::string(1, c));
        if (std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t j = at_;
            while (j < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[j])) || s_[j] == '.')) ++j;
            const std::string digits = s_.substr(at_, j - at_);
            at_ = j;
            return displayNumber(digits, digits, digits);
        }
        ++at_;
        switch (c) {
            case '=': return displayRaw(" = ", "=", "=");
            case '+': return displayRaw(" + ", "+", "+");
            case '-': return displayRaw(" − ", "-", "-");
            case ',': return displayRaw(", ", ",", ",");
            case ';': return displayRaw("; ", ";", ";");
            case ':': return displayRaw(": ", ":", ":");
            case '\\': break;
            default: return displayRaw(std::string(1, c), std::string(1, c), std::string(1, c));
        }
        std::size_t j = at_;
        while (j < s_.size() && std::isalpha(static_cast<unsigned char>(s_[j]))) ++j;
        const std::string command = s_.substr(at_, j - at_);
        at_ = j;
        if (command.empty()) {  // \, \; \  \{
            const char what = at_ < s_.size() ? s_[at_++] : ' ';
            return what == '{' || what == '}' ? displayRaw(std::string(1, what), "", "") : displayRaw(" ", " ", " ");
        }
        if (auto it = letters().find(command); it != letters().end()) return symbol(it->second);
        if (command == "frac" || command == "tfrac" || command == "dfrac") {
            const std::string num = group(), den = group();
            return displayNode(DisplayKind::Fraction, {parsed(num), parsed(den)});
        }
        if (command == "mathrm" || command == "operatorname") return symbol(flat(group()), true);
        if (command == "text") return displayRaw(group(), "", "");
        if (command == "mathcal") return group(), symbol("ℒ");
        if (command == "dot" || command == "ddot" || command == "hat") {
            const DisplayPtr inner = parsed(group());
            if (inner->kind != DisplayKind::Symbol) return inner;
            auto n = std::make_shared<DisplayNode>(*inner);
            if (command == "hat") n->hat = true;
            else n->dots = command == "dot" ? 1 : 2;
            return n;
        }
        if (command == "left") {
            const std::string open = group();
            const DisplayPtr inner = row(atoms());
            if (startsWith("\\right")) {
                at_ += 6;
                group();
            }
            if (open == "(") return displayNode(DisplayKind::Fence, {inner});
            return row({displayRaw(open == "\\{" ? "{" : open, "", ""), inner});
        }
        if (command == "sum") return symbol("∑", true);
        if (command == "cdots" || command == "dots" || command == "ldots") return displayRaw("⋯", "", "");
        if (command == "le") return displayRaw(" ≤ ", "", "");
        if (command == "ge") return displayRaw(" ≥ ", "", "");
        if (command == "times") return displayRaw(" × ", "", "");
        if (command == "cdot") return displayRaw(" · ", "", "");
        if (command == "quad" || command == "qquad") return displayRaw("    ", "", "");
        if (command == "begin") {
            group();  // bmatrix
            auto m = std::make_shared<DisplayNode>();
            m->kind = DisplayKind::Matrix;
            std::vector<DisplayPtr> cells;
            while (at_ < s_.size()) {
                cells.push_back(row(atoms()));
                if (startsWith("&")) {
                    ++at_;
                    continue;
                }
                m->rows.push_back(cells);
                cells.clear();
                if (startsWith("\\\\")) {
                    at_ += 2;
                    continue;
                }
                if (startsWith("\\end")) {
                    at_ += 4;
                    group();
                }
                break;
            }
            for (auto& r : m->rows) r.resize(m->rows[0].size(), displayRaw("", "", ""));
            return m;
        }
        return displayRaw(command, "", "");
    }
};

}  // namespace

DisplayPtr formulaFromLatex(const std::string& latex, const std::string& text) {
    auto root = std::make_shared<DisplayNode>();
    root->kind = DisplayKind::Raw;
    root->text = root->plain = text;
    root->latex = latex;
    Parser parser(latex);
    std::vector<DisplayPtr> parts;
    parser.atoms(&parts);
    root->children = std::move(parts);
    return root;
}

}  // namespace ll::present
