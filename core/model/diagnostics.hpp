#pragma once
// Problems found in user input, each naming the field and the value.
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/message.hpp"

namespace ll {

enum class Severity { Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string field;  // a path as JSON counts it: "robot.joints[0].mass" is the first joint's
    Message message;    // says the value and what is wrong with it: one short line
    Message hint = {};  // why, and what to do about it (printed on a following `hint:` line)

    // The field with its joint in words, as the table names it: "robot.joints[0].mass (joint 1)".
    std::string where() const;  // place() in English
    Message place() const;
    std::string text() const;      // "robot.joints[0].mass (joint 1): ..." (and "\nhint: ..."), in English
    std::string toString() const;  // "error: " or "warning: ", then text()
};

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

// Thrown for bad input; carries the diagnostics (at least one error). Fields and
// messages are made valid UTF-8 (core/model/utf8_text.hpp), so printing them never
// shows half a character, whatever bytes the input held.
class InputError : public std::runtime_error {
public:
    explicit InputError(std::vector<Diagnostic> diagnostics);
    InputError(std::string field, Message message, Message hint = {});
    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

private:
    std::vector<Diagnostic> diagnostics_;
};

// Field path of a joint's field, counted from 0 as JSON (and jq, and Python) count:
// jointField(1, "mass") == "robot.joints[1].mass", the second joint ("joint 2" in words).
std::string jointField(int jointIndex0, const std::string& field);

// A value as diagnostics quote it: 6 significant digits ("0.4318", "1e+300").
std::string formatValue(double value);

}  // namespace ll
