#pragma once
// An error or warning as a reader sees it, in a language (language.hpp): "fejl:",
// "advarsel:", "tip:", "(led 2)" and the most common messages a student meets (a negative
// mass, an inertia no body has, a centre of mass far away, a number typed in mm, a key
// the format does not know) in Danish; the field (robot.joints[1].mass), names and numbers
// as they are. A message the table does not know stays English within the Danish frame.
#include <string>

#include "core/model/diagnostics.hpp"
#include "core/present/language.hpp"

namespace ll::present {

// Diagnostic::toString() in `language`.
std::string diagnosticText(const Diagnostic& diagnostic, Language language);

}  // namespace ll::present
