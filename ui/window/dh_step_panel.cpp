#include "ui/window/dh_step_panel.hpp"

#include "ui/window/relabel.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <QCheckBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include "core/kinematics/forward_kinematics.hpp"

namespace ll::ui {
namespace {
constexpr int kAnimationMs = 1000, kTickMs = 33;
}  // namespace

DhStepPanel::DhStepPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    auto* controls = new QVBoxLayout;
    auto* pick = new QHBoxLayout;
    auto* jointLabel = new QLabel(this);
    pick->addWidget(jointLabel);
    jointBox_ = new QSpinBox(this);
    jointBox_->setRange(1, 1);
    pick->addWidget(jointBox_);
    pick->addStretch(1);
    controls->addLayout(pick);
    previous_ = new QPushButton(this);
    next_ = new QPushButton(this);
    animate_ = new QPushButton(this);
    controls->addWidget(previous_);
    controls->addWidget(next_);
    controls->addWidget(animate_);
    dimensions_ = new QCheckBox(this);
    controls->addWidget(dimensions_);
    controls->addStretch(1);
    layout->addLayout(controls);
    product_ = new QLabel(this);
    product_->setTextFormat(Qt::RichText);
    product_->setWordWrap(true);
    product_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    layout->addWidget(product_, 2);
    matrix_ = new QLabel(this);
    matrix_->setTextFormat(Qt::RichText);
    matrix_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    layout->addWidget(matrix_, 1);
    connect(jointBox_, &QSpinBox::valueChanged, this, [this](int i) {
        if (i - 1 != joint_) setStep(i - 1, 0);
    });
    (*new Relabel(this))([this, jointLabel] {
        jointLabel->setText(tr("Joint i"));
        previous_->setText(tr("◀ Previous motion"));
        next_->setText(tr("Next motion ▶"));
        animate_->setText(tr("Animate the next motion"));
        dimensions_->setText(tr("Every parameter on the robot"));
        dimensions_->setToolTip(tr("Each row's θ, d, a and α drawn as arcs and arrows with their values, at the pose shown"));
        refresh();
    });
    connect(previous_, &QPushButton::clicked, this, &DhStepPanel::previous);
    connect(next_, &QPushButton::clicked, this, &DhStepPanel::next);
    connect(animate_, &QPushButton::clicked, this, &DhStepPanel::animate);
    connect(dimensions_, &QCheckBox::toggled, this, &DhStepPanel::dimensionsToggled);
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, [this] {
        fraction_ += double(kTickMs) / kAnimationMs;
        if (fraction_ >= 1) {
            timer_.stop();
            fraction_ = 0;
            ++done_;
            refresh();
            return;
        }
        emit stepChanged(joint_, done_, fraction_);
    });
    refresh();
}

void DhStepPanel::setRobot(const RobotModel& robot, bool isRobot) {
    robot_ = robot;
    isRobot_ = isRobot && robot.dof() > 0;
    if (q_.size() != robot_.dof()) q_ = Eigen::VectorXd::Zero(robot_.dof());
    jointBox_->setRange(1, std::max(1, robot_.dof()));
    setStep(std::min(joint_, std::max(0, robot_.dof() - 1)), done_);
}

void DhStepPanel::setPose(const Eigen::VectorXd& q) {
    if (q.size() != robot_.dof() || q == q_) return;
    q_ = q;
    refresh();
}

void DhStepPanel::setStep(int joint, int done) {
    timer_.stop();
    joint_ = std::clamp(joint, 0, std::max(0, robot_.dof() - 1));
    done_ = std::clamp(done, 0, 4);
    fraction_ = 0;
    refresh();
}

void DhStepPanel::next() {
    if (timer_.isActive()) return;
    if (done_ < 4) setStep(joint_, done_ + 1);
    else if (joint_ + 1 < robot_.dof()) setStep(joint_ + 1, 1);
}

void DhStepPanel::previous() {
    if (timer_.isActive()) return;
    if (done_ > 0) setStep(joint_, done_ - 1);
    else if (joint_ > 0) setStep(joint_ - 1, 3);
}

void DhStepPanel::animate() {
    if (!isRobot_ || timer_.isActive()) return;
    if (done_ == 4) {
        if (joint_ + 1 >= robot_.dof()) return;
        setStep(joint_ + 1, 0);
    }
    fraction_ = 0;
    timer_.start();
}

QString DhStepPanel::productText() const { return product_->text(); }
bool DhStepPanel::showsDimensions() const { return dimensions_->isChecked(); }
void DhStepPanel::setShowDimensions(bool on) { dimensions_->setChecked(on); }

