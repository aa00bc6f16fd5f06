#include "core/present/diagnostic_text.hpp"

#include "core/model/message_error.hpp"
#include "core/present/message_text.hpp"

namespace ll::present {

namespace {

std::string words(const Diagnostic& d, Language language, Place place) {
    std::string text = (place == Place::Named ? messageText(d.place(), language) + ": " : std::string()) + messageText(d.message, language);
    if (!d.hint.empty()) text += "\n" + messageText(MessageId::HintLine, language) + messageText(d.hint, language);
    return text;
}

}  // namespace

std::string diagnosticText(const Diagnostic& d, Language language, Place place) {
    const MessageId severity = d.severity == Severity::Error ? MessageId::ErrorLine : MessageId::WarningLine;
    return messageText(severity, language) + words(d, language, place);
}

std::string diagnosticBody(const Diagnostic& d, Language language) { return words(d, language, Place::Named); }

std::string errorText(const std::exception& error, Language language) {
    if (const auto* input = dynamic_cast<const InputError*>(&error)) {
        std::string text;
        for (const Diagnostic& d : input->diagnostics())
            if (d.severity == Severity::Error) text += (text.empty() ? "" : "\n") + diagnosticBody(d, language);
        return text;
    }
    if (const auto* ours = dynamic_cast<const MessageError*>(&error)) return messageText(ours->message(), language);
    return error.what();
}

}  // namespace ll::present
