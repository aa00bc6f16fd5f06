#pragma once
// Messages that quote what a user typed must be valid UTF-8 and must quote whole
// characters: a terminal or a window shows a cut multi-byte character as '�'. These
// helpers decode UTF-8, name a character with its code point ('°' (U+00B0)) and make
// any text safe to print (a byte that is not UTF-8 is shown as the escape \xC2).
#include <cstddef>
#include <string>
#include <string_view>

namespace ll {

// One character of UTF-8 text at a byte offset.
struct Utf8Char {
    char32_t codePoint = 0;  // valid only when `valid`
    std::size_t bytes = 1;   // the sequence's length; 1 for an invalid byte
    bool valid = false;      // false: a stray, overlong, surrogate or truncated sequence
};

// The character starting at `offset` (< text.size()).
Utf8Char decodeUtf8(std::string_view text, std::size_t offset);

bool isValidUtf8(std::string_view text);

// `text` with every byte that is not part of a valid UTF-8 sequence replaced by the
// four ASCII characters \xNN; valid text is returned unchanged.
std::string validUtf8(std::string_view text);

// The character encoded as UTF-8.
std::string encodeUtf8(char32_t codePoint);

// "'°' (U+00B0)"; control characters are not shown, only their code point
// ("U+0009"); a byte that is not UTF-8 is named as "byte 0xC2".
std::string describeCharacter(const Utf8Char& c, std::string_view text, std::size_t offset);

// Number of characters (code points; an invalid byte counts as one) in the first
// `bytes` bytes of `text`: turns a byte offset into the position a user counts.
std::size_t characterCount(std::string_view text, std::size_t bytes);

}  // namespace ll
