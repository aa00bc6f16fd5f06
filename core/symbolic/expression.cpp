#include "core/symbolic/expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include <cln/exception.h>
#include <cln/float.h>
#include <cln/number_io.h>

#include "core/symbolic/angle_units.hpp"
#include "core/model/diagnostics.hpp"
#include "core/model/usable_number.hpp"
#include "core/symbolic/ginac_lock.hpp"

namespace ll {

namespace {

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// 1-based position of the first whole-word occurrence of `name`, or 0.
std::size_t identifierPosition(const std::string& text, const std::string& name) {
    for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
        const bool startsWord = at == 0 || !isIdentifierChar(text[at - 1]);
        const std::size_t end = at + name.size();
        const bool endsWord = end == text.size() || !isIdentifierChar(text[end]);
        if (startsWord && endsWord) return at + 1;
    }
    return 0;
}

// GiNaC reports "parse error at line 0, column 0: <what>\n[<function>]"; keep <what>.
std::string parseErrorReason(const std::string& what) {
    std::string reason = what;
    const std::size_t column = reason.find("column ");
    if (column != std::string::npos) {
        const std::size_t colon = reason.find(": ", column);
        if (colon != std::string::npos) reason = reason.substr(colon + 2);
    }
    reason = reason.substr(0, reason.find('\n'));
    return reason;
}

// The token GiNaC stopped at ("got: \"/\"" -> "/"), empty at the end of the text.
std::string offendingToken(const std::string& reason) {
    const std::size_t got = reason.find("got: ");
    if (got == std::string::npos) return {};
    std::string token = reason.substr(got + 5);
    if (token.size() >= 2 && token.front() == '"' && token.back() == '"') return token.substr(1, token.size() - 2);
    return {};  // EOF
}

// GiNaC's lexer has read one character past the offending token when it throws, so
// the token is the last occurrence of its text ending at or before `consumed`.
std::size_t tokenPosition(const std::string& text, const std::string& token, std::streamoff consumed) {
    if (token.empty() || consumed < 0) return 0;
    const std::size_t limit = static_cast<std::size_t>(consumed);
    const std::size_t from = limit >= token.size() ? limit - token.size() : 0;
    const std::size_t at = text.rfind(token, from);
    return at == std::string::npos ? 0 : at + 1;
}

// What GiNaC expected, in our words where we know them ("expected ')'", "expected EOF").
Message parserExpectation(const std::string& what) {
    using enum MessageId;
    if (what == "expected EOF") return ParserExpectedEnd;
    if (what == "expected ')' or ',' in argument list") return ParserExpectedArgumentListEnd;
    if (what.rfind("expected '", 0) == 0) return message(ParserExpected, what.substr(9));
    return literal(what);  // GiNaC's own words
}

// GiNaC's reason, "<what>, got: <token>" with the token quoted or EOF, in our words:
// "unexpected \"/\"", "expected ')', got end of expression".
Message parseErrorDetail(const std::string& reason) {
    using enum MessageId;
    const std::size_t got = reason.find(", got: ");
    if (got == std::string::npos) return literal(reason);
    const std::string what = reason.substr(0, got);
    const std::string token = reason.substr(got + 7);
    if (what == "unexpected token") return token == "EOF" ? Message(ParserUnexpectedEnd) : message(ParserUnexpectedToken, token);
    return message(ParserExpectedGot, parserExpectation(what), token == "EOF" ? Message(ParserEndOfExpression) : literal(token));
}

// Positions are found in the text GiNaC read (source.text) and reported in characters
// of what the user typed (source.original).
Message describeParseError(const PreparedExpression& source, const std::string& what, std::streamoff consumed) {
    using enum MessageId;
    const std::string reason = parseErrorReason(what);
    if (reason.rfind("no function \"", 0) == 0) {
        const std::string name = reason.substr(13, reason.find('"', 13) - 13);
        return message(ExpressionUnknownFunction, name, source.atPosition(identifierPosition(source.text, name)), source.quoted());
    }
    const std::string token = offendingToken(reason);
    if (token.empty()) return message(ExpressionSyntaxErrorAtEnd, source.quoted(), parseErrorDetail(reason));
    return message(ExpressionSyntaxError, source.atPosition(tokenPosition(source.text, token, consumed)), source.quoted(),
                   parseErrorDetail(reason));
}

Message describeUnknownSymbol(const PreparedExpression& source, const std::string& what, const std::vector<std::string>& known) {
    using enum MessageId;
    // find_or_insert_symbol: symbol "l3" not found
    const std::size_t open = what.find('"');
    const std::size_t close = open == std::string::npos ? open : what.find('"', open + 1);
    if (close == std::string::npos) return message(ExpressionCannotParse, source.quoted(), what);
    const std::string name = what.substr(open + 1, close - open - 1);
    std::string knownList;
    const std::size_t shown = std::min<std::size_t>(known.size(), 12);  // a long list would bury the message
    for (std::size_t i = 0; i < shown; ++i) knownList += known[i] + ", ";
    if (shown < known.size()) knownList += "..., ";
    knownList += "pi";
    return message(ExpressionUnknownSymbol, name, source.atPosition(identifierPosition(source.text, name)), source.quoted(), knownList);
}

// Index just past the ')' that closes the '(' at `open`, or npos.
std::size_t pastClosing(const std::string& text, std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < text.size(); ++i) {
        if (text[i] == '(') ++depth;
        if (text[i] == ')' && --depth == 0) return i + 1;
    }
    return std::string::npos;
}

