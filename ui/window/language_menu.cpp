#include "ui/window/language_menu.hpp"

#include <string>
#include <utility>

#include <QActionGroup>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>

#include "ui/window/relabel.hpp"
#include "ui/document/app_language.hpp"

namespace ll::ui {

LanguageMenu::LanguageMenu(QMainWindow& window) : window_(window) {}

void LanguageMenu::addTo(QMenu* view) {
    Relabel& relabel = *new Relabel(&window_);
    languageMenu_ = view->addMenu(QString());
    auto* languages = new QActionGroup(languageMenu_);
    for (const auto& [code, name] : {std::pair{"da", "Dansk"}, {"en", "English"}}) {  // each language in its own name
        QAction* a = languageMenu_->addAction(QString::fromUtf8(name));
        a->setData(QString::fromLatin1(code));
        a->setCheckable(true);
        languages->addAction(a);
        connect(a, &QAction::triggered, this, [this, code = std::string(code)] {
            const present::Language language = *present::languageNamed(code);
            rememberLanguage(language);
            set({language, presentation_.notation});
        });
    }
    notationMenu_ = view->addMenu(QString());
    relabel([languages = languageMenu_, notations = notationMenu_] {
        languages->setTitle(tr("&Language"));
        notations->setTitle(tr("&Notation"));
    });
    auto* notations = new QActionGroup(notationMenu_);
    for (const auto& [id, label] : {std::pair{present::Notation::Notes, QT_TR_NOOP("The course notes: B q̈ + C q̇ + g = Q")},
                                    {present::Notation::Siciliano, QT_TR_NOOP("Siciliano: B q̈ + C q̇ + g = τ")},
                                    {present::Notation::Spong, QT_TR_NOOP("Spong: D q̈ + C q̇ + g = τ")},
                                    {present::Notation::Craig, QT_TR_NOOP("Craig: M Θ̈ + V + G = τ (modified DH)")}}) {
        QAction* a = notationMenu_->addAction(QString());
        relabel([a, label = label] { a->setText(tr(label)); });
        a->setData(QString::fromLatin1(present::notationName(id)));
        a->setCheckable(true);
        notations->addAction(a);
        connect(a, &QAction::triggered, this, [this, id = id] {
            rememberNotation(id);
            set({presentation_.language, id});
        });
    }
    check();
}

void LanguageMenu::set(const present::Presentation& presentation) {
    presentation_ = presentation;
    // The window's own texts follow at once (every widget relabels itself on the
    // LanguageChange event installing the translators sends), the derivation with them.
    if (presentation.language != windowLanguage()) installLanguage(presentation.language);
    check();
    emit changed(presentation_);
}

void LanguageMenu::check() {
    if (languageMenu_)
        for (QAction* a : languageMenu_->actions())
            a->setChecked(a->data().toString() == QString::fromLatin1(present::languageCode(presentation_.language)));
    if (notationMenu_)
        for (QAction* a : notationMenu_->actions())
            a->setChecked(a->data().toString() == QString::fromLatin1(present::notationName(presentation_.notation)));
}

}  // namespace ll::ui
