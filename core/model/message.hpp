#pragma once
// A message is data: an id and its arguments (a field, a joint, a value with its unit, a
// limit), turned into words only where a reader sees it, in the reader's language
// (core/present/message_text.hpp). The English words of every id are its entry in
// core/model/messages/*.def, the Danish ones in core/present/danish/*.def; a test fails
// when an id lacks Danish (tests/core/test_message_catalogue.cpp).
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace ll {

enum class MessageId : unsigned short {
    Literal,       // no words of ours: the text as it came (a number, a name, a system's or parser's own words)
#ifndef Q_MOC_RUN  // Qt's moc, which reads headers including this one, cannot parse the list
#define LL_MESSAGE(id, english) id,
#include "core/model/messages/all.def"
#undef LL_MESSAGE
#endif
    Count
};

struct Message {
    MessageId id = MessageId::Literal;
    std::string literal;        // the text itself when id is Literal
    std::vector<Message> args;  // fill {1}, {2}, ... of the id's words

    Message() = default;
    Message(MessageId id_, std::vector<Message> args_ = {}) : id(id_), args(std::move(args_)) {}

    bool empty() const { return id == MessageId::Literal && literal.empty(); }
    std::string english() const;  // the words in English (what() of an exception, the CLI in English)
};

// Text that is not ours to translate: a value, a name, a path, a library's own words.
Message literal(std::string text);

namespace detail {
inline Message messageArg(Message m) { return m; }
inline Message messageArg(std::string s) { return literal(std::move(s)); }
inline Message messageArg(const char* s) { return literal(s); }
std::string formatArgument(double value);
template <class T, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
Message messageArg(T value) {
    if constexpr (std::is_floating_point_v<T>) return literal(formatArgument(value));
    else return literal(std::to_string(value));
}
}  // namespace detail

// message(MessageId::MassNegative, formatValue(m)): the id with its arguments in order;
// a string is a literal, an integer is written as is, a double as formatValue writes it.
template <class... A>
Message message(MessageId id, A&&... args) {
    return Message(id, {detail::messageArg(std::forward<A>(args))...});
}

// The English words of an id, with {1}, {2}, ... where its arguments go.
const char* englishWords(MessageId id);
// The name of an id as the .def files spell it ("MassNegative").
const char* messageIdName(MessageId id);

// The placeholders {1}..{9} that `words` uses (1..9): a language's words for an id must
// take the same arguments as the English.
std::set<int> placeholders(const std::string& words);

// `words` with each {k} replaced by args[k-1] (k = 1..9); other braces stay as they are.
std::string filledIn(const std::string& words, const std::vector<std::string>& args);

}  // namespace ll