// The end (exclusive) of the operand of a '/' that starts at `from`: an optional sign,
// then a number, a name, a call f(...) or a parenthesised group, then any ^ exponent.
std::size_t operandEnd(const std::string& text, std::size_t from) {
    std::size_t i = text.find_first_not_of(" \t\n", from);
    if (i == std::string::npos) return text.size();
    if (text[i] == '-' || text[i] == '+') i = text.find_first_not_of(" \t\n", i + 1);
    if (i == std::string::npos) return text.size();
    if (text[i] == '(') {
        i = pastClosing(text, i);
    } else if (std::isalpha(static_cast<unsigned char>(text[i]))) {
        while (i < text.size() && isIdentifierChar(text[i])) ++i;
        const std::size_t next = text.find_first_not_of(" \t\n", i);
        if (next != std::string::npos && text[next] == '(') i = pastClosing(text, next);
    } else {
        while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
        if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
            ++i;
            if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
            while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        }
    }
    if (i == std::string::npos) return text.size();
    const std::size_t next = text.find_first_not_of(" \t\n", i);
    if (next != std::string::npos && text[next] == '^') return operandEnd(text, next + 1);
    return i;
}

// 1-based position of the first '/' whose divisor is zero once `values` are put in, or 0.
std::size_t zeroDivisorPosition(const std::string& text, const GiNaC::symtab& symbols, const GiNaC::lst& values) {
    for (std::size_t slash = text.find('/'); slash != std::string::npos; slash = text.find('/', slash + 1)) {
        const std::string divisor = text.substr(slash + 1, operandEnd(text, slash + 1) - slash - 1);
        try {
            GiNaC::parser parser(symbols, /*strict=*/true);
            std::istringstream input(divisor);
            const GiNaC::ex value = parser(input).subs(values).evalf();
            if (value.is_zero()) return slash + 1;
        } catch (const std::exception&) {
            // not a divisor that reads alone (or itself singular): look further
        } catch (...) {
        }
    }
    return 0;
}

