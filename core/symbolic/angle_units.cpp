#include "core/symbolic/angle_units.hpp"

#include <cctype>
#include <cmath>
#include <sstream>

#include "core/model/diagnostics.hpp"
#include "core/model/utf8_text.hpp"

namespace ll {

namespace {

// The degree sign becomes a product with a reserved name (core/io/expression.cpp); the
// space ends the name, so "90°2" is a syntax error, not a symbol.
const char* const kDegreeProduct = "*deg_unit_ ";

// What to write instead of a character people paste from documents.
Message lookAlikeHint(char32_t c) {
    using enum MessageId;
    switch (c) {
        case 0x2212:
        case 0x2013:
        case 0x2014: return WriteAsciiMinus;
        case 0x00D7:
        case 0x00B7:
        case 0x22C5:
        case 0x2219: return WriteStarForProduct;
        case 0x00F7:
        case 0x2215: return WriteSlashForQuotient;
        case 0x03C0: return WritePi;
        case 0x00B2: return WriteSquare;
        case 0x00B3: return WriteCube;
        case 0x00BA:
        case 0x02DA:
        case 0x2218: return NotTheDegreeSign;
        case 0x00A0:
        case 0x2009:
        case 0x202F: return WritePlainSpace;
        case 0x2032: return NoMinutesOfArc;
        case 0x00B5:
        case 0x03BC: return WriteSiUnits;
        default: return ExpressionsAreAscii;
    }
}

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Length of the number starting at `i` (digits, '.', an exponent e±digits).
std::size_t numberLength(const std::string& s, std::size_t i) {
    std::size_t j = i;
    while (j < s.size() && (isDigit(s[j]) || s[j] == '.')) ++j;
    if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
        std::size_t k = j + 1;
        if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
        if (k < s.size() && isDigit(s[k])) {
            while (k < s.size() && isDigit(s[k])) ++k;
            j = k;
        }
    }
    return j - i;
}

std::string shortNumber(double value) {
    std::ostringstream out;
    out.precision(10);
    out << value;
    return out.str();
}

}  // namespace

Message PreparedExpression::atPosition(std::size_t bytePosition) const {
    if (bytePosition == 0 || position.empty()) return {};
    const std::size_t index = std::min(bytePosition - 1, position.size() - 1);
    return message(MessageId::ExpressionAtPosition, position[index]);
}

std::string PreparedExpression::quoted() const {
    std::string text(1, '"');
    return text.append(validUtf8(original)).append(1, '"');
}

