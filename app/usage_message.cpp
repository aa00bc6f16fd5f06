#include "app/usage_message.hpp"

#include <array>
#include <cstddef>

#include "core/model/message.hpp"
#include "core/present/message_text.hpp"

namespace ll::cli {
namespace {

using Catalogue = std::array<const char*, static_cast<std::size_t>(UsageId::Count)>;

// Indexed by id, so a Danish line without its id in usage_messages.def does not compile
// and an id without a Danish line is a nullptr the test finds.
Catalogue danishCatalogue() {
    Catalogue words{};
    words[static_cast<std::size_t>(UsageId::Literal)] = "{1}";
#define LL_USAGE_DA(id, danish) words[static_cast<std::size_t>(UsageId::id)] = danish;
#include "app/usage_messages_da.def"
#undef LL_USAGE_DA
    return words;
}

}  // namespace

const char* englishWords(UsageId id) {
    switch (id) {
        case UsageId::Literal: return "{1}";
#define LL_USAGE(id, english) \
    case UsageId::id:         \
        return english;
#include "app/usage_messages.def"
#undef LL_USAGE
        case UsageId::Count: break;
    }
    return "";
}

const char* danishWords(UsageId id) {
    static const Catalogue catalogue = danishCatalogue();
    const auto k = static_cast<std::size_t>(id);
    return k < catalogue.size() ? catalogue[k] : nullptr;
}

const char* usageIdName(UsageId id) {
    switch (id) {
        case UsageId::Literal: return "Literal";
#define LL_USAGE(id, english) \
    case UsageId::id:         \
        return #id;
#include "app/usage_messages.def"
#undef LL_USAGE
        case UsageId::Count: break;
    }
    return "?";
}

std::string usageText(const UsageMessage& message, present::Language language) {
    const char* danish = language == present::Language::Danish ? danishWords(message.id) : nullptr;
    std::vector<std::string> args;
    args.reserve(message.args.size());
    for (const Message& a : message.args) args.push_back(present::messageText(a, language));
    return ll::filledIn(danish ? danish : englishWords(message.id), args);
}

}  // namespace ll::cli
