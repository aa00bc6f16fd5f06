#pragma once
// View → Language and View → Notation: the language the derivation is shown in and the
// textbook whose letters it uses (the course notes, Siciliano, Spong, Craig), both
// remembered for the next start. A change relabels the derivation on screen at once; it
// is not derived again.
#include <QObject>

#include "core/present/localized_document.hpp"

class QMainWindow;
class QMenu;

namespace ll::ui {

class LanguageMenu : public QObject {
    Q_OBJECT
public:
    explicit LanguageMenu(QMainWindow& window);

    // The two submenus, added to `view`.
    void addTo(QMenu* view);
    void set(const present::Presentation& presentation);
    const present::Presentation& current() const { return presentation_; }

signals:
    void changed(const ll::present::Presentation& presentation);

private:
    void check();

    QMainWindow& window_;
    present::Presentation presentation_;
    QMenu *languageMenu_ = nullptr, *notationMenu_ = nullptr;
};

}  // namespace ll::ui
