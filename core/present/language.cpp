#include "core/present/language.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <utility>
#include <vector>

namespace ll::present {
namespace {

// English → Danish, the register of a Danish engineering course (docs/glossary-da.md).
const std::map<std::string, std::string>& danish() {
    static const std::map<std::string, std::string> table = {
        // step titles (core/symbolic/robot_derivation.cpp, lagrangian_derivation.cpp, core/pipeline/pose_results.cpp)
        {"DH parameters (standard convention)", "DH-parametre (standardkonvention)"},
        {"DH parameters (modified convention)", "DH-parametre (modificeret konvention)"},
        {"Kinematic model", "Kinematisk model"},
        {"Centres of mass", "Massemidtpunkter"},
        {"Angular velocities", "Vinkelhastigheder"},
        {"Velocities of the centres of mass", "Massemidtpunkternes hastigheder"},
        {"Link inertia tensors in the base frame", "Linkenes inertitensorer i basiskoordinatsystemet"},
        {"Potential energy", "Potentiel energi"},
        {"Kinetic energy and the mass matrix", "Kinetisk energi og massematricen"},
        {"Equations of motion (Lagrange-d'Alembert)", "Bevægelsesligninger (Lagrange–d'Alembert)"},
        {"Generalized coordinates", "Generaliserede koordinater"},
        {"B(q), g(q) and E_pot at the pose", "B(q), g(q) og E_pot i stillingen"},
        {"The results at the teach pose", "Resultaterne i teach-stillingen"},
        // the structured form's sections (core/present/structured_display.cpp, structured_document.cpp)
        {"Kinematic model: frames in each link's own frame", "Kinematisk model: koordinatsystemerne i hvert links eget koordinatsystem"},
        {"Jacobian columns of the centres of mass", "Jacobi-søjler for massemidtpunkterne"},
        {"Potential energy and g", "Potentiel energi og g"},
        {"Kinetic energy: the mass matrix as sums", "Kinetisk energi: massematricen som summer"},
        {"Equations of motion: C from the derivatives of B", "Bevægelsesligninger: C ud fra de afledte af B"},
        {"Q holds the declared non-conservative forces (friction, torques).",
         "Q indeholder de angivne ikke-konservative kræfter (friktion, momenter)."},
        {"Kinematic model: the axes x_f, y_f, z_f and origin o_f of every frame f, in each link's own frame",
         "Kinematisk model: akserne x_f, y_f, z_f og origo o_f for hvert koordinatsystem f, i hvert links eget koordinatsystem"},
        {"Jacobian columns J_P,j^(i) of each centre of mass, in its link's frame (J_O,j^(i) = z of joint j's axis)",
         "Jacobi-søjler J_P,j^(i) for hvert massemidtpunkt, i dets links koordinatsystem (J_O,j^(i) = z for led j's akse)"},
        {"Potential energy: gamma_j^(i) = g0 . J_P,j^(i), so g_j = dE_pot/dq_j = -sum_{i>=j} m_i gamma_j^(i)",
         "Potentiel energi: gamma_j^(i) = g0 . J_P,j^(i), så g_j = dE_pot/dq_j = -sum_{i>=j} m_i gamma_j^(i)"},
        {"Mass matrix: beta_jk^(i) = m_i J_P,j^(i) . J_P,k^(i) + z_j^T I_i z_k, b_jk = sum_{i>=max(j,k)} beta_jk^(i)",
         "Massematrix: beta_jk^(i) = m_i J_P,j^(i) . J_P,k^(i) + z_j^T I_i z_k, b_jk = sum_{i>=max(j,k)} beta_jk^(i)"},
        {"Christoffel symbols: d b_jk / d q_l by the Jacobian identities (zero for l <= min(j,k))",
         "Christoffel-symboler: d b_jk / d q_l ud fra Jacobi-identiteterne (nul for l <= min(j,k))"},
        // document words (text_document, latex_document, ui/derivation_pages)
        {"Step", "Trin"},
        {"Actuation", "Aktuering"},
        {"Form", "Form"},
        {"Shorthand", "Notation"},
        {"Euler–Lagrange model", "Euler–Lagrange-model"},
        {"Euler–Lagrange derivation", "Euler–Lagrange-udledning"},
        {"the joint velocities and accelerations", "ledhastighederne og -accelerationerne"},
        {"the joint velocities", "ledhastighederne"},
        {"entry by entry", "element for element"},
        {"the zeros left out", "nullerne udeladt"},
        {"expanded", "ekspanderet"},
        {"structured", "struktureret"},
        // the actuation sentence (core/model/actuation.cpp)
        {"no inputs", "ingen input"},
        {"inputs on", "input på"},
        {"underactuated", "underaktueret"},
        {"fully actuated", "fuldt aktueret"},
        // the notation profile's remark
        {"Craig's notation goes with modified DH parameters; this robot is given in the standard convention",
         "Craigs notation hører til modificerede DH-parametre; denne robot er givet i standardkonventionen"},
        {"this notation goes with standard DH parameters; this robot is given in the modified convention",
         "denne notation hører til standard-DH-parametre; denne robot er givet i den modificerede konvention"},
    };
    return table;
}

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

std::string translated(const std::string& english, Language language) {
    if (language == Language::English) return english;
    const auto& table = danish();
    const auto it = table.find(english);
    return it != table.end() ? it->second : english;
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
