#include "core/model/message.hpp"

#include "core/model/diagnostics.hpp"

namespace ll {

Message literal(std::string text) {
    Message m;
    m.literal = std::move(text);
    return m;
}

std::string detail::formatArgument(double value) { return formatValue(value); }

const char* englishWords(MessageId id) {
    switch (id) {
        case MessageId::Literal: return "{1}";
#define LL_MESSAGE(id, english) \
    case MessageId::id:         \
        return english;
#include "core/model/messages/all.def"
#undef LL_MESSAGE
        case MessageId::Count: break;
    }
    return "";
}

const char* messageIdName(MessageId id) {
    switch (id) {
        case MessageId::Literal: return "Literal";
#define LL_MESSAGE(id, english) \
    case MessageId::id:         \
        return #id;
#include "core/model/messages/all.def"
#undef LL_MESSAGE
        case MessageId::Count: break;
    }
    return "?";
}

std::set<int> placeholders(const std::string& words) {
    std::set<int> out;
    for (std::size_t i = 0; i + 2 < words.size(); ++i)
        if (words[i] == '{' && words[i + 1] >= '1' && words[i + 1] <= '9' && words[i + 2] == '}') out.insert(words[i + 1] - '0');
    return out;
}

std::string filledIn(const std::string& words, const std::vector<std::string>& args) {
    std::string out;
    out.reserve(words.size() + 16);
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (words[i] == '{' && i + 2 < words.size() && words[i + 1] >= '1' && words[i + 1] <= '9' && words[i + 2] == '}') {
            const std::size_t k = static_cast<std::size_t>(words[i + 1] - '1');
            if (k < args.size()) out += args[k];
            i += 2;
        } else {
            out += words[i];
        }
    }
    return out;
}

std::string Message::english() const {
    if (id == MessageId::Literal) return literal;
    std::vector<std::string> filled;
    filled.reserve(args.size());
    for (const Message& a : args) filled.push_back(a.english());
    return filledIn(englishWords(id), filled);
}

}  // namespace ll
