#include "core/present/json_writer.hpp"

#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace ll::present {
namespace {

// The length of the UTF-8 sequence at s[i] (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF), or 0 when it is not one.
std::size_t utf8Length(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
    const unsigned b0 = byte(i);
    const auto continuation = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) {
        const unsigned b = byte(k);  // 0 past the end: not a continuation byte
        return b >= lo && b <= hi;
    };
    if (b0 >= 0xC2 && b0 <= 0xDF) return continuation(i + 1) ? 2 : 0;
    if (b0 >= 0xE0 && b0 <= 0xEF) {
        const unsigned lo = b0 == 0xE0 ? 0xA0 : 0x80, hi = b0 == 0xED ? 0x9F : 0xBF;
        return continuation(i + 1, lo, hi) && continuation(i + 2) ? 3 : 0;
    }
    if (b0 >= 0xF0 && b0 <= 0xF4) {
        const unsigned lo = b0 == 0xF0 ? 0x90 : 0x80, hi = b0 == 0xF4 ? 0x8F : 0xBF;
        return continuation(i + 1, lo, hi) && continuation(i + 2) && continuation(i + 3) ? 4 : 0;
    }
    return 0;
}

}  // namespace

void JsonWriter::newline() {
    if (compact_) return;
    out_ += '\n';
    out_.append(2 * levels_.size(), ' ');
}

void JsonWriter::beforeValue() {
    if (afterKey_) {
        afterKey_ = false;
        return;
    }
    if (levels_.empty()) {
        if (started_) throw std::logic_error("JsonWriter: a second value at the top level");
        started_ = true;
        return;
    }
    Level& top = levels_.back();
    if (top.object) throw std::logic_error("JsonWriter: a value in an object without its key");
    if (!top.empty) out_ += ',';
    top.empty = false;
    newline();
}

void JsonWriter::key(std::string_view name) {
    if (levels_.empty() || !levels_.back().object || afterKey_)
        throw std::logic_error("JsonWriter: a key outside an object, or two keys in a row");
    Level& top = levels_.back();
    if (!top.empty) out_ += ',';
    top.empty = false;
    newline();
    quote(name, out_);
    out_ += compact_ ? ":" : ": ";
    afterKey_ = true;
}

void JsonWriter::open(char bracket, bool object) {
    beforeValue();
    out_ += bracket;
    levels_.push_back({object});
}

void JsonWriter::close(char bracket) {
    if (levels_.empty() || levels_.back().object != (bracket == '}') || afterKey_)
        throw std::logic_error("JsonWriter: closing what is not open");
    const bool empty = levels_.back().empty;
    levels_.pop_back();
    if (!empty) newline();
    out_ += bracket;
}

void JsonWriter::quote(std::string_view s, std::string& out) {
    out += '"';
    std::size_t run = 0;  // start of the bytes not yet written
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 && c != '"' && c != '\\' && c < 0x80) {
            ++i;
            continue;
        }
        if (c >= 0x80) {
            const std::size_t n = utf8Length(s, i);
            if (n == 0) {
                char hex[8];
                std::snprintf(hex, sizeof hex, "%02X", c);
                throw std::invalid_argument("JSON output: invalid UTF-8 byte 0x" + std::string(hex) + " at byte " + std::to_string(i) +
                                            " of a string");
            }
            i += n;
            continue;
        }
        out.append(s.data() + run, i - run);
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\b': out += "\\b"; break;
            case '\t': out += "\\t"; break;
            case '\n': out += "\\n"; break;
            case '\f': out += "\\f"; break;
            case '\r': out += "\\r"; break;
            default: {
                char escaped[8];
                std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
                out += escaped;
            }
        }
        run = ++i;
    }
    out.append(s.data() + run, s.size() - run);
    out += '"';
}

void JsonWriter::value(std::string_view s) {
    beforeValue();
    quote(s, out_);
}

void JsonWriter::value(long long n) {
    beforeValue();
    out_ += std::to_string(n);
}

void JsonWriter::value(double x) {
    beforeValue();
    out_ += nlohmann::json(x).dump();  // its shortest round-trip form, and null for NaN
}

void JsonWriter::value(bool b) {
    beforeValue();
    out_ += b ? "true" : "false";
}

void JsonWriter::value(const std::vector<std::string>& strings) {
    beginArray();
    for (const std::string& s : strings) value(std::string_view(s));
    endArray();
}

}  // namespace ll::present
