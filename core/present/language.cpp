#include "core/present/language.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

namespace ll::present {
namespace {

// Phrases inside longer texts, longest first where one contains another.
const std::vector<std::pair<std::string, std::string>>& danishPhrases() {
    static const std::vector<std::pair<std::string, std::string>> table = {
        // why a form was chosen (core/pipeline/derivation_forms.cpp)
        {"the expanded textbook form is cheap", "den ekspanderede lærebogsform er billig at udlede"},
        {"the expanded form grows exponentially (thousands of terms per entry), the structured form stays short",
         "den ekspanderede form vokser eksponentielt (tusinder af termer pr. element), den strukturerede form forbliver kort"},
        {"with twists and offsets multiples of pi/2 and at most one joint with both a and d non-zero",
         "med vridninger og vinkeloffsets som multipla af pi/2 og højst ét led med både a og d forskellige fra nul"},
        {"general twists or offsets", "generelle vridninger eller vinkeloffsets"},
        {"with several joints offset along both x and z", "med flere led forskudt langs både x og z"},
        {"a hand-typed Lagrangian is derived from its E_kin and E_pot", "en indtastet Lagrange-funktion udledes ud fra sin E_kin og E_pot"},
        {"asked for with --form", "valgt med --form"},
        // the structured form's notes on its names (core/symbolic/structured_dynamics.cpp)
        {"the kinetic energy; in JSON written out over the b_jk", "den kinetiske energi; i JSON skrevet ud over b_jk"},
        {"the potential energy: each link's weight over its gravity and frame-", "den potentielle energi: hvert links vægt over dets tyngde- og koordinatsystem-"},
        {" names, and the springs", "-navne, og fjedrene"},
        {"(its weight's lever on joint", "(dets tyngdes vægtarm om led"},
        {"per unit mass)", "pr. masseenhed)"},
        {"sum of the contributions of links", "summen af bidragene fra link"},
        {"sum of the contributions of link", "summen af bidragene fra link"},
        {"contribution of link", "bidrag fra link"},
        {"of the derivative of J_P column", "af den afledte af J_P-søjle"},
        {"of the velocity of the centre of mass of link", "af hastigheden af massemidtpunktet for link"},
        {"(J_P column), in its frame", "(J_P-søjle), i dets koordinatsystem"},
        {"per unit", "pr. enhed"},
        {"of the origin of frame", "af origo for koordinatsystem"},
        {" in the frame of link", " i koordinatsystemet for link"},
        {" of axis ", " af aksen "},
        {"derivative of", "afledte af"},
        {" column ", "-søjle "},
        {" of link ", " for link "},
        {" of frame ", " for koordinatsystem "},
        {" by q", " efter q"},
        {" to b", " til b"},
        {" and the velocities", " og hastighederne"},
        // the structured form's section formulas
        {"depends on", "afhænger af"},
        {" only.", " alene."},
        {" of ", " af "},
        {" joints", " led"},
        {" with ", " med "},
    };
    return table;
}

}  // namespace

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

std::string replacedInOrder(std::string text, const std::vector<std::pair<std::string, std::string>>& pairs) {
    for (const auto& [from, to] : pairs)
        for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) text.replace(at, from.size(), to);
    return text;
}

std::string translatedPhrases(std::string text, Language language) {
    return language == Language::English ? text : replacedInOrder(std::move(text), danishPhrases());
}

}  // namespace ll::present
