#include "core/present/language.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace ll::present {

std::optional<Language> languageNamed(std::string_view name) {
    const std::string_view code = name.substr(0, std::min(name.find_first_of("_.@-"), name.size()));
    if (code == "da") return Language::Danish;
    if (code == "en" || code == "C" || code == "POSIX") return Language::English;
    return std::nullopt;
}

const char* languageCode(Language language) { return language == Language::Danish ? "da" : "en"; }

Language languageFromEnvironment() {
    if (const char* list = std::getenv("LANGUAGE"); list && *list) {
        std::string_view rest = list;
        while (!rest.empty()) {
            const std::size_t colon = std::min(rest.find(':'), rest.size());
            if (const auto l = languageNamed(rest.substr(0, colon)); l && rest.substr(0, colon) != "C") return *l;
            rest.remove_prefix(std::min(colon + 1, rest.size()));
        }
    }
    for (const char* variable : {"LC_ALL", "LC_MESSAGES", "LANG"})
        if (const char* value = std::getenv(variable); value && *value) return languageNamed(value).value_or(Language::English);
    return Language::English;
}

}  // namespace ll::present
