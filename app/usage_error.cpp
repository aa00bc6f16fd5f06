#include "app/usage_error.hpp"

#include "core/model/message.hpp"
#include "core/present/message_text.hpp"

namespace ll::cli {

UsageError::UsageError(UsageMessage message)
    : std::runtime_error(usageText(message, present::Language::English)), message_(std::move(message)) {}

UsageError::UsageError(const std::string& words) : UsageError(usageMessage(UsageId::Literal, words)) {}

UsageError::UsageError(const Message& words) : UsageError(usageMessage(UsageId::Literal, words)) {}

std::string usageErrorLine(const UsageMessage& message, present::Language language) {
    // The core's "error: "/"fejl: ", so a usage error begins as a scene's errors do.
    return present::messageText(MessageId::ErrorLine, language) + usageText(message, language);
}

}  // namespace ll::cli
