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
        // step formulas
        {"revolute q_i adds to theta_i, prismatic q_i to d_i", "rotationsled: q_i lægges til theta_i, prismatisk led: q_i til d_i"},
        {"row i:", "række i:"},
        {"\\text{row }", "\\text{række }"},
        {"(r_ci: COM of link i in frame i)", "(r_ci: massemidtpunktet for link i, udtrykt i koordinatsystem i)"},
        {"j<=i, revolute", "j<=i, rotationsled"},
        {"as given: gravity, springs and every other conservative force", "som angivet: tyngdekraft, fjedre og enhver anden konservativ kraft"},
        {"as given", "som angivet"},
        {"(no gravity declared)", "(ingen tyngdekraft angivet)"},
        {"non-conservative forces only", "kun ikke-konservative kræfter"},
        {"minimal, independent and complete; the velocity of x is", "minimale, uafhængige og fuldstændige; hastigheden af x er"},
        {"minimal, independent, complete", "minimale, uafhængige, fuldstændige"},
        {"written as", "skrevet som"},
        {" with g = ", " med g = "},
        {"motors: rotor j (inertia Jm_j, gear ratio G_j) turns at G_j qd_j, so it adds its armature Jm_j G_j^2 to b_jj",
         "motorer: rotor j (inertimoment Jm_j, udvekslingsforhold G_j) drejer med G_j qd_j og lægger derfor sin rotorinerti Jm_j G_j^2 til b_jj"},
        {"(Ja_j when given as armature)", "(Ja_j, når motoren er angivet ved sin rotorinerti)"},
        // the actuation sentence at the end of step 8's formula
        {"no inputs", "ingen input"},
        {"inputs on", "input på"},
        {"(underactuated:", "(underaktueret:"},
        {"(fully actuated)", "(fuldt aktueret)"},
        // the structured form's section formulas
        {"Every vector of link i is written in link i's own frame, where its centre of mass and inertia tensor are constant.",
         "Hver vektor for link i skrives i link i's eget koordinatsystem, hvor dets massemidtpunkt og inertitensor er konstante."},
        {"for a revolute joint j, z_j for a prismatic one.", "for et rotationsled j, z_j for et prismatisk led."},
        {"for a spring", "for en fjeder"},
        {"for a motor", "for en motor"},
        {"depends on", "afhænger af"},
        {" only.", " alene."},
        {"derivatives ∂b_jk/∂q_l (j ≤ k) are non-zero.", "afledte ∂b_jk/∂q_l (j ≤ k) er forskellige fra nul."},
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
