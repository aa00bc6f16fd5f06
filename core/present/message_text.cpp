#include "core/present/message_text.hpp"

#include <array>
#include <cstddef>

#include "core/present/latex_text.hpp"

namespace ll::present {
namespace {

using Catalogue = std::array<const char*, static_cast<std::size_t>(MessageId::Count)>;

Catalogue danishCatalogue() {
    Catalogue words{};
    words[static_cast<std::size_t>(MessageId::Literal)] = "{1}";
#define LL_DANISH(id, danish) words[static_cast<std::size_t>(MessageId::id)] = danish;
#include "core/present/danish/all.def"
#undef LL_DANISH
    return words;
}

}  // namespace

const char* danishWords(MessageId id) {
    static const Catalogue catalogue = danishCatalogue();
    const auto k = static_cast<std::size_t>(id);
    return k < catalogue.size() ? catalogue[k] : nullptr;
}

const char* wordsOf(MessageId id, Language language) {
    const char* words = language == Language::Danish ? danishWords(id) : nullptr;
    return words ? words : englishWords(id);
}

std::string messageText(const Message& message, Language language) {
    if (message.id == MessageId::Literal) return message.literal;
    std::vector<std::string> args;
    args.reserve(message.args.size());
    for (const Message& a : message.args) args.push_back(messageText(a, language));
    return filledIn(wordsOf(message.id, language), args);
}

std::string latexMessageText(const Message& message, Language language) {
    if (message.id == MessageId::Literal) return message.literal;
    const std::string words = wordsOf(message.id, language);
    std::string out;
    std::size_t from = 0;  // the words between the placeholders escaped, each {k} filled in
    for (std::size_t at = 0; at + 2 < words.size(); ++at)
        if (words[at] == '{' && words[at + 1] >= '1' && words[at + 1] <= '9' && words[at + 2] == '}') {
            out += latexText(words.substr(from, at - from));
            if (const std::size_t k = static_cast<std::size_t>(words[at + 1] - '1'); k < message.args.size())
                out += latexMessageText(message.args[k], language);
            from = at + 3;
            at += 2;
        }
    return out + latexText(words.substr(from));
}

}  // namespace ll::present
