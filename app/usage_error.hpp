#pragma once
// Bad command-line input: exit code 2 and one `error:` line (app/main.cpp), in the
// language the reader asked for (--lang, else the environment).
#include <stdexcept>
#include <string>
#include <utility>

#include "app/usage_message.hpp"
#include "core/present/language.hpp"

namespace ll::cli {

class UsageError : public std::runtime_error {
public:
    // what() is the English text, as scripts and tests read it; message() the data.
    explicit UsageError(UsageMessage message);
    // throw UsageError(UsageId::OptionNeedsValue, name): usageMessage's arguments.
    template <class... A>
    explicit UsageError(UsageId id, A&&... args) : UsageError(usageMessage(id, std::forward<A>(args)...)) {}
    // Words not ours to translate (UsageId::Literal): a library's own English, and the
    // benchmark's messages (app/bench, a developer's tool in English only).
    explicit UsageError(const std::string& words);
    // The core's message as it is, in the reader's language (a MessageError's).
    explicit UsageError(const Message& words);

    const UsageMessage& message() const { return message_; }

private:
    UsageMessage message_;
};

// "error: " and the message in `language` ("fejl: " in Danish, as the core's errors
// begin): the line the program prints for a usage error, without its newline.
std::string usageErrorLine(const UsageMessage& message, present::Language language);

}  // namespace ll::cli