// The start of the operand before a '^' at `caret`: a number (1.5, 2e-3), a name, a
// call f(...) or a parenthesised group; npos when there is none.
std::size_t operandBegin(const std::string& text, std::size_t caret) {
    std::size_t i = caret;
    while (i > 0 && std::isspace(static_cast<unsigned char>(text[i - 1]))) --i;
    if (i == 0) return std::string::npos;
    if (text[i - 1] == ')') {
        int depth = 0;
        std::size_t open = i;
        while (open > 0) {
            --open;
            if (text[open] == ')') ++depth;
            if (text[open] == '(' && --depth == 0) break;
        }
        if (depth != 0) return std::string::npos;
        std::size_t name = open;
        while (name > 0 && std::isspace(static_cast<unsigned char>(text[name - 1]))) --name;
        std::size_t first = name;
        while (first > 0 && isIdentifierChar(text[first - 1])) --first;
        return first < name && std::isalpha(static_cast<unsigned char>(text[first])) ? first : open;
    }
    std::size_t j = i;
    while (j > 0) {
        const char c = text[j - 1];
        if (isIdentifierChar(c) || c == '.') {
            --j;
        } else if ((c == '+' || c == '-') && j >= 3 && (text[j - 2] == 'e' || text[j - 2] == 'E') &&
                   (std::isdigit(static_cast<unsigned char>(text[j - 3])) || text[j - 3] == '.')) {
            j -= 2;  // the sign of a number's exponent, 2e-3
        } else {
            break;
        }
    }
    return j < i ? j : std::string::npos;
}

// GiNaC computes a number raised to an integer exactly, as soon as it reads it: 10^(10^10),
// pow(10, 10^10), a^n with the parameter n = 1e10, or ((9^999)^999)^999 would take hours
// and gigabytes (a scene's physics never needs such numbers). So before GiNaC reads an
// expression, every power is checked on its own, innermost first (a power's text holds
// those inside it, so shorter texts go first and what is evaluated is already bounded):
// its exponent, evaluated with the parameters' values, must lie within ±kLargestExponent,
// and an exact number raised to it must have at most kLargestDigits digits.
constexpr double kLargestExponent = 1000;
constexpr double kLargestDigits = 10000;
constexpr std::size_t kLargestOperands = 100000;

void checkPowers(const std::string& field, const PreparedExpression& source, const GiNaC::symtab& symbols, const GiNaC::lst& values) {
    using enum MessageId;
    const std::string& text = source.text;
    struct Power {
        std::size_t at, baseBegin, baseEnd, begin, end;  // the '^' or the call's name; base; exponent
        std::size_t span() const { return end - std::min(at, baseBegin); }
    };
    std::vector<Power> powers;
    for (std::size_t caret = text.find('^'); caret != std::string::npos; caret = text.find('^', caret + 1)) {
        const std::size_t base = operandBegin(text, caret);
        powers.push_back({caret, base == std::string::npos ? caret : base, caret, caret + 1, operandEnd(text, caret + 1)});
    }
    static const std::regex call(R"(\b(pow|power)\s*\()");
    for (auto m = std::sregex_iterator(text.begin(), text.end(), call); m != std::sregex_iterator(); ++m) {
        const std::size_t name = static_cast<std::size_t>(m->position(0));
        const std::size_t open = name + static_cast<std::size_t>(m->length(0)) - 1;
        const std::size_t close = pastClosing(text, open);
        if (close == std::string::npos) continue;  // the parser reports the missing ')'
        int depth = 0;
        for (std::size_t i = open + 1; i + 1 < close; ++i) {
            if (text[i] == '(') ++depth;
            if (text[i] == ')') --depth;
            if (text[i] == ',' && depth == 0) {
                powers.push_back({name, open + 1, i, i + 1, close - 1});
                break;
            }
        }
    }
    std::stable_sort(powers.begin(), powers.end(), [](const Power& a, const Power& b) { return a.span() < b.span(); });
    // Each power's base and exponent are read again on their own: deeply nested powers,
    // 2^(2^(2^…)), would be read over and over (12 KB of them took 1.8 s). Typed
    // expressions, even long ones, have short operands; beyond kLargestOperands characters
    // in all the expression is refused rather than checked for seconds.
    std::size_t operands = 0;
    for (const Power& x : powers) operands += (x.end - x.begin) + (x.baseEnd - x.baseBegin);
    if (operands > kLargestOperands) throw InputError(field, message(PowersNestedTooDeeply, source.quoted(), operands, kLargestOperands));
    // The value of a piece of the text alone, or nothing when it does not read alone (the
    // whole parse reports that) or is not a real number.
    const auto valueOf = [&](std::size_t begin, std::size_t end, bool exact) -> std::optional<GiNaC::numeric> {
        try {
            GiNaC::parser parser(symbols, /*strict=*/true);
            std::istringstream input(text.substr(begin, end - begin));
            GiNaC::ex e = parser(input).subs(values);
            if (!exact) e = e.evalf();
            if (GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_real()) return GiNaC::ex_to<GiNaC::numeric>(e);
        } catch (...) {
        }
        return std::nullopt;
    };
    const auto shown = [](double value) {
        std::ostringstream out;
        out.precision(4);
        out << value;
        return out.str();
    };
    for (const Power& x : powers) {
        const std::optional<GiNaC::numeric> exponent = valueOf(x.begin, x.end, false);
        if (!exponent) continue;
        const double e = exponent->to_double();  // inf when beyond a double
        const Message where = message(text[x.at] == '^' ? PowerAfterCaret : PowerOfPowCall, source.atPosition(x.at + 1), source.quoted());
        if (!(std::abs(e) <= kLargestExponent)) throw InputError(field, message(PowerExponentTooLarge, shown(e), where));
        const std::optional<GiNaC::numeric> base = valueOf(x.baseBegin, x.baseEnd, true);
        if (!base || !base->is_rational()) continue;  // a float (a parameter's value) is raised in floating point
        const double bits = std::max(base->numer().int_length(), base->denom().int_length());
        const double digits = std::abs(e) * bits * std::log10(2.0);
        if (digits > kLargestDigits) throw InputError(field, message(PowerTooManyDigits, where, shown(digits)));
    }
}

