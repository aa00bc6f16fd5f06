#pragma once
// Problems found in user input, each naming the field and the value.
#include <stdexcept>
#include <string>
#include <vector>

namespace ll {

enum class Severity { Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string field;    // e.g. "robot.joints[2].mass" (joints numbered from 1)
    std::string message;  // says the value and what is wrong with it

    std::string toString() const;  // "error: robot.joints[2].mass: ..."
};

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

// Thrown for bad input; carries the diagnostics (at least one error). Fields and
// messages are made valid UTF-8 (core/model/utf8_text.hpp), so printing them never
// shows half a character, whatever bytes the input held.
class InputError : public std::runtime_error {
public:
    explicit InputError(std::vector<Diagnostic> diagnostics);
    InputError(std::string field, std::string message);
    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

private:
    std::vector<Diagnostic> diagnostics_;
};

// Field path of a joint's field, 1-based as in the textbook: jointField(1, "mass")
// == "robot.joints[2].mass".
std::string jointField(int jointIndex0, const std::string& field);

// A value as diagnostics quote it: 6 significant digits ("0.4318", "1e+300").
std::string formatValue(double value);

}  // namespace ll
