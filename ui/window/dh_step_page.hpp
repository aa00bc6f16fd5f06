#pragma once
// The plots dock's "DH step-through" tab: two pages of step 0 — "Find the DH parameters"
// (the frames placed from the joint axes rule by rule, ui/window/dh_axes_panel) and "Row by
// row" (frame i−1 carried into frame i by row i's four motions, ui/window/dh_step_panel).
#include <QTabWidget>

namespace ll::ui {

class DhAxesPanel;
class DhStepPanel;

class DhStepPage : public QTabWidget {
    Q_OBJECT
public:
    explicit DhStepPage(QWidget* parent = nullptr);
    DhAxesPanel* axes() const { return axes_; }
    DhStepPanel* rows() const { return rows_; }

private:
    DhAxesPanel* axes_;
    DhStepPanel* rows_;
};

}  // namespace ll::ui