// The derivation expands what a user types (E_pot, E_kin, a DH field with symbolic
// parameters): (θ1 + θ2 + 1)^1000 is half a million terms and never finished. The
// number of terms each part would expand to is counted on the tree as GiNaC read it
// (a sum adds, a product multiplies, (k terms)^n gives C(n+k−1, k−1)), every part,
// function arguments too, and an expression beyond kLargestExpansion is refused.
constexpr double kLargestExpansion = 10000;

double expandedTerms(const GiNaC::ex& e, double& largest) {
    double terms = 1;
    if (GiNaC::is_a<GiNaC::add>(e)) {
        terms = 0;
        for (const GiNaC::ex& t : e) terms += expandedTerms(t, largest);
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
        for (const GiNaC::ex& f : e) terms *= expandedTerms(f, largest);
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
        const double k = expandedTerms(e.op(0), largest);
        (void)expandedTerms(e.op(1), largest);
        const GiNaC::ex& n = e.op(1);
        if (k > 1 && GiNaC::is_a<GiNaC::numeric>(n) && GiNaC::ex_to<GiNaC::numeric>(n).is_pos_integer()) {
            const double m = GiNaC::ex_to<GiNaC::numeric>(n).to_double();
            terms = std::exp(std::lgamma(m + k) - std::lgamma(k) - std::lgamma(m + 1));  // C(m+k−1, k−1)
        }
    } else {
        for (std::size_t i = 0; i < e.nops(); ++i) (void)expandedTerms(e.op(i), largest);
    }
    terms = std::min(terms, 1e300);
    largest = std::max(largest, terms);
    return terms;
}

// Quantities here are real: GiNaC's parser reads I as the imaginary unit (a name no
// parameter may take), and sqrt(-1), log(-2) or asin(2) of numbers become complex
// numbers at once. A Lagrangian's field with one could not be compiled ("cannot compile
// the non-real number I", naming no field; found by fuzz_lagrangian: "tau*sin(I)").
void checkReal(const std::string& field, const PreparedExpression& source, const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::numeric>(*it) && !GiNaC::ex_to<GiNaC::numeric>(*it).is_real()) {
            std::ostringstream shown;
            shown << e;
            std::string value = shown.str();
            if (value.size() > 60) value = value.substr(0, 60) + "…";
            throw InputError(field, message(MessageId::ExpressionImaginaryValue, value, source.quoted()));
        }
}

