#include "core/model/diagnostics.hpp"

#include <algorithm>

namespace ll {

std::string Diagnostic::toString() const {
    return std::string(severity == Severity::Error ? "error: " : "warning: ") + field + ": " + message;
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

static std::string joinErrors(const std::vector<Diagnostic>& diagnostics) {
    std::string text;
    for (const Diagnostic& d : diagnostics) {
        if (d.severity != Severity::Error) continue;
        if (!text.empty()) text += "\n";
        text += d.field + ": " + d.message;
    }
    return text;
}

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(joinErrors(diagnostics)), diagnostics_(std::move(diagnostics)) {}

InputError::InputError(std::string field, std::string message)
    : InputError(std::vector<Diagnostic>{{Severity::Error, std::move(field), std::move(message)}}) {}

std::string jointField(int jointIndex0, const std::string& field) {
    return "robot.joints[" + std::to_string(jointIndex0 + 1) + "]" + (field.empty() ? "" : "." + field);
}

}  // namespace ll
