#pragma once
// The window's language and notation. Our strings come from the Danish catalogue
// (resources/translations/lagrangelab_da.ts, compiled by lrelease into :/i18n), Qt's own
// (standard dialogs: Cancel, Yes) from Debian's qtbase_da.qm. Chosen when the window
// starts: --lang, else what View → Language remembered, else the system locale (LANGUAGE,
// LC_ALL, LC_MESSAGES, LANG). The derivation follows a change at once (the document is
// relabelled, not derived again), and so do the menus and panels (ui/window/relabel.hpp).
#include <exception>
#include <optional>

#include <QString>

#include "core/present/localized_document.hpp"

class QCoreApplication;

namespace ll::ui {

// The remembered choice (nullopt: follow the system) and notation.
std::optional<present::Language> rememberedLanguage();
void rememberLanguage(std::optional<present::Language> language);
present::Notation rememberedNotation();
void rememberNotation(present::Notation notation);

// The language the window starts in: `given` (--lang), else the remembered one, else the
// system's.
present::Language startLanguage(std::optional<present::Language> given);

// Installs the translators for `language` into the running application (English: none),
// in place of those of the language before: the window relabels itself at once.
// False when our catalogue could not be loaded.
bool installLanguage(present::Language language);

// The language the window's strings are in now.
present::Language windowLanguage();

// What went wrong, for a message box or the status bar: our exceptions (InputError,
// MessageError: a file that cannot be saved) in `language`, any other's what() as it is
// (present::errorText). A worker passes the language it was given on the GUI thread.
QString shownError(const std::exception& error, present::Language language);

}  // namespace ll::ui