void checkExpansion(const std::string& field, const PreparedExpression& source, const GiNaC::ex& e) {
    double largest = 0;
    (void)expandedTerms(e, largest);
    if (largest <= kLargestExpansion) return;
    std::ostringstream shown;
    shown.precision(3);
    shown << largest;
    throw InputError(field, message(MessageId::ExpressionExpandsTooFar, source.quoted(), shown.str()));
}

// The functions an expression may call: those the simulation compiles
// (core/symbolic/compiled_expressions) and pow. GiNaC's parser knows more, and some of
// them compute exactly and without end on a large argument (factorial(10^8),
// tgamma(10^8), binomial, zeta), so they are refused before GiNaC reads the text.
const std::set<std::string>& availableFunctions() {
    static const std::set<std::string> names{"sin",  "cos",  "tan",  "exp",   "log", "sqrt", "sinh", "cosh", "tanh",
                                             "asin", "acos", "atan", "atan2", "abs", "step", "csgn", "pow",  "power"};
    return names;
}

// Every function GiNaC's parser reads (about 50).
const std::set<std::string>& ginacFunctionNames() {
    static const std::set<std::string> names = [] {
        std::set<std::string> n;
        for (const auto& [prototype, reader] : GiNaC::get_default_reader()) n.insert(prototype.first);
        return n;
    }();
    return names;
}

void checkFunctions(const std::string& field, const PreparedExpression& source) {
    const std::set<std::string>& known = ginacFunctionNames();
    const std::string& text = source.text;
    for (std::size_t i = 0; i < text.size();) {
        if (!std::isalpha(static_cast<unsigned char>(text[i])) || (i > 0 && isIdentifierChar(text[i - 1]))) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < text.size() && isIdentifierChar(text[end])) ++end;
        const std::string name = text.substr(i, end - i);
        const std::size_t next = text.find_first_not_of(" \t\n", end);
        if (next != std::string::npos && text[next] == '(' && known.count(name) && !availableFunctions().count(name))
            throw InputError(field, message(MessageId::ExpressionFunctionNotAvailable, name, source.atPosition(i + 1), source.quoted()));
        i = end;
    }
}

// "division by zero in <quoted>", naming the '/' whose divisor is zero (0: not found).
Message divisionByZero(const PreparedExpression& source, std::size_t divisor) {
    using enum MessageId;
    const Message note = divisor == 0 ? Message() : message(ExpressionZeroDivisor, source.atPosition(divisor));
    return message(ExpressionDivisionByZero, source.quoted(), note);
}

Message describePole(const PreparedExpression& source, const std::string& what, std::size_t divisor = 0) {
    if (what.find("division by zero") != std::string::npos) return divisionByZero(source, divisor);
    return message(MessageId::ExpressionSingularValue, source.quoted(), what);
}

// The constants every expression may use: pi, and deg = π/180 for angles (unless a
// parameter is called deg); "deg_unit_" is what a degree sign becomes (core/io/angle_units).
GiNaC::symtab withConstants(GiNaC::symtab symbols) {
    auto lock = symbolic::lockGinac();
    symbols["pi"] = GiNaC::Pi;
    symbols["deg_unit_"] = GiNaC::Pi / 180;
    if (!symbols.count("deg")) symbols["deg"] = GiNaC::Pi / 180;
    return symbols;
}

const std::set<std::string>& reservedWords() {
    static const std::set<std::string> words = [] {
        std::set<std::string> w{"pi", "Pi", "I", "Euler", "Catalan", "t", "deg_unit_"};
        w.insert(ginacFunctionNames().begin(), ginacFunctionNames().end());
        return w;
    }();
    return words;
}

}  // namespace

std::optional<Message> ParameterTable::whyNotAName(const std::string& name) {
    using enum MessageId;
    static const std::regex identifier("[A-Za-z][A-Za-z0-9_]*");
    static const std::regex jointVariable("q(d|dd)?[0-9]+");
    if (!std::regex_match(name, identifier)) return message(NotAName, name);
    if (std::regex_match(name, jointVariable)) return message(NameReservedForJointCoordinate, name);
    if (reservedWords().count(name)) return message(NameReserved, name);
    return std::nullopt;
}

