#include "ui/window/presentation_mode.hpp"

#include <functional>
#include <initializer_list>
#include <utility>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLayout>
#include <QMainWindow>
#include <QMenuBar>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>

#include "ui/window/relabel.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/trajectory_chart.hpp"

namespace ll::ui {

PresentationMode::PresentationMode(const WindowParts& parts) : parts_(parts) {
    QMainWindow* window = parts.window;
    toggle_ = new QAction(window);
    (*new Relabel(window))([toggle = toggle_] { toggle->setText(tr("Presentation mode")); });
    toggle_->setShortcut(Qt::Key_F11);
    connect(toggle_, &QAction::triggered, this, [this] { setOn(!on_); });
    window->addAction(toggle_);  // F11 leaves presentation mode, where the menu bar is hidden
    // The keys, whichever widget has the focus (a button would take the space, the step
    // list the arrows); off otherwise, so the editors keep their keys. F (fit) is the 3D
    // view bar's shortcut, always on.
    for (auto [key, slot] :
         std::initializer_list<std::pair<QKeySequence, std::function<void()>>>{{Qt::Key_Space, [this] { parts_.playback->togglePlay(); }},
                                                                               {Qt::Key_Right, [this] { step(1); }},
                                                                               {Qt::Key_PageDown, [this] { step(1); }},
                                                                               {Qt::Key_Left, [this] { step(-1); }},
                                                                               {Qt::Key_PageUp, [this] { step(-1); }},
                                                                               {Qt::Key_Plus, [this] { parts_.playback->faster(); }},
                                                                               {Qt::Key_Minus, [this] { parts_.playback->slower(); }},
                                                                               {Qt::Key_Escape, [this] { setOn(false); }}}) {
        auto* action = new QAction(window);
        action->setShortcut(key);
        action->setShortcutContext(Qt::WindowShortcut);
        action->setEnabled(false);
        connect(action, &QAction::triggered, this, slot);
        window->addAction(action);
        keys_ << action;
    }
    // The large dock titles of presenting follow a language change (after the docks' own).
    (*new Relabel(window))([this] {
        QTimer::singleShot(0, this, [this] {
            for (QDockWidget* dock : parts_.window->findChildren<QDockWidget*>())
                if (auto* title = qobject_cast<QLabel*>(dock->titleBarWidget())) title->setText(dock->windowTitle());
        });
    });
}

void PresentationMode::step(int delta) {
    if (stepper_) stepper_(delta);
    else if (delta > 0) parts_.derivation->nextStep();
    else parts_.derivation->previousStep();
}

QByteArray PresentationMode::layoutToRemember() const { return on_ ? layoutBefore_ : parts_.window->saveState(); }

void PresentationMode::setOn(bool on) {
    if (on == on_) return;
    QMainWindow* window = parts_.window;
    if (on) {  // the layout as it is, to come back to exactly
        layoutBefore_ = window->saveState();
        geometryBefore_ = window->geometry();
    }
    on_ = on;
    parts_.modelDock->setVisible(!on);
    // Nothing a projector's audience needs to read twice: the menus (F11 and the keys stay
    // live as the window's own actions), the tool bar, the status line and the pick hint.
    window->menuBar()->setVisible(!on);
    window->statusBar()->setVisible(!on);
    parts_.readout->setVisible(!on);
    for (QToolBar* bar : window->findChildren<QToolBar*>(QString(), Qt::FindDirectChildrenOnly)) bar->setVisible(!on);
    if (auto* viewBar = window->findChild<QWidget*>("view-bar")) viewBar->setVisible(!on);  // the 3D view's (ui/window/view_bar)
    QFont font = QApplication::font();
    static const double base = font.pointSizeF() > 0 ? font.pointSizeF() : 10;
    font.setPointSizeF(on ? base * 1.6 : base);
    QApplication::setFont(font);
    parts_.derivation->setZoom(on ? 1.6 : 1.0);
    parts_.typeset->setZoom(on ? 1.6 : 1.0);  // 24 px per em: 18 pt at 96 dpi
    parts_.typeset->setPageOnly(on);
    parts_.derivationTabs->tabBar()->setVisible(!on);
    parts_.plotTabs->tabBar()->setVisible(!on);
    // Only the energy plot is shown: the other tabs' widest page (the DH step-through's
    // matrix at 1.6×) must not set the column's width. 0 gives the pages' minimum back.
    parts_.plotTabs->setMinimumWidth(on ? 200 : 0);
    parts_.readout->setFixedHeight(3 * QFontMetrics(font).lineSpacing() + 6);
    // The plots: bigger labels and lines need room, so their dock gets more height, and
    // the dock titles (which the application font does not reach) grow too.
    for (TrajectoryChart* chart : {parts_.energy, parts_.joints}) chart->setScale(on ? 1.4 : 1.0);
    // A dock paints its title in the platform's small title font whatever the application
    // font is, so presenting docks get a label of their own as title.
    for (QDockWidget* dock : window->findChildren<QDockWidget*>()) {
        QWidget* old = dock->titleBarWidget();
        if (on && !old) {
            auto* title = new QLabel(dock->windowTitle(), dock);
            title->setContentsMargins(6, 2, 6, 2);
            dock->setTitleBarWidget(title);
        } else if (!on && old) {
            dock->setTitleBarWidget(nullptr);
            old->deleteLater();
        }
    }
    for (QAction* key : keys_) key->setEnabled(on);
    emit changed(on);
    if (on) {
        if (size_.isValid()) {
            window->showNormal();
            window->resize(size_);
        } else {
            window->showFullScreen();
        }
        layOut();
        // Again once the window has its full size (full screen comes through the event loop).
        QTimer::singleShot(0, this, [this] { layOut(); });
    } else {  // every dock, toolbar and the window itself where they were
        // The camera that framed the projector's wide view would leave the robot small in
        // the docked one: refitted once the view has its docked size, unless the lecturer
        // turned, panned or zoomed it while presenting (then it stays as they left it).
        const bool refit = !parts_.view->cameraMovedByUser();
        window->showNormal();
        parts_.view->setFramePose(false);
        // After the event loop has applied the normal state, the smaller fonts and the
        // removed dock titles: restored now, the window would keep the presenting layout's
        // minimum width and the docks would be laid out again for the old sizes.
        // Twice: the first pass lets the widgets take their smaller minimum sizes, which
        // some (the toolbars) only do after a layout pass at the new size.
        const auto restore = [this, window] {
            if (on_) return;
            for (QWidget* w : window->findChildren<QWidget*>())
                if (w->layout()) w->layout()->activate();
            window->setGeometry(geometryBefore_);
            window->restoreState(layoutBefore_);
        };
        QTimer::singleShot(0, this, [this, restore, refit] {
            restore();
            QTimer::singleShot(0, this, [this, restore, refit] {
                restore();
                if (refit && !on_) QTimer::singleShot(0, parts_.view, [view = parts_.view] { view->fit(); });  // at the docked size
            });
        });
    }
}

void PresentationMode::layOut() {
    if (!on_) return;
    QMainWindow* window = parts_.window;
    QDockWidget *derivation = parts_.derivationDock, *plots = parts_.plotDock;
    // The plots under the derivation, both beside the 3D view: on a projector's 16:9 the
    // robot gets the left 58 % at full height instead of a strip above a plot.
    if (window->dockWidgetArea(plots) != Qt::RightDockWidgetArea || window->dockWidgetArea(derivation) != Qt::RightDockWidgetArea) {
        derivation->show();
        window->splitDockWidget(derivation, plots, Qt::Vertical);
    }
    const QSize area = window->size();
    window->resizeDocks({derivation}, {area.width() * 42 / 100}, Qt::Horizontal);
    window->resizeDocks({derivation, plots}, {area.height() * 56 / 100, area.height() * 44 / 100}, Qt::Vertical);
    parts_.plotTabs->setCurrentWidget(parts_.energyPage);
    parts_.derivationTabs->setCurrentWidget(parts_.typeset);
    // The camera on the robot as it stands, fitted to the view's new shape.
    QTimer::singleShot(0, this, [this] {
        if (on_) parts_.view->setFramePose(true);
    });
}

}  // namespace ll::ui
