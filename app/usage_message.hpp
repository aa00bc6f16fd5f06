#pragma once
// A usage error of the command line as data: an id and its arguments (an option's name,
// the value as typed, the allowed values, a count, a path, the core's message that
// refused a value), turned into words only when printed, in the reader's language
// (--lang, else the environment). The program's own catalogue, beside the core's
// (core/model/message.hpp): the core knows nothing of command-line options. English
// words: app/usage_messages.def, Danish: app/usage_messages_da.def;
// tests/app/test_usage_messages.cpp fails when an id lacks Danish.
#include <concepts>
#include <string>
#include <utility>
#include <vector>

#include "core/model/message.hpp"
#include "core/present/language.hpp"

namespace ll::cli {

enum class UsageId : unsigned short {
    Literal,       // words that are not ours to translate: the core's own English, the benchmark's
#ifndef Q_MOC_RUN  // Qt's moc, which reads the headers a test includes, cannot parse the list
#define LL_USAGE(id, english) id,
#include "app/usage_messages.def"
#undef LL_USAGE
#endif
    Count
};

struct UsageMessage {
    UsageId id = UsageId::Literal;
    // Fill {1}, {2}, ... of the id's words, each in the same language (core/model/message.hpp:
    // a string is a literal); Literal: {1} is the text.
    std::vector<Message> args;
};

namespace detail {
inline Message usageArg(std::string text) { return literal(std::move(text)); }
inline Message usageArg(Message message) { return message; }
template <std::integral T>
Message usageArg(T count) {
    return literal(std::to_string(count));
}
}  // namespace detail

// usageMessage(UsageId::OptionNeedsValue, "out"): the id with its arguments in order, a
// string as it is, a whole number in digits, a core Message in the reader's language. A
// double is given as the site writes it (std::to_string, formatValue): its digits are the
// site's choice.
template <class... A>
UsageMessage usageMessage(UsageId id, A&&... args) {
    return {id, {detail::usageArg(std::forward<A>(args))...}};
}

// The words of an id with {1}, {2}, ... where its arguments go; danishWords is nullptr
// when the Danish catalogue lacks the id (the reader then meets the English words).
const char* englishWords(UsageId id);
const char* danishWords(UsageId id);
// The id's name as the .def files spell it ("OptionNeedsValue").
const char* usageIdName(UsageId id);

// The message in words in `language`.
std::string usageText(const UsageMessage& message, present::Language language);

}  // namespace ll::cli
