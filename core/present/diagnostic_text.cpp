#include "core/present/diagnostic_text.hpp"

#include <utility>
#include <vector>

namespace ll::present {
namespace {

// Phrases of the messages (core/model/validation.cpp, unit_slips.cpp, core/io/scene_file.cpp),
// longest first where one contains another.
const std::vector<std::pair<std::string, std::string>>& danishMessages() {
    static const std::vector<std::pair<std::string, std::string>> table = {
        {"no physical body has this inertia; the model is simulated as given",
         "intet fysisk legeme har denne inerti; modellen simuleres som angivet"},
        {"violate the triangle inequality", "overholder ikke trekantsuligheden"},
        {"principal moments", "hovedinertimomenter"},
        {"inertia tensor is not positive semi-definite", "inertitensoren er ikke positiv semidefinit"},
        {"inertia tensor is not symmetric", "inertitensoren er ikke symmetrisk"},
        {"inertia tensor has a non-finite entry", "inertitensoren har et ikke-endeligt element"},
        {"mass is negative", "massen er negativ"},
        {"armature is negative", "rotorinertien er negativ"},
        {"it must be >= 0", "den skal være >= 0"},
        {"must be >= 0, got", "skal være >= 0, fik"},
        {"must be > 0, got", "skal være > 0, fik"},
        {"must be a finite number > 0, got", "skal være et endeligt tal > 0, fik"},
        {"must be a finite nonzero direction", "skal være en endelig retning forskellig fra nul"},
        {"puts the centre of mass", "placerer massemidtpunktet"},
        {"m from its frame, far outside the robot", "m fra sit koordinatsystem, langt uden for robotten"},
        {"the robot's reach is about", "robottens rækkevidde er omkring"},
        {"(sum of |a| and |d|)", "(summen af |a| og |d|)"},
        {"is longer than any arm", "er længere end nogen arm"},
        {"is larger than the whole robot", "er større end hele robotten"},
        {"is heavier than any arm's link", "er tungere end noget link på en arm"},
        {"check its unit (m) and its digits", "kontrollér enheden (m) og cifrene"},
        {"typed in mm?", "skrevet i mm?"},
        {"typed in g?", "skrevet i g?"},
        {"typed in g mm² or kg mm²?", "skrevet i g mm² eller kg mm²?"},
        {"radius of gyration", "inertiradius"},
        {"largest principal moment", "største hovedinertimoment"},
        {"unknown key", "ukendt nøgle"},
        {"required field is missing", "et påkrævet felt mangler"},
        {"key given twice (only one value may be given)", "nøglen er angivet to gange (kun én værdi er tilladt)"},
        {"JSON syntax error", "JSON-syntaksfejl"},
        {"at line", "i linje"},
        {"cannot read the file", "kan ikke læse filen"},
        {"expected a number or an expression, got", "forventede et tal eller et udtryk, fik"},
        {"a robot needs at least one joint", "en robot skal have mindst ét led"},
        {"a Lagrangian system needs at least one coordinate", "et Lagrange-system skal have mindst én koordinat"},
        {"a scene has either a robot or a lagrangian, not both", "en scene har enten en robot eller en lagrangian, ikke begge"},
        {"is not positive definite", "er ikke positiv definit"},
        {"the mass matrix", "massematricen"},
        {"absurdly large", "absurd stor"},
        {"absurdly small", "absurd lille"},
        {"(the default)", "(standardværdien)"},
    };
    return table;
}

std::string replacedAll(std::string text) {
    for (const auto& [from, to] : danishMessages())
        for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) text.replace(at, from.size(), to);
    return text;
}

}  // namespace

std::string diagnosticText(const Diagnostic& d, Language language) {
    if (language == Language::English) return d.toString();
    std::string where = d.where();
    if (const std::size_t at = where.rfind(" (joint "); at != std::string::npos) where.replace(at, 8, " (led ");
    return std::string(d.severity == Severity::Error ? "fejl: " : "advarsel: ") + where + ": " + replacedAll(d.message) +
           (d.hint.empty() ? "" : "\ntip: " + replacedAll(d.hint));
}

}  // namespace ll::present
