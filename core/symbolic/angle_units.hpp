#pragma once
// Angles as people copy them from textbooks and datasheets: "90°", "90 deg", "90deg",
// "45*deg + 0.1", or radians ("-pi/2", 1.5708). In an expression `deg` is the constant
// π/180 (unless a parameter is called deg), and a degree sign or a `deg` written right
// after a number or a ')' multiplies it, so "90°" = "90 deg" = "90*deg" = pi/2 exactly.
//
// Before GiNaC reads an expression, prepareExpression checks its characters: the text
// must be UTF-8 and ASCII apart from the degree sign, so a message never quotes half
// a character; anything else is refused naming the character with its code point
// ("'×' (U+00D7) at position 3", with a hint for look-alikes such as − × · π ² º).
#include <cstddef>
#include <string>
#include <vector>

#include "core/model/message.hpp"

namespace ll {

// An expression rewritten for GiNaC's parser, with the way back to what was typed.
struct PreparedExpression {
    std::string original;  // as typed
    std::string text;      // ASCII for GiNaC: '°' -> "*deg_unit_ ", "90 deg" -> "90 *deg"
    // position[b]: the 1-based character position in `original` of byte b of `text`;
    // one entry more than `text` has bytes (the end).
    std::vector<std::size_t> position;
    // 1-based character position of the first degree sign or `deg` unit, 0 if none.
    std::size_t unitPosition = 0;
    std::string unit;  // "°" or "deg" as written there

    // " at position N" for a 1-based byte position in `text`, N counted in characters of
    // `original` (0: an empty message); at() is the same in English.
    Message atPosition(std::size_t bytePosition) const;
    std::string at(std::size_t bytePosition) const { return atPosition(bytePosition).english(); }
    // The original text in double quotes.
    std::string quoted() const;
};

// Throws InputError naming `field` for a byte that is not UTF-8 or a character that is
// neither ASCII nor the degree sign. `degIsParameter`: a parameter named deg exists, so
// `deg` is that parameter and not a unit.
PreparedExpression prepareExpression(const std::string& field, const std::string& text, bool degIsParameter);

// How to write `radians` the way the user probably meant it, for the warning about a
// bare number in an angle field: 90 -> {"90°", "pi/2"}; 37 -> {"37°", "37*pi/180"}.
struct DegreeReading {
    std::string degrees;  // the number as degrees: "90°"
    std::string radians;  // the same angle in radians with pi: "pi/2"
};
DegreeReading readAsDegrees(double value);

}  // namespace ll