void ParameterTable::add(const std::string& field, const std::string& name, double value, GiNaC::ex definition) {
    if (auto why = whyNotAName(name)) throw InputError(field, *why);
    if (contains(name)) throw InputError(field, message(MessageId::ParameterDefinedTwice, name));
    // Finite and not subnormal: GiNaC::numeric cannot hold inf, NaN or a subnormal double.
    if (auto why = unusableNumber(value)) throw InputError(field, *why);
    Parameter parameter{GiNaC::symbol(name), value, definition};
    symbols_[name] = parameter.symbol;
    names_.push_back(name);
    parameters_.push_back(std::move(parameter));
}

void ParameterTable::define(const std::string& field, const std::string& name, double value) {
    add(field, name, value, unusableNumber(value) ? GiNaC::ex() : GiNaC::ex(GiNaC::numeric(value)));
}

double ParameterTable::define(const std::string& field, const std::string& name, const std::string& text) {
    const PreparedExpression source = prepare(field, text);
    const GiNaC::ex expression = parse(field, source, {}, false);
    const double value = toNumber(field, source, expression);
    add(field, name, value, expression);
    return value;
}

PreparedExpression ParameterTable::prepare(const std::string& field, const std::string& text) const {
    return prepareExpression(field, text, contains("deg"));
}

GiNaC::ex ParameterTable::parse(const std::string& field, const std::string& text) const {
    return parse(field, prepare(field, text), {}, false);
}

GiNaC::ex ParameterTable::parse(const std::string& field, const std::string& text, const std::vector<GiNaC::symbol>& extra) const {
    return parse(field, prepare(field, text), extra, true);
}

GiNaC::ex ParameterTable::parse(const std::string& field, const PreparedExpression& source, const std::vector<GiNaC::symbol>& extra,
                                bool checkValues) const {
    using enum MessageId;
    if (source.text.find_first_not_of(" \t\n") == std::string::npos) throw InputError(field, ExpressionEmpty);
    GiNaC::symtab symbols = symbols_;
    std::vector<std::string> known;
    for (const GiNaC::symbol& s : extra) {
        symbols[s.get_name()] = s;
        known.push_back(s.get_name());
    }
    known.insert(known.end(), names_.begin(), names_.end());
    symbols = withConstants(symbols);
    checkFunctions(field, source);
    checkPowers(field, source, symbols, values());
    std::istringstream input(source.text);
    try {
        GiNaC::parser parser(symbols, /*strict=*/true);
        const GiNaC::ex expression = parser(input);
        checkExpansion(field, source, expression);
        checkReal(field, source, expression);
        if (checkValues) (void)expression.subs(values());  // throws for x/(k-2) with k = 2
        return expression;
    } catch (const InputError&) {
        throw;  // checkExpansion's and checkReal's, as they are
    } catch (const GiNaC::parse_error& e) {
        input.clear();
        throw InputError(field, describeParseError(source, e.what(), input.tellg()));
    } catch (const GiNaC::pole_error& e) {
        throw InputError(field, describePole(source, e.what(), zeroDivisorPosition(source.text, symbols, values())));
    } catch (const cln::division_by_0_exception&) {
        throw InputError(field, divisionByZero(source, zeroDivisorPosition(source.text, symbols, values())));
    } catch (const cln::read_number_exception&) {
        throw InputError(field, message(ExpressionSyntaxError, Message(), source.quoted(), ExpressionMalformedNumber));
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        if (what.find("find_or_insert_symbol") != std::string::npos)  // strict mode refused a name
            throw InputError(field, describeUnknownSymbol(source, what, known));
        throw InputError(field, message(ExpressionCannotParse, source.quoted(), what));
    } catch (const std::exception& e) {
        throw InputError(field, message(ExpressionCannotParse, source.quoted(), e.what()));
    }
}

