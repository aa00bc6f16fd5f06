#pragma once
// An error or warning as a reader sees it, in a language (language.hpp): its frame
// ("fejl:", "advarsel:", "tip:", "(led 2)") and its message and hint in words
// (message_text.hpp), each from the language's catalogue; the field
// (robot.joints[1].mass), names and numbers as they are.
#include <exception>
#include <string>

#include "core/model/diagnostics.hpp"
#include "core/present/language.hpp"

namespace ll::present {

enum class Place { Named, Omitted };

// Diagnostic::toString() in `language`: "error: robot.joints[0].mass (joint 1): ..."; with
// Place::Omitted without the field (a tooltip on the field itself).
std::string diagnosticText(const Diagnostic& diagnostic, Language language, Place place = Place::Named);
// Diagnostic::text() in `language`: the same without "error: " / "warning: " (a list of
// the errors of one file).
std::string diagnosticBody(const Diagnostic& diagnostic, Language language);

// What went wrong, in `language`: an InputError's errors (diagnosticBody, one a line), a
// MessageError's message (core/model/message_error.hpp); any other exception's what() as
// it is (a library's or the system's own words).
std::string errorText(const std::exception& error, Language language);

}  // namespace ll::present
