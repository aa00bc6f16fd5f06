#include "core/symbolic/answer_reader.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

#include "core/model/utf8_text.hpp"
#include "core/symbolic/trig_names.hpp"

namespace ll::symbolic {

AnswerUnreadable::AnswerUnreadable(Message message, std::size_t position, std::vector<std::string> closest, bool unknownName)
    : std::runtime_error(message.english()),
      message_(std::move(message)),
      position_(position),
      closest_(std::move(closest)),
      unknownName_(unknownName) {}

namespace {

using GiNaC::ex;

// ---- The typed characters in plain ASCII, each byte remembering its character ----------

struct Plain {
    std::string text;
    std::vector<std::size_t> position;  // per byte of text: 1-based character of the answer
    void put(const std::string& s, std::size_t at) {
        text += s;
        position.insert(position.end(), s.size(), at);
    }
};

// Letters that stand for themselves in a formula, by their names (θ1 is theta1).
const char* greekName(char32_t c) {
    switch (c) {
        case U'α': return "alpha";
        case U'β': return "beta";
        case U'γ': return "gamma";
        case U'δ': return "delta";
        case U'ε': return "epsilon";
        case U'ζ': return "zeta";
        case U'η': return "eta";
        case U'θ':
        case U'ϑ':
        case U'Θ': return "theta";
        case U'κ': return "kappa";
        case U'λ': return "lambda";
        case U'μ': return "mu";
        case U'ν': return "nu";
        case U'ξ': return "xi";
        case U'ρ': return "rho";
        case U'σ': return "sigma";
        case U'τ': return "tau";
        case U'φ':
        case U'ϕ': return "phi";
        case U'χ': return "chi";
        case U'ψ': return "psi";
        case U'ω': return "omega";
        case U'ℓ': return "l";
        case U'∂': return "d";
        default: return nullptr;
    }
}

// The other characters a hand-written formula has, in ASCII: dots over a letter, fractions,
// multiplication and minus signs, spaces.
const char* symbolSpelling(char32_t c) {
    switch (c) {
        case 0x0307: return "_dot";   // combining dot above: q̇1, θ̇₁
        case 0x0308: return "_ddot";  // combining two dots: q̈1
        case U'ẋ': return "x_dot";
        case U'½': return "(1/2)";
        case U'¼': return "(1/4)";
        case U'¾': return "(3/4)";
        case U'⅓': return "(1/3)";
        case U'⅔': return "(2/3)";
        case U'·':
        case U'×':
        case U'⋅':
        case U'∙':
        case U'∗': return "*";
        case U'−':
        case U'–':
        case U'‐': return "-";
        case U'÷':
        case U'∕': return "/";
        case 0x00A0:
        case 0x2009:
        case 0x202F:
        case 0x2002:
        case 0x2003: return " ";
        default: return nullptr;
    }
}

Plain plainText(const std::string& text) {
    Plain plain;
    std::size_t offset = 0, character = 0;
    while (offset < text.size()) {
        const Utf8Char c = decodeUtf8(text, offset);
        ++character;
        const char32_t u = c.codePoint;
        auto refuse = [&] {
            throw AnswerUnreadable(message(MessageId::AnswerCharacter, std::to_string(character), describeCharacter(c, text, offset)),
                                   character);
        };
        if (!c.valid) refuse();
        if (u < 0x80) {
            if (u == '\t' || u == '\n' || u == '\r') plain.put(" ", character);
            else if (u < 0x20 || u == 0x7f) refuse();
            else plain.put(std::string(1, static_cast<char>(u)), character);
        } else if (const char* name = greekName(u)) {
            plain.put(name, character);
        } else if (u == U'π') {
            plain.put(" pi ", character);
        } else if (u >= U'₀' && u <= U'₉') {
            plain.put(std::string(1, static_cast<char>('0' + (u - U'₀'))), character);
        } else if (u == U'²' || u == U'³' || u == U'¹' || (u >= U'⁴' && u <= U'⁹') || u == U'⁰') {
            const int digit = u == U'¹' ? 1 : u == U'²' ? 2 : u == U'³' ? 3 : u == U'⁰' ? 0 : static_cast<int>(u - U'⁰');
            plain.put("^" + std::to_string(digit), character);
        } else if (const char* spelled = symbolSpelling(u)) {
            plain.put(spelled, character);
        } else {
            refuse();
        }
        offset += c.bytes;
    }
    return plain;
}

// ---- Tokens -------------------------------------------------------------------------------

enum class Kind { Number, Name, Operator, End };

struct Token {
    Kind kind = Kind::End;
    std::string text;          // the name, the number's digits, or the operator ("**" is "^")
    std::size_t position = 0;  // 1-based character
    bool spaceBefore = false;
};

std::vector<Token> tokens(const Plain& plain) {
    std::vector<Token> out;
    const std::string& s = plain.text;
    std::size_t i = 0;
    bool space = false;
    auto at = [&](std::size_t k) {
        return k < plain.position.size() ? plain.position[k] : (plain.position.empty() ? 1 : plain.position.back() + 1);
    };
    while (i < s.size()) {
        const char c = s[i];
        if (c == ' ') {
            space = true;
            ++i;
            continue;
        }
        Token t;
        t.position = at(i);
        t.spaceBefore = space;
        space = false;
        if (std::isdigit(static_cast<unsigned char>(c)) ||
            (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            std::size_t j = i;
            while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
            // an exponent only when digits follow (2e3, 1.5e-2); "2e" alone is not a number
            if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
                std::size_t k = j + 1;
                if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
                if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
                    j = k;
                    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
                }
            }
            t.kind = Kind::Number;
            t.text = s.substr(i, j - i);
            if (std::count(t.text.begin(), t.text.end(), '.') > 1)
                throw AnswerUnreadable(message(MessageId::AnswerMalformedNumber, std::to_string(t.position), t.text), t.position);
            i = j;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::size_t j = i;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
            t.kind = Kind::Name;
            t.text = s.substr(i, j - i);
            i = j;
        } else if (c == '*' && i + 1 < s.size() && s[i + 1] == '*') {
            t.kind = Kind::Operator;
            t.text = "^";
            i += 2;
        } else if (std::string("+-*/^()[],;=").find(c) != std::string::npos) {
            t.kind = Kind::Operator;
            t.text = std::string(1, c);
            ++i;
        } else {
            Utf8Char ch;
            ch.codePoint = static_cast<unsigned char>(c);
            ch.valid = true;
            throw AnswerUnreadable(message(MessageId::AnswerCharacter, std::to_string(t.position), describeCharacter(ch, s, i)),
                                   t.position);
        }
        out.push_back(t);
    }
    Token end;
    end.position = at(s.size());
    out.push_back(end);
    return out;
}

// "9.81" → 981/100, "2e-3" → 1/500: exact.
ex exactNumber(const std::string& text) {
    std::string mantissa = text;
    long exponent = 0;
    const std::size_t e = text.find_first_of("eE");
    if (e != std::string::npos) {
        mantissa = text.substr(0, e);
        exponent = std::stol(text.substr(e + 1));
    }
    const std::size_t dot = mantissa.find('.');
    std::string digits = mantissa;
    if (dot != std::string::npos) {
        exponent -= static_cast<long>(mantissa.size() - dot - 1);
        digits.erase(dot, 1);
    }
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
    if (digits.empty()) return 0;
    GiNaC::numeric value(digits.c_str());
    return value * GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(exponent));
}

