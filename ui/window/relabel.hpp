#pragma once
// Texts made again when the window's language changes, without a restart. Each text is
// given as a function that sets it with tr() (so lupdate finds the string and the
// translator installed now answers): called once at once, and again whenever the watched
// widget receives QEvent::LanguageChange (Qt sends it to every widget when a translator
// is installed or removed; ui/document/app_language.hpp switches them).
//
//     Relabel& relabel = *new Relabel(this);
//     relabel([=] { button->setText(tr("Remove")); });
#include <functional>
#include <utility>
#include <vector>

#include <QEvent>
#include <QObject>

namespace ll::ui {

class Relabel : public QObject {
public:
    // Watches `owner` (a widget, or the main window for features that are no widget);
    // lives as long as it.
    explicit Relabel(QObject* owner) : QObject(owner) { owner->installEventFilter(this); }

    // Applies `set` now and after every language change.
    void operator()(std::function<void()> set) {
        set();
        setters_.push_back(std::move(set));
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == parent() && event->type() == QEvent::LanguageChange)
            for (const auto& set : setters_) set();
        return false;
    }

private:
    std::vector<std::function<void()>> setters_;
};

}  // namespace ll::ui
