#pragma once
// The language a derivation is written in: English (the core's own words) or Danish, the
// language the course is taught in. Catalogues of our own rather than GNU gettext (the
// words of each message id, core/present/message_text.hpp): gettext's lookup follows the process locale, which a fresh Debian often lacks
// for da_DK (only C.UTF-8 is generated), so `--lang da` would silently stay English.
// Names of fields (robot.joints[0].mass), symbols and numbers are never translated.
#include <optional>
#include <string>
#include <string_view>

namespace ll::present {

enum class Language { English, Danish };

// "en", "da", also a locale name (da_DK.UTF-8, en_GB); nullopt for anything else.
std::optional<Language> languageNamed(std::string_view name);
// "en" or "da".
const char* languageCode(Language language);
// As gettext reads the environment: the first of LANGUAGE (a colon-separated list),
// LC_ALL, LC_MESSAGES and LANG that names a language we have; English otherwise.
Language languageFromEnvironment();

}  // namespace ll::present