// ---- Names ---------------------------------------------------------------------------------

bool isFunctionName(const std::string& name) { return name == "sin" || name == "cos" || name == "tan" || name == "sqrt" || name == "cot"; }

// The digits at the end of `name` after `prefix` (q12 → 12 for prefix "q"), when the rest is
// exactly that.
std::optional<int> indexAfter(const std::string& name, const std::string& prefix, const std::string& suffix = "") {
    if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    if (name.size() < suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return std::nullopt;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.empty() || digits.size() > 3 ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
        return std::nullopt;
    return std::stoi(digits);
}

class NameReader {
public:
    explicit NameReader(const AnswerVocabulary& v) : v_(v) {}

    // The expression a name stands for, or nothing.
    std::optional<ex> resolve(const std::string& name) const {
        if (auto it = v_.names.find(name); it != v_.names.end()) return it->second;
        if (name == "pi" || name == "Pi") return ex(GiNaC::Pi);
        std::string plain = name;  // q_1, theta_dot_1 → q1, thetadot1
        plain.erase(std::remove(plain.begin(), plain.end(), '_'), plain.end());
        if (plain != name)
            if (auto it = v_.names.find(plain); it != v_.names.end()) return it->second;
        const int n = static_cast<int>(v_.q.size());
        auto joint = [&](std::optional<int> i, const std::vector<GiNaC::symbol>& of) -> std::optional<ex> {
            if (i && *i >= 1 && *i <= static_cast<int>(of.size())) return ex(of[*i - 1]);
            return std::nullopt;
        };
        if (v_.robot) {
            for (const char* p : {"q", "theta", "th"}) {
                if (auto e = joint(indexAfter(plain, p), v_.q)) return e;
                for (const char* dotted : {"dot", "d"}) {
                    if (auto e = joint(indexAfter(plain, std::string(p) + dotted), v_.qd)) return e;
                    if (auto e = joint(indexAfter(plain, p, dotted), v_.qd)) return e;
                    if (auto e = joint(indexAfter(plain, std::string("d") + p), v_.qd)) return e;
                }
                for (const char* ddotted : {"ddot", "dd"}) {
                    if (auto e = joint(indexAfter(plain, std::string(p) + ddotted), v_.qdd)) return e;
                    if (auto e = joint(indexAfter(plain, p, ddotted), v_.qdd)) return e;
                    if (auto e = joint(indexAfter(plain, std::string("dd") + p), v_.qdd)) return e;
                }
            }
            if (auto trig = parseTrigName(plain, n); trig && !trig->indices.empty()) {
                ex angle = 0;
                for (int i : trig->indices) angle += v_.q[i - 1];
                return trig->kind == 'c' ? GiNaC::cos(angle) : GiNaC::sin(angle);
            }
        } else {
            for (std::size_t i = 0; i < v_.coordinateNames.size(); ++i) {
                const std::string& c = v_.coordinateNames[i];
                std::string cp = c;
                cp.erase(std::remove(cp.begin(), cp.end(), '_'), cp.end());
                std::size_t digits = cp.size();  // theta1: θ̇1 reads as theta_dot1, the dot before the index
                while (digits > 0 && std::isdigit(static_cast<unsigned char>(cp[digits - 1]))) --digits;
                const std::string letters = cp.substr(0, digits), index = cp.substr(digits);
                if (plain == cp) return ex(v_.q[i]);
                if (plain == cp + "dot" || plain == "d" + cp || plain == cp + "d" || (!index.empty() && plain == letters + "dot" + index))
                    return ex(v_.qd[i]);
                if (plain == cp + "ddot" || plain == "dd" + cp || plain == cp + "dd" ||
                    (!index.empty() && plain == letters + "ddot" + index))
                    return ex(v_.qdd[i]);
            }
        }
        return std::nullopt;
    }

    std::vector<std::string> known() const {
        std::vector<std::string> all;
        for (const auto& [name, value] : v_.names) all.push_back(name);
        if (v_.robot)
            for (std::size_t i = 1; i <= v_.q.size(); ++i) {
                all.push_back("q" + std::to_string(i));
                all.push_back("qd" + std::to_string(i));
            }
        for (std::size_t i = 0; i < v_.coordinateNames.size(); ++i) {
            all.push_back(v_.coordinateNames[i]);
            all.push_back(v_.coordinateNames[i] + "_dot");
        }
        return all;
    }

    // A run of names written together ("a1lc2"): the one way to split it into known names,
    // the last of which may be a function when `beforeParenthesis`. Empty: none or several.
    std::vector<std::string> split(const std::string& run, bool beforeParenthesis) const {
        std::vector<std::vector<std::string>> found;
        std::vector<std::string> current;
        search(run, 0, beforeParenthesis, current, found);
        if (found.size() != 1) return {};
        return found.front();
    }

private:
    void search(const std::string& run, std::size_t from, bool beforeParenthesis, std::vector<std::string>& current,
                std::vector<std::vector<std::string>>& found) const {
        if (found.size() > 1) return;
        if (from == run.size()) {
            if (current.size() > 1) found.push_back(current);
            return;
        }
        for (std::size_t end = from + 1; end <= run.size(); ++end) {
            const std::string piece = run.substr(from, end - from);
            const bool last = end == run.size();
            const bool ok = resolve(piece).has_value() || (last && beforeParenthesis && isFunctionName(piece));
            if (!ok) continue;
            // a piece may not end between two digits (a12 is not a1·2)
            if (!last && std::isdigit(static_cast<unsigned char>(run[end - 1])) && std::isdigit(static_cast<unsigned char>(run[end])))
                continue;
            current.push_back(piece);
            search(run, end, beforeParenthesis, current, found);
            current.pop_back();
        }
    }

    const AnswerVocabulary& v_;
};

// ---- The grammar ---------------------------------------------------------------------------
//   answer  := sum ['=' sum]
//   sum     := ['+'|'-'] product (('+'|'-') product)*
//   product := factor (('*'|'/') factor | factor written right after)*
//   factor  := ['+'|'-'] power
//   power   := primary ['^' factor]
//   primary := number | name | function ['^' power] (‘(’ sum ‘)’ | power) | '(' sum ')'

class Parser {
public:
    Parser(std::vector<Token> tokens, const AnswerVocabulary& vocabulary) : t_(std::move(tokens)), names_(vocabulary) {}

    ReadAnswer answer() {
        ReadAnswer read;
        if (peek().kind == Kind::End) throw AnswerUnreadable(message(MessageId::AnswerEmpty), 1);
        if (isOp("[")) {  // a whole matrix, unless the brackets only group one expression
            read.rows = matrix();
            const bool one = read.rows.size() == 1 && read.rows[0].size() == 1;
            if (peek().kind == Kind::End && !one) return read;
            read.rows.clear();
            i_ = 0;
        }
        read.value = sum();
        if (isOp("=")) {
            next();
            read.equation = true;
            if (peek().kind == Kind::End) expected(MessageId::AnswerExpectOperand);
            read.value = read.value - sum();
            if (isOp("=")) throw AnswerUnreadable(message(MessageId::AnswerSecondEquals, std::to_string(peek().position)), peek().position);
        }
        if (peek().kind != Kind::End) {
            if (isOp(")") || isOp("]"))
                throw AnswerUnreadable(message(MessageId::AnswerUnmatchedClosing, std::to_string(peek().position)), peek().position);
            expected(MessageId::AnswerExpectOperator);
        }
        return read;
    }

private:
    // "[a, b; c, d]", "[[a, b], [c, d]]", "[a; b; c]": rows of equal length.
    std::vector<std::vector<ex>> matrix() {
        next();  // '['
        std::vector<std::vector<ex>> rows(1);
        const bool nested = isOp("[");
        for (;;) {
            if (nested) {
                if (!isOp("[")) expected(MessageId::AnswerExpectOpenBracket);
                next();
                std::vector<ex> row{sum()};
                while (isOp(",")) {
                    next();
                    row.push_back(sum());
                }
                if (!isOp("]")) expected(MessageId::AnswerExpectBracket);
                next();
                rows.back() = row;
                if (!isOp(",") && !isOp(";")) break;
                next();
                rows.emplace_back();
                continue;
            }
            rows.back().push_back(sum());
            if (isOp(",")) {
                next();
            } else if (isOp(";")) {
                next();
                rows.emplace_back();
            } else {
                break;
            }
        }
        if (!isOp("]")) expected(MessageId::AnswerExpectBracket);
        const std::size_t closing = next().position;
        for (std::size_t r = 1; r < rows.size(); ++r)
            if (rows[r].size() != rows[0].size())
                throw AnswerUnreadable(message(MessageId::AnswerRowLength, std::to_string(closing), r + 1, rows[r].size(), rows[0].size()),
                                       closing);
        return rows;
    }

    const Token& peek(std::size_t ahead = 0) const { return t_[std::min(i_ + ahead, t_.size() - 1)]; }
    const Token& next() { return t_[std::min(i_++, t_.size() - 1)]; }
    bool isOp(const char* op, std::size_t ahead = 0) const { return peek(ahead).kind == Kind::Operator && peek(ahead).text == op; }

    [[noreturn]] void expected(MessageId what) const {
        const Token& found = peek();
        Message foundText = found.kind == Kind::End ? message(MessageId::AnswerTheEnd) : literal("'" + found.text + "'");
        throw AnswerUnreadable(Message(MessageId::AnswerExpected, {literal(std::to_string(found.position)), Message(what), foundText}),
                               found.position);
    }

    // Whether the next token starts a factor written right after the previous one (2 a1,
    // a1 (…), (…)(…)).
    bool startsImplicitFactor() const {
        const Token& t = peek();
        return t.kind == Kind::Number || t.kind == Kind::Name || (t.kind == Kind::Operator && (t.text == "(" || t.text == "["));
    }

    ex sum() {
        ex value;
        if (isOp("-")) {
            next();
            value = -product();
        } else {
            if (isOp("+")) next();
            value = product();
        }
        while (isOp("+") || isOp("-")) {
            const bool minus = next().text == "-";
            const ex term = product();
            value = minus ? value - term : value + term;
        }
        return value;
    }

    ex product() {
        ex value = factor();
        for (;;) {
            if (isOp("*")) {
                next();
                value = value * factor();
            } else if (isOp("/")) {
                const Token& slash = next();
                const ex divisor = factor();
                if (divisor.is_zero())
                    throw AnswerUnreadable(message(MessageId::AnswerDivisionByZero, std::to_string(slash.position)), slash.position);
                value = value / divisor;
            } else if (startsImplicitFactor()) {
                value = value * power();
            } else {
                return value;
            }
        }
    }

    ex factor() {
        if (isOp("-")) {
            next();
            return -factor();
        }
        if (isOp("+")) {
            next();
            return factor();
        }
        return power();
    }

    ex power() {
        ex base = primary();
        if (isOp("^")) {
            const std::size_t at = next().position;
            return GiNaC::pow(base, exponent(at));
        }
        return base;
    }

    // An exponent: a rational number of at most ±64 (b11's squares, a ½ power), so that
    // no answer makes GiNaC compute 2^(10^10) exactly.
    ex exponent(std::size_t caret) {
        const ex e = factor();
        if (!GiNaC::is_exactly_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_rational() ||
            GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e)) > 64)
            throw AnswerUnreadable(message(MessageId::AnswerExponent, std::to_string(caret)), caret);
        return e;
    }

    ex primary() {
        const Token& t = peek();
        if (t.kind == Kind::Number) {
            next();
            return exactNumber(t.text);
        }
        if (isOp("(") || isOp("[")) {  // brackets group as parentheses do
            const bool square = isOp("[");
            next();
            const ex inside = sum();
            if (!isOp(square ? "]" : ")")) expected(square ? MessageId::AnswerExpectBracket : MessageId::AnswerExpectClosing);
            next();
            return inside;
        }
        if (t.kind == Kind::Name) return name();
        expected(MessageId::AnswerExpectOperand);
    }

    ex function(const std::string& which) {
        // sin^2(q2), sin² q2: the power of the function's value
        std::optional<ex> raised;  // sin^2: the function's value to that power
        if (isOp("^")) {
            const std::size_t at = next().position;
            raised = exponent(at);
        }
        ex argument;
        if (isOp("(")) {
            next();
            argument = sum();
            if (!isOp(")")) expected(MessageId::AnswerExpectClosing);
            next();
        } else if (startsImplicitFactor()) {
            argument = power();  // cos q2
        } else {
            expected(MessageId::AnswerExpectArgument);
        }
        ex value;
        if (which == "sin") value = GiNaC::sin(argument);
        else if (which == "cos") value = GiNaC::cos(argument);
        else if (which == "tan") value = GiNaC::sin(argument) / GiNaC::cos(argument);
        else if (which == "cot") value = GiNaC::cos(argument) / GiNaC::sin(argument);
        else value = GiNaC::sqrt(argument);
        return raised ? GiNaC::pow(value, *raised) : value;
    }

    ex name() {
        const Token t = next();
        if (isFunctionName(t.text)) return function(t.text);
        if (auto value = names_.resolve(t.text)) return *value;
        if (auto pieces = names_.split(t.text, isOp("(")); !pieces.empty()) {
            ex value = 1;
            for (std::size_t k = 0; k + 1 < pieces.size(); ++k) value = value * *names_.resolve(pieces[k]);
            const std::string& last = pieces.back();
            if (isFunctionName(last) && !names_.resolve(last)) return value * function(last);
            ex lastValue = *names_.resolve(last);
            if (isOp("^")) {  // m1lc1^2: the power is the last name's, as written
                const std::size_t at = next().position;
                lastValue = GiNaC::pow(lastValue, exponent(at));
            }
            return value * lastValue;
        }
        std::vector<std::string> closest = closestNames(t.text, names_.known());
        Message list = literal("");
        if (!closest.empty()) {
            std::string joined;
            for (const std::string& c : closest) joined += (joined.empty() ? "" : ", ") + c;
            list = message(MessageId::AnswerClosestNames, joined);
        }
        throw AnswerUnreadable(message(MessageId::AnswerUnknownName, std::to_string(t.position), t.text, list), t.position, closest, true);
    }

    std::vector<Token> t_;
    std::size_t i_ = 0;
    NameReader names_;
};

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::vector<std::string> closestNames(const std::string& name, const std::vector<std::string>& known) {
    std::vector<std::pair<std::size_t, std::string>> scored;
    for (const std::string& k : known) {
        const std::size_t d = editDistance(name, k);
        if (d <= 2 && d < std::max(name.size(), k.size())) scored.emplace_back(d, k);
    }
    std::sort(scored.begin(), scored.end());
    scored.erase(std::unique(scored.begin(), scored.end()), scored.end());
    std::vector<std::string> out;
    for (const auto& [d, k] : scored) {
        if (out.size() == 3) break;
        out.push_back(k);
    }
    return out;
}

std::string plainSpelling(const std::string& text) { return plainText(text).text; }

ReadAnswer readAnswer(const std::string& text, const AnswerVocabulary& vocabulary) {
    const Plain plain = plainText(text);
    Parser parser(tokens(plain), vocabulary);
    return parser.answer();
}

}  // namespace ll::symbolic