void DhStepPanel::refresh() {
    const bool on = isRobot_;
    for (QWidget* w : std::initializer_list<QWidget*>{jointBox_, previous_, next_, animate_, dimensions_}) w->setEnabled(on);
    if (!on) {
        product_->setText(tr("A typed Lagrangian has no DH table: the step-through shows a robot's rows."));
        matrix_->clear();
        emit stepChanged(-1, 0, 0);
        emit parameterChanged(-1, DhParameter::Theta);
        return;
    }
    {
        const QSignalBlocker quiet(jointBox_);
        jointBox_->setValue(joint_ + 1);
    }
    const int i = joint_ + 1;
    const bool standard = robot_.convention == DhConvention::Standard;
    const std::array<ElementaryMotion, 4> motions = elementaryMotions(robot_, joint_, q_[joint_]);
    // A parameter's name as the table reads it: a_{i−1}, α_{i−1} in the modified convention.
    const auto name = [&](DhParameter p) {
        const QString row = QString::number(i), before = QString::number(i - 1);
        switch (p) {
            case DhParameter::A: return QString("a<sub>%1</sub>").arg(standard ? row : before);
            case DhParameter::Alpha: return QString("α<sub>%1</sub>").arg(standard ? row : before);
            case DhParameter::D: return QString("d<sub>%1</sub>").arg(row);
            case DhParameter::Theta: return QString("θ<sub>%1</sub>").arg(row);
        }
        return QString();
    };
    const auto op = [](ElementaryMotion::Kind k) {
        switch (k) {
            case ElementaryMotion::Kind::RotZ: return QString("Rot<sub>z</sub>");
            case ElementaryMotion::Kind::TransZ: return QString("Trans<sub>z</sub>");
            case ElementaryMotion::Kind::TransX: return QString("Trans<sub>x</sub>");
            case ElementaryMotion::Kind::RotX: return QString("Rot<sub>x</sub>");
        }
        return QString();
    };
    const int current = done_ < 4 ? done_ : -1;  // the motion to come
    QString factors;
    for (int k = 0; k < 4; ++k) {
        const ElementaryMotion& m = motions[static_cast<std::size_t>(k)];
        QString f = QString("%1(%2)").arg(op(m.kind), name(m.parameter));
        if (k < done_) f = QString("<span style='color:#1a7f37'>%1</span>").arg(f);    // done
        else if (k == current) f = QString("<b style='color:#c0392b'>%1</b>").arg(f);  // next
        else f = QString("<span style='color:#888'>%1</span>").arg(f);
        factors += (k ? " " : "") + f;
    }
    QString lines = QString("<p style='font-size:large'>A<sub>%1</sub> = %2</p>").arg(i).arg(factors);
    lines += "<p>" + tr("Frame %1 becomes frame %2 by four motions, each along or about an axis of the moving frame.").arg(i - 1).arg(i) +
             "</p><ol>";
    for (int k = 0; k < 4; ++k) {
        const ElementaryMotion& m = motions[static_cast<std::size_t>(k)];
        const QString value = m.rotates() ? QString("%1 rad (%2°)").arg(m.amount, 0, 'g', 4).arg(m.amount * 180 / M_PI, 0, 'f', 1)
                                          : QString("%1 m").arg(m.amount, 0, 'g', 4);
        const bool revolute = robot_.joints[static_cast<std::size_t>(joint_)].dh.type == JointType::Revolute;
        const bool joint = m.parameter == (revolute ? DhParameter::Theta : DhParameter::D);  // q_i enters here
        QString item = QString("%1(%2 = %3)").arg(op(m.kind), name(m.parameter), value);
        if (joint) item += " " + tr("(q<sub>%1</sub> included)").arg(i);
        if (k == current) item = "<b>" + item + "</b> ← " + tr("next");
        lines += "<li>" + item + "</li>";
    }
    lines += "</ol><p>" + tr("Motions done: %1 of 4").arg(done_) + "</p>";
    product_->setText(lines);
    // A_i's numbers at the pose shown.
    const Eigen::Matrix4d A = linkTransform(robot_, joint_, q_[joint_]).matrix();
    QString table = QString("<p>A<sub>%1</sub>(q<sub>%1</sub>) =</p><table cellspacing=4>").arg(i);
    for (int r = 0; r < 4; ++r) {
        table += "<tr>";
        for (int c = 0; c < 4; ++c) table += QString("<td align=right>%1</td>").arg(std::abs(A(r, c)) < 5e-13 ? 0.0 : A(r, c), 0, 'f', 4);
        table += "</tr>";
    }
    table += "</table><p>" + tr("lengths in m") + "</p>";
    matrix_->setText(table);
    emit stepChanged(joint_, done_, 0.0);
    emit parameterChanged(joint_, current >= 0 ? motions[static_cast<std::size_t>(current)].parameter : motions[3].parameter);
}

}  // namespace ll::ui
