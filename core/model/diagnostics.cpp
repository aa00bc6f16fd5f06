#include "core/model/diagnostics.hpp"

#include <sstream>

#include <algorithm>

#include "core/model/utf8_text.hpp"

namespace ll {

Message Diagnostic::place() const {
    static const std::string joints = "robot.joints[";
    const std::size_t at = field.find(joints);
    if (at == std::string::npos) return literal(field);
    const std::size_t start = at + joints.size(), end = field.find(']', start);
    if (end == std::string::npos || end == start || field.find_first_not_of("0123456789", start) != end) return literal(field);
    return ll::message(MessageId::FieldOfJoint, field, std::stol(field.substr(start, end - start)) + 1);
}

std::string Diagnostic::where() const { return place().english(); }

std::string Diagnostic::text() const {
    return where() + ": " + message.english() + (hint.empty() ? "" : "\n" + Message(MessageId::HintLine).english() + hint.english());
}

std::string Diagnostic::toString() const {
    return Message(severity == Severity::Error ? MessageId::ErrorLine : MessageId::WarningLine).english() + text();
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

static std::string joinErrors(const std::vector<Diagnostic>& diagnostics) {
    std::string text;
    for (const Diagnostic& d : diagnostics) {
        if (d.severity != Severity::Error) continue;
        if (!text.empty()) text += "\n";
        text += d.text();
    }
    return text;
}

static void makePrintable(Message& m) {
    if (!isValidUtf8(m.literal)) m.literal = validUtf8(m.literal);
    for (Message& a : m.args) makePrintable(a);
}

// Messages quote what the user typed; whatever it held, they are printed as valid UTF-8.
static std::vector<Diagnostic> printable(std::vector<Diagnostic> diagnostics) {
    for (Diagnostic& d : diagnostics) {
        if (!isValidUtf8(d.field)) d.field = validUtf8(d.field);
        makePrintable(d.message);
        makePrintable(d.hint);
    }
    return diagnostics;
}

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(joinErrors(printable(diagnostics))), diagnostics_(printable(std::move(diagnostics))) {}

InputError::InputError(std::string field, Message message, Message hint)
    : InputError(std::vector<Diagnostic>{{Severity::Error, std::move(field), std::move(message), std::move(hint)}}) {}

std::string jointField(int jointIndex0, const std::string& field) {
    return "robot.joints[" + std::to_string(jointIndex0) + "]" + (field.empty() ? "" : "." + field);
}

std::string formatValue(double value) {
    std::ostringstream s;
    s.precision(6);
    s << value;
    return s.str();
}

}  // namespace ll