PreparedExpression prepareExpression(const std::string& field, const std::string& text, bool degIsParameter) {
    PreparedExpression p;
    p.original = text;
    // 1. Characters: ASCII is kept, the degree sign becomes a product, the rest is refused.
    std::string ascii;
    std::vector<std::size_t> asciiPosition;
    std::size_t character = 0;
    for (std::size_t i = 0; i < text.size();) {
        ++character;
        const Utf8Char c = decodeUtf8(text, i);
        if (c.valid && c.codePoint < 0x80) {
            ascii += text[i];
            asciiPosition.push_back(character);
        } else if (c.valid && c.codePoint == 0xB0) {
            for (const char* k = kDegreeProduct; *k; ++k) {
                ascii += *k;
                asciiPosition.push_back(character);
            }
            if (p.unitPosition == 0) p.unitPosition = character, p.unit = "°";
        } else {
            const std::string shown = describeCharacter(c, text, i);
            if (!c.valid) throw InputError(field, message(MessageId::ExpressionNotUtf8, shown, character, p.quoted()));
            throw InputError(field, message(MessageId::UnexpectedCharacter, shown, character, p.quoted(), lookAlikeHint(c.codePoint)));
        }
        i += c.bytes;
    }
    asciiPosition.push_back(character + 1);

    // 2. `deg` right after a number, a name or ')' multiplies it: "90 deg" -> "90 *deg".
    bool afterOperand = false;
    for (std::size_t i = 0; i < ascii.size();) {
        const char c = ascii[i];
        std::size_t length = 1;
        bool operand = false;
        if (isDigit(c) || (c == '.' && i + 1 < ascii.size() && isDigit(ascii[i + 1]))) {
            length = numberLength(ascii, i);
            operand = true;
            // An exponent far beyond a double's (±308): CLN would compute 10^55555555555
            // exactly, for minutes and gigabytes (found by fuzz_expression: "4e5555555…").
            const std::string literal = ascii.substr(i, length);
            const std::size_t e = literal.find_first_of("eE");
            if (e != std::string::npos) {
                std::size_t k = e + 1 + (literal[e + 1] == '+' || literal[e + 1] == '-');
                while (k + 1 < literal.size() && literal[k] == '0') ++k;
                if (literal.size() - k > 3 || std::stoi(literal.substr(k)) > 400)
                    throw InputError(field, message(MessageId::NumberExponentTooLarge,
                                                    validUtf8(literal.size() > 24 ? literal.substr(0, 24) + "…" : literal),
                                                    asciiPosition[i], p.quoted()));
            }
        } else if (isNameStart(c)) {
            while (i + length < ascii.size() && isNameChar(ascii[i + length])) ++length;
            operand = true;
            if (!degIsParameter && ascii.compare(i, length, "deg") == 0) {
                if (p.unitPosition == 0 || asciiPosition[i] < p.unitPosition) p.unitPosition = asciiPosition[i], p.unit = "deg";
                if (afterOperand) {
                    p.text += '*';
                    p.position.push_back(asciiPosition[i]);
                }
            }
        } else if (c == ')') {
            operand = true;
        } else if (c == ' ' || c == '\t' || c == '\n') {
            operand = afterOperand;
        }
        p.text.append(ascii, i, length);
        p.position.insert(p.position.end(), asciiPosition.begin() + i, asciiPosition.begin() + i + length);
        afterOperand = operand;
        i += length;
    }
    p.position.push_back(asciiPosition.back());

    // 3. A function called with nothing between its brackets, "sin()": GiNaC's parser
    //    builds the call without an argument and crashes evaluating it (found by
    //    fuzz_expression and fuzz_lagrangian), so it is refused here, before GiNaC.
    for (std::size_t open = p.text.find('('); open != std::string::npos; open = p.text.find('(', open + 1)) {
        const std::size_t close = p.text.find_first_not_of(" \t\n", open + 1);
        if (close == std::string::npos || p.text[close] != ')') continue;
        std::size_t start = open;
        while (start > 0 && (p.text[start - 1] == ' ' || p.text[start - 1] == '\t' || p.text[start - 1] == '\n')) --start;
        std::size_t nameStart = start;
        while (nameStart > 0 && isNameChar(p.text[nameStart - 1])) --nameStart;
        while (nameStart < start && !isNameStart(p.text[nameStart])) ++nameStart;  // "2sin()": the name is "sin"
        if (nameStart == start) continue;                                          // "()" alone: GiNaC reports it
        const std::string name = p.text.substr(nameStart, start - nameStart);
        throw InputError(field, message(MessageId::CallWithoutArgument, name, p.atPosition(nameStart + 1), p.quoted()));
    }
    return p;
}

DegreeReading readAsDegrees(double value) {
    DegreeReading reading{shortNumber(value) + "°", ""};
    for (int q = 1; q <= 12; ++q) {
        const double p = value * q / 180.0;
        if (!(std::abs(p) < 1e15)) break;  // no exact multiple of pi to offer (and lround would overflow)
        if (std::abs(p - std::round(p)) > 1e-9) continue;
        const long numerator = std::lround(p);
        if (numerator == 0) {
            reading.radians.assign(1, '0');
        } else {
            std::string text = numerator == 1 ? "pi" : numerator == -1 ? "-pi" : std::to_string(numerator) + "*pi";
            if (q > 1) text.append("/").append(std::to_string(q));
            reading.radians = text;
        }
        return reading;
    }
    reading.radians = shortNumber(value) + "*pi/180";
    return reading;
}

}  // namespace ll
