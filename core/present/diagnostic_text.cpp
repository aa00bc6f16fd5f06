#include "core/present/diagnostic_text.hpp"

#include "core/present/message_text.hpp"

namespace ll::present {

std::string diagnosticText(const Diagnostic& d, Language language, Place place) {
    using enum MessageId;
    const Message severity = d.severity == Severity::Error ? ErrorLine : WarningLine;
    std::string text = messageText(severity, language) +
                       (place == Place::Named ? messageText(d.place(), language) + ": " : std::string()) +
                       messageText(d.message, language);
    if (!d.hint.empty()) text += "\n" + messageText(HintLine, language) + messageText(d.hint, language);
    return text;
}

}  // namespace ll::present
