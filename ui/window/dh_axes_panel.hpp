#pragma once
// "Find the DH parameters": step 0 of the notes done by their rules, one rule at a time
// (core/visual/dh_construction.hpp). The robot stands at home with its joint axes drawn as
// lines; Next places z_k, then o_k with the normal it came from, then x_k, then y_k, frame
// after frame, each with its sentence and the case it hit (skew, intersecting, parallel,
// coincident axes), while the table fills row by row. At the end the panel says whether
// the scene's own table is the one the rules give or another free choice. A robot imported
// from URDF has its link frames drawn over the DH frames (`overlay`).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <QWidget>

#include "core/visual/dh_construction.hpp"

class QLabel;
class QPushButton;

namespace ll::ui {

class DhAxesPanel : public QWidget {
    Q_OBJECT
public:
    explicit DhAxesPanel(QWidget* parent = nullptr);

    // The robot (a Lagrangian scene has none: the panel says so) and the frames to overlay
    // (world frame at home). Keeps the step where it can.
    void setRobot(const RobotModel& robot, bool isRobot, std::vector<std::pair<std::string, Eigen::Isometry3d>> overlay = {});
    // Step 4k + r: r rules done on frame k (dh_construction.hpp); clamped.
    void setStep(int index);
    int step() const { return index_; }
    int steps() const { return construction_ ? construction_->steps() : 1; }
    // What is drawn at the step shown (empty for a Lagrangian scene).
    std::vector<ConstructionMark> marks() const;
    // The texts as shown (tests).
    QString sentenceText() const;
    QString tableText() const;

public slots:
    void next();
    void previous();

signals:
    void stepChanged(int index);

private:
    void refresh();
    QString sentence(const DhConstructionStep& step) const;
    QString table() const;
    std::unique_ptr<const DhConstruction> construction_;
    int index_ = 0;
    QLabel *position_, *sentence_, *table_;
    QPushButton *first_, *previous_, *next_, *last_;
};

}  // namespace ll::ui
