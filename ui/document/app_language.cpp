#include "ui/document/app_language.hpp"

#include <cstring>

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

#include "core/present/diagnostic_text.hpp"

namespace ll::ui {
namespace {

present::Language installed = present::Language::English;

QSettings settings() { return QSettings("LagrangeLab", "LagrangeLab"); }

// lupdate does not read C++17 nested namespaces (namespace ll::ui {), so the catalogue's
// contexts are the bare class names (MainWindow) while tr() asks with the class's full
// name (ll::ui::MainWindow): a context not found as given is looked up without its
// namespace.
class Catalogue : public QTranslator {
public:
    using QTranslator::QTranslator;
    QString translate(const char* context, const char* source, const char* disambiguation, int n) const override {
        QString t = QTranslator::translate(context, source, disambiguation, n);
        if (t.isEmpty() && context)
            if (const char* bare = std::strrchr(context, ':')) t = QTranslator::translate(bare + 1, source, disambiguation, n);
        return t;
    }
};

}  // namespace

std::optional<present::Language> rememberedLanguage() {
    const QString code = settings().value("language").toString();
    if (code.isEmpty()) return std::nullopt;
    return present::languageNamed(code.toStdString());
}

void rememberLanguage(std::optional<present::Language> language) {
    auto s = settings();
    if (language) s.setValue("language", QString::fromLatin1(present::languageCode(*language)));
    else s.remove("language");
}

present::Notation rememberedNotation() {
    return present::notationNamed(settings().value("notation").toString().toStdString()).value_or(present::Notation::Notes);
}

void rememberNotation(present::Notation notation) { settings().setValue("notation", QString::fromLatin1(present::notationName(notation))); }

present::Language startLanguage(std::optional<present::Language> given) {
    if (given) return *given;
    if (const auto remembered = rememberedLanguage()) return *remembered;
    return present::languageFromEnvironment();
}

bool installLanguage(present::Language language) {
    // Owned by the application; the ones of the language before are taken out first, so a
    // switch while the window runs leaves only the new language's (Qt then sends every
    // widget QEvent::LanguageChange, and the window relabels itself: ui/window/relabel.hpp).
    static QTranslator* ours = nullptr;
    static QTranslator* qt = nullptr;
    for (QTranslator** t : {&ours, &qt})
        if (*t) {
            QCoreApplication::removeTranslator(*t);
            delete *t;
            *t = nullptr;
        }
    installed = language;
    if (language == present::Language::English) return true;
    ours = new Catalogue(QCoreApplication::instance());
    qt = new QTranslator(QCoreApplication::instance());
    const bool loaded = ours->load(QStringLiteral(":/i18n/lagrangelab_da.qm"));
    if (loaded) QCoreApplication::installTranslator(ours);
    if (qt->load(QStringLiteral("qtbase_da"), QLibraryInfo::path(QLibraryInfo::TranslationsPath))) QCoreApplication::installTranslator(qt);
    return loaded;
}

present::Language windowLanguage() { return installed; }

QString shownError(const std::exception& error, present::Language language) {
    return QString::fromStdString(present::errorText(error, language));
}

}  // namespace ll::ui
