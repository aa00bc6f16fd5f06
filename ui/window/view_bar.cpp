#include "ui/window/view_bar.hpp"

#include <QAction>
#include <QFrame>
#include <QSignalBlocker>
#include <QToolButton>
#include <utility>

#include "ui/window/flow_layout.hpp"
#include "ui/window/relabel.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::ui {

ViewBar::ViewBar(SceneView* view, QWidget* parent) : QWidget(parent) {
    setObjectName("view-bar");
    QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred);
    policy.setHeightForWidth(true);
    setSizePolicy(policy);
    auto* layout = new FlowLayout(this);
    Relabel& relabel = *new Relabel(this);
    const auto button = [this, layout](QAction* action) {
        auto* b = new QToolButton(this);
        b->setAutoRaise(true);
        b->setDefaultAction(action);  // the action's shortcut lives as long as the button is shown
        layout->addWidget(b);
        return b;
    };
    auto* fit = new QAction(this);
    fit->setShortcut(Qt::Key_F);
    connect(fit, &QAction::triggered, view, &SceneView::fit);
    parent->addAction(fit);  // F also while the bar is hidden (presentation mode)
    relabel([fit] { fit->setText(tr("Fit")); });
    button(fit);
    for (const char* name : {QT_TR_NOOP("front"), QT_TR_NOOP("side"), QT_TR_NOOP("top"), QT_TR_NOOP("iso")}) {
        auto* a = new QAction(this);
        connect(a, &QAction::triggered, view, [view, name] { view->setStandardView(name); });
        relabel([a, name] { a->setText(tr(name)); });
        button(a);
    }
    auto* separator = new QFrame(this);
    separator->setFrameShape(QFrame::VLine);
    separator->setFrameShadow(QFrame::Sunken);
    layout->addWidget(separator);
    for (const auto& [name, slot] : {std::pair{QT_TR_NOOP("frames"), &SceneView::setShowFrames},
                                     {QT_TR_NOOP("labels"), &SceneView::setShowLabels},
                                     {QT_TR_NOOP("COMs"), &SceneView::setShowComs},
                                     {QT_TR_NOOP("trail"), &SceneView::setShowTrail},
                                     {QT_TR_NOOP("meshes"), &SceneView::setShowLook}}) {
        auto* a = new QAction(this);
        a->setCheckable(true);
        a->setChecked(true);
        connect(a, &QAction::toggled, view, slot);
        // A toggle set elsewhere (a saved view restored) shows in its button.
        bool (SceneView::*shown)() const = slot == &SceneView::setShowFrames   ? &SceneView::showFrames
                                           : slot == &SceneView::setShowLabels ? &SceneView::showLabels
                                           : slot == &SceneView::setShowComs   ? &SceneView::showComs
                                           : slot == &SceneView::setShowTrail  ? &SceneView::showTrail
                                                                               : &SceneView::lookWanted;
        connect(view, &SceneView::partsShownChanged, a, [a, view, shown] {
            const QSignalBlocker quiet(a);
            a->setChecked((view->*shown)());
        });
        relabel([a, name = name] { a->setText(tr(name)); });
        QToolButton* b = button(a);
        // The meshes button only for a robot that has meshes (one imported from URDF).
        if (slot == &SceneView::setShowLook) {
            b->hide();
            connect(view, &SceneView::lookAvailable, b, &QWidget::setVisible);
        }
    }
}

}  // namespace ll::ui
