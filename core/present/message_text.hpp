#pragma once
// A message (core/model/message.hpp) in words, in a language: the id's words from that
// language's catalogue (English: core/model/messages/*.def, Danish:
// core/present/danish/*.def) with its arguments, each in the same language, filled in.
#include <string>

#include "core/model/message.hpp"
#include "core/present/language.hpp"

namespace ll::present {

std::string messageText(const Message& message, Language language);

// The Danish words of an id, nullptr when the catalogue has none (the test of the
// catalogue fails then; the reader meets the English words).
const char* danishWords(MessageId id);

// The words of an id in a language, {1}, {2}, … where its arguments go (the English
// where the language has none).
const char* wordsOf(MessageId id, Language language);

}  // namespace ll::present
