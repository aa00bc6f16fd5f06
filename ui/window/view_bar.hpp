#pragma once
// The 3D view's bar: Fit (F), the standard views (front, side, top, iso) and the toggles
// (frames, labels, COMs, trail); hidden while presenting, when F still fits. Its buttons wrap to a second row where one row does not
// hold them (flow_layout.hpp), so no button hides behind "»" in a longer language.
#include <QWidget>

namespace ll::ui {

class SceneView;

class ViewBar : public QWidget {
    Q_OBJECT
public:
    ViewBar(SceneView* view, QWidget* parent);
};

}  // namespace ll::ui