double ParameterTable::evaluate(const std::string& field, const std::string& text, AngleUnits units) const {
    const PreparedExpression source = prepare(field, text);
    if (units == AngleUnits::Refused && source.unitPosition != 0) {
        const std::string unit = "'" + source.unit + (source.unit == "deg" ? "'" : "' (U+00B0)");
        throw InputError(field, message(MessageId::DegreesOutsideAngleField, unit, source.unitPosition, source.quoted()),
                         MessageId::AngleFieldsAre);
    }
    return toNumber(field, source, parse(field, source, {}, false));
}

namespace {

Message tooSmall(const PreparedExpression& source) { return message(MessageId::ExpressionUnderflow, source.quoted()); }

}  // namespace

double ParameterTable::toNumber(const std::string& field, const PreparedExpression& source, const GiNaC::ex& expression) const {
    using enum MessageId;
    // Parameter values enter as doubles, so CLN computes in doubles and signals
    // overflow, underflow and 1/0 with exceptions of its own.
    try {
        const GiNaC::ex result = expression.subs(values()).evalf();
        if (!GiNaC::is_a<GiNaC::numeric>(result)) throw InputError(field, message(ExpressionNotANumber, source.quoted()));
        const GiNaC::numeric& number = GiNaC::ex_to<GiNaC::numeric>(result);
        if (!number.is_real()) {
            std::ostringstream shown;
            shown << result;
            throw InputError(field, message(ExpressionNotReal, shown.str(), source.quoted()));
        }
        // Exact numbers beyond the double range would make to_double throw; floats give inf.
        if (GiNaC::abs(number) > GiNaC::numeric(std::numeric_limits<double>::max()))
            throw InputError(field,
                             message(ProblemInExpression, message(ValueNotFinite, number.is_negative() ? "-inf" : "inf"), source.quoted()));
        const double value = number.to_double();
        if (auto why = unusableNumber(value)) throw InputError(field, message(ProblemInExpression, *why, source.quoted()));
        // A typed number below the normal range is refused (CLN reads "1e-310" exactly, to_double
        // gives 0); a computed one underflows to 0 as in C++ ("tiny*tiny").
        if (value == 0.0 && !number.is_zero() && GiNaC::is_a<GiNaC::numeric>(expression)) throw InputError(field, tooSmall(source));
        return value;
    } catch (const InputError&) {
        throw;
    } catch (const GiNaC::pole_error& e) {
        throw InputError(field, describePole(source, e.what(), zeroDivisorPosition(source.text, withConstants(symbols_), values())));
    } catch (const cln::division_by_0_exception&) {
        throw InputError(field, divisionByZero(source, zeroDivisorPosition(source.text, withConstants(symbols_), values())));
    } catch (const cln::floating_point_overflow_exception&) {
        throw InputError(field, message(ExpressionOverflow, source.quoted()));
    } catch (const cln::floating_point_underflow_exception&) {
        throw InputError(field, tooSmall(source));
    } catch (const std::exception& e) {
        throw InputError(field, message(ExpressionCannotEvaluate, source.quoted(), e.what()));
    }
}

bool ParameterTable::contains(const std::string& name) const { return symbols_.count(name) != 0; }

const ParameterTable::Parameter& ParameterTable::find(const std::string& name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
        if (names_[i] == name) return parameters_[i];
    throw std::out_of_range("no parameter named '" + name + "'");
}

const GiNaC::symbol& ParameterTable::symbol(const std::string& name) const { return find(name).symbol; }

double ParameterTable::value(const std::string& name) const { return find(name).value; }

const GiNaC::ex& ParameterTable::definition(const std::string& name) const { return find(name).definition; }

GiNaC::lst ParameterTable::values() const {
    GiNaC::lst substitutions;
    for (const Parameter& p : parameters_) substitutions.append(p.symbol == GiNaC::numeric(p.value));
    return substitutions;
}

ParameterTable parameterTable(const Scene& scene) {
    ParameterTable table;
    for (const auto& [name, value] : scene.parameters) {
        const std::string field = "parameters." + name;
        const auto text = scene.expressions.find(field);
        if (text != scene.expressions.end()) table.define(field, name, text->second);
        else table.define(field, name, value);
    }
    return table;
}

}  // namespace ll
