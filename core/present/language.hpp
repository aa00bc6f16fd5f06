#pragma once
// The language a derivation is written in: English (the core's own words) or Danish, the
// language the course is taught in. Catalogues of our own rather than GNU gettext (the
// words of each message id, core/present/message_text.hpp; the phrases inside formulas
// below): gettext's lookup follows the process locale, which a fresh Debian often lacks
// for da_DK (only C.UTF-8 is generated), so `--lang da` would silently stay English.
// Names of fields (robot.joints[0].mass), symbols and numbers are never translated.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ll::present {

enum class Language { English, Danish };

// "en", "da", also a locale name (da_DK.UTF-8, en_GB); nullopt for anything else.
std::optional<Language> languageNamed(std::string_view name);
// "en" or "da".
const char* languageCode(Language language);
// As gettext reads the environment: the first of LANGUAGE (a colon-separated list),
// LC_ALL, LC_MESSAGES and LANG that names a language we have; English otherwise.
Language languageFromEnvironment();

// `text` with every `from` of `pairs` replaced by its `to`, pair by pair in order (a longer
// phrase before a shorter one it contains); a replacement is not searched again.
std::string replacedInOrder(std::string text, const std::vector<std::pair<std::string, std::string>>& pairs);

// `text` (a step's general formula, a form's reason, a structured name's note) with each
// of the core's phrases in it in `language`: the phrases around symbols and numbers ("row
// i:", "Q: non-conservative forces only", "auto: 2 joints: …"). Titles, headings and the
// documents' fixed words are message ids instead (core/model/messages/document.def).
std::string translatedPhrases(std::string text, Language language);

}  // namespace ll::present
