#pragma once
// A message (core/model/message.hpp) in words, in a language: the id's words from that
// language's catalogue (English: core/model/messages/*.def, Danish:
// core/present/danish/*.def) with its arguments, each in the same language, filled in.
#include <string>

#include "core/model/message.hpp"
#include "core/present/language.hpp"

namespace ll::present {

std::string messageText(const Message& message, Language language);

// The same in LaTeX's text mode: the id's words escaped as latex_text.hpp escapes them,
// each literal argument put in as it is (LaTeX already: math such as "$q_{2}$", a range
// "4--7", or words the caller escaped), each message argument worded the same way.
std::string latexMessageText(const Message& message, Language language);

// The Danish words of an id, nullptr when the catalogue has none (the test of the
// catalogue fails then; the reader meets the English words).
const char* danishWords(MessageId id);

// The words of an id in a language, {1}, {2}, … where its arguments go (the English
// where the language has none).
const char* wordsOf(MessageId id, Language language);

}  // namespace ll::present
