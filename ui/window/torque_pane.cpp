#include "ui/window/torque_pane.hpp"

#include "ui/window/relabel.hpp"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include "core/model/quantity_units.hpp"
#include "ui/document/entry_selection.hpp"
#include "ui/paint/math_typesetter.hpp"
#include "ui/window/trajectory_chart.hpp"

namespace ll::ui {

TorquePane::TorquePane(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* bar = new QHBoxLayout;
    joint_ = new QComboBox(this);
    residual_ = new QLabel(this);
    residual_->setFont(textbookFont(residual_->font()));
    auto* where = new QLabel(this);
    bar->addWidget(where);
    bar->addWidget(joint_);
    auto* equation = new QLabel(this);
    equation->setFont(textbookFont(equation->font()));
    bar->addWidget(equation);
    bar->addStretch(1);
    bar->addWidget(residual_);
    chart_ = new TrajectoryChart(TrajectoryChart::Kind::Curves, this);
    chart_->setTextbookFont();
    layout->addLayout(bar);
    layout->addWidget(chart_, 1);
    connect(joint_, &QComboBox::currentIndexChanged, this, &TorquePane::redraw);
    (*new Relabel(this))([this, where, equation] {
        where->setText(tr("Where the torque of"));
        equation->setText(tr("goes: B q̈ + C q̇ + g = Q"));
        if (joint_->count() > 0) {  // the joints' names and the curves' again, in the new language
            const QSignalBlocker block(joint_);
            for (int j = 0; j < joint_->count() && scene_ && !scene_->lagrangian; ++j) joint_->setItemText(j, tr("joint %1").arg(j + 1));
            redraw();
        }
    });
    connect(chart_, &TrajectoryChart::timePicked, this, &TorquePane::timePicked);
}

void TorquePane::setTorques(std::shared_ptr<const TorqueHistory> history, std::shared_ptr<const Scene> scene) {
    history_ = std::move(history);
    scene_ = std::move(scene);
    const int n = scene_ ? scene_->dof() : 0;
    const int keep = joint_->currentIndex();
    joint_->blockSignals(true);
    if (joint_->count() != n) {
        joint_->clear();
        for (int j = 0; j < n; ++j)
            joint_->addItem(scene_->lagrangian ? QString::fromStdString(scene_->lagrangian->coordinates[static_cast<std::size_t>(j)])
                                               : tr("joint %1").arg(j + 1));
    }
    joint_->setCurrentIndex(std::clamp(keep, 0, std::max(0, n - 1)));
    joint_->blockSignals(false);
    redraw();
}

void TorquePane::setJoint(int joint) { joint_->setCurrentIndex(joint); }
int TorquePane::joint() const { return joint_->currentIndex(); }
void TorquePane::setCursorTime(double t) { chart_->setCursorTime(t); }

void TorquePane::redraw() {
    const int j = joint_->currentIndex();
    if (!history_ || !scene_ || j < 0 || history_->parts.empty() || j >= history_->parts.front().inertial.size()) {
        chart_->setCurves({}, {}, {});
        residual_->clear();
        return;
    }
    const std::string unit =
        scene_->lagrangian ? "" : forceUnit(scene_->robot.joints[static_cast<std::size_t>(j)].dh.type == JointType::Revolute);
    struct Part {
        QString name;
        QColor colour;
        Qt::PenStyle style;
        double (*of)(const TorqueParts&, int);
    };
    const Part parts[] = {
        {tr("B q̈ (inertial)"), QColor(31, 119, 180), Qt::SolidLine, [](const TorqueParts& p, int k) { return p.inertial[k]; }},
        {tr("C q̇ (Coriolis, centrifugal)"), QColor(214, 39, 40), Qt::SolidLine, [](const TorqueParts& p, int k) { return p.coriolis[k]; }},
        {tr("g (gravity, springs)"), QColor(44, 160, 44), Qt::SolidLine, [](const TorqueParts& p, int k) { return p.potential[k]; }},
        {tr("Q (non-conservative)"), QColor(40, 40, 40), Qt::DashLine, [](const TorqueParts& p, int k) { return p.Q()[k]; }},
        {tr("Q: actuation"), QColor(148, 103, 189), Qt::DotLine, [](const TorqueParts& p, int k) { return p.actuation[k]; }},
        {tr("Q: viscous friction"), QColor(140, 86, 75), Qt::DotLine, [](const TorqueParts& p, int k) { return p.viscous[k]; }},
        {tr("Q: Coulomb friction"), QColor(227, 119, 194), Qt::DotLine, [](const TorqueParts& p, int k) { return p.coulomb[k]; }},
    };
    std::vector<TrajectoryChart::Curve> curves;
    for (std::size_t i = 0; i < std::size(parts); ++i) {
        TrajectoryChart::Curve c{parts[i].name, parts[i].colour, parts[i].style, {}};
        c.values.reserve(history_->parts.size());
        double largest = 0;
        for (const TorqueParts& p : history_->parts) {
            c.values.push_back(parts[i].of(p, j));
            largest = std::max(largest, std::abs(c.values.back()));
        }
        // Q's parts only when the scene declares them (a zero curve says nothing); the
        // three terms of the left side always.
        if (i < 4 || largest > 0) curves.push_back(std::move(c));
    }
    // τ_j [N·m]: short, the axis title is set along the plot's height
    const QString axis = unit.empty() ? QString::fromUtf8("τ (%1)").arg(joint_->currentText())
                                      : QString::fromUtf8("τ%1 [%2]").arg(j + 1).arg(QString::fromStdString(unit));
    chart_->setCurves(history_->t, std::move(curves), axis);
    residual_->setText(tr("largest |B q̈ + C q̇ + g − Q| of the run: %1%2")
                           .arg(readableNumber(history_->largestResidual), unit.empty() ? QString() : " " + QString::fromStdString(unit)));
}

}  // namespace ll::ui
