#include "ui/window/tracking_pane.hpp"

#include <algorithm>
#include <cmath>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

#include "core/model/quantity_units.hpp"
#include "ui/document/entry_selection.hpp"
#include "ui/paint/math_typesetter.hpp"
#include "ui/window/relabel.hpp"
#include "ui/window/trajectory_chart.hpp"

namespace ll::ui {
namespace {

// The law as the textbook writes it.
QString lawText(ControlLaw law) {
    switch (law) {
        case ControlLaw::Pd: return QString::fromUtf8("τ = K_p e + K_d ė");
        case ControlLaw::PdGravity: return QString::fromUtf8("τ = K_p e + K_d ė + ĝ(q)");
        case ControlLaw::ComputedTorque: return QString::fromUtf8("τ = B̂(q)(q̈_d + K_p e + K_d ė) + Ĉ(q, q̇) q̇ + ĝ(q)");
        case ControlLaw::Feedforward: return QString::fromUtf8("τ = B̂(q_d) q̈_d + Ĉ(q_d, q̇_d) q̇_d + ĝ(q_d) + K_p e + K_d ė");
    }
    return {};
}

// "K_p e" with the index lowered, as rich text for a label.
QString lowered(const QString& text) {
    QString html = text.toHtmlEscaped();
    static const QRegularExpression index("_([A-Za-z0-9]+)");
    return html.replace(index, "<sub>\\1</sub>");
}

// Below this V̇ and −q̇ᵀK_d q̇ are the same curve (rounding and the integrator's q̈).
constexpr double kSameRate = 1e-6;

}  // namespace

TrackingPane::TrackingPane(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* bar = new QHBoxLayout;
    joint_ = new QComboBox(this);
    joint_->setObjectName("tracking-joint");
    show_ = new QComboBox(this);
    show_->setObjectName("tracking-show");
    law_ = new QLabel(this);
    law_->setFont(textbookFont(law_->font()));
    law_->setTextFormat(Qt::RichText);
    bar->addWidget(show_);
    bar->addWidget(joint_);
    bar->addStretch(1);
    bar->addWidget(law_);
    chart_ = new TrajectoryChart(TrajectoryChart::Kind::Curves, this);
    chart_->setTextbookFont();
    note_ = new QLabel(this);
    note_->setObjectName("tracking-note");
    note_->setWordWrap(true);
    note_->setTextFormat(Qt::RichText);
    note_->setFont(textbookFont(note_->font()));
    gain_ = new QSlider(Qt::Horizontal, this);
    gain_->setObjectName("tuning-gains");
    gain_->setRange(-8, 8);
    payload_ = new QSlider(Qt::Horizontal, this);
    payload_->setObjectName("tuning-payload");
    payload_->setRange(0, 50);
    gainText_ = new QLabel(this);
    payloadText_ = new QLabel(this);
    // The tuning sliders beside the choices (the plot keeps the height)
    for (QSlider* slider : {gain_, payload_}) slider->setFixedWidth(110);
    for (QWidget* w : std::initializer_list<QWidget*>{gainText_, gain_, payloadText_, payload_}) bar->insertWidget(bar->count() - 2, w);
    layout->addLayout(bar);
    layout->addWidget(chart_, 1);
    layout->addWidget(note_);
    connect(joint_, &QComboBox::currentIndexChanged, this, &TrackingPane::redraw);
    connect(show_, &QComboBox::currentIndexChanged, this, &TrackingPane::redraw);
    connect(chart_, &TrajectoryChart::timePicked, this, &TrackingPane::timePicked);
    (*new Relabel(this))([this] {
        const QSignalBlocker block(joint_);
        for (int j = 0; j < joint_->count(); ++j) joint_->setItemText(j, tr("joint %1").arg(j + 1));
        fillShows();
        redraw();
        showTuning(std::pow(2.0, gain_->value() / 4.0), payload_->value() / 10.0);
    });
}

void TrackingPane::showTuning(double factor, double payload) {
    gainText_->setText(tr("gains × %1").arg(factor, 0, 'g', 3));
    payloadText_->setText(tr("payload in its model %1 kg").arg(payload, 0, 'f', 1));
}

void TrackingPane::fillShows() {
    const QSignalBlocker block(show_);
    const int keep = std::max(0, show_->currentIndex());
    show_->clear();
    show_->addItem(tr("Tracking error e, ė"), int(Show::Error));
    show_->addItem(tr("Controller's torque"), int(Show::Torque));
    if (history_ && history_->lyapunov) {
        show_->addItem(tr("Lyapunov function V"), int(Show::Lyapunov));
        show_->addItem(tr("dV/dt and −q̇ᵀKd q̇"), int(Show::LyapunovRate));
    }
    show_->setCurrentIndex(std::min(keep, show_->count() - 1));
}

void TrackingPane::setControl(std::shared_ptr<const ControlHistory> history, std::shared_ptr<const Scene> scene, std::vector<double> t) {
    history_ = std::move(history);
    scene_ = std::move(scene);
    t_ = std::move(t);
    const int n = scene_ ? scene_->dof() : 0;
    {
        const QSignalBlocker block(joint_);
        const int keep = joint_->currentIndex();
        if (joint_->count() != n) {
            joint_->clear();
            for (int j = 0; j < n; ++j) joint_->addItem(tr("joint %1").arg(j + 1));
        }
        joint_->setCurrentIndex(std::clamp(keep, 0, std::max(0, n - 1)));
    }
    fillShows();
    redraw();
}

void TrackingPane::setJoint(int joint) { joint_->setCurrentIndex(joint); }

void TrackingPane::setShow(Show show) {
    const int at = show_->findData(int(show));
    if (at >= 0) show_->setCurrentIndex(at);
}

TrackingPane::Show TrackingPane::show() const { return static_cast<Show>(show_->currentData().toInt()); }
void TrackingPane::setCursorTime(double t) { chart_->setCursorTime(t); }
QString TrackingPane::note() const { return note_->text(); }

void TrackingPane::redraw() {
    const int j = joint_->currentIndex();
    const bool ready = history_ && scene_ && scene_->effects.control && !history_->parts.empty() && t_.size() == history_->parts.size();
    if (!ready || j < 0 || j >= scene_->dof()) {
        chart_->setCurves({}, {}, {});
        law_->clear();
        note_->clear();
        return;
    }
    const Control& control = *scene_->effects.control;
    law_->setText(QString("%1:&nbsp; %2").arg(QString::fromUtf8(toString(control.law)), lowered(lawText(control.law))));
    const bool revolute = scene_->robot.joints[static_cast<std::size_t>(j)].dh.type == JointType::Revolute;
    const QString unit = QString::fromStdString(coordinateUnit(revolute)), force = QString::fromStdString(forceUnit(revolute));
    const auto column = [&](const Eigen::VectorXd ControlParts::*part) {
        std::vector<double> v;
        v.reserve(history_->parts.size());
        for (const ControlParts& p : history_->parts) v.push_back((p.*part)[j]);
        return v;
    };
    std::vector<TrajectoryChart::Curve> curves;
    QString axis, note;
    const TrackingSummary& s = history_->summary;
    switch (show()) {
        case Show::Error:
            // The units in the legend: a title "[rad], [rad/s]" along the axis did not fit the dock's height.
            curves.push_back({tr("e = qref − q") + QString(" [%1]").arg(unit), QColor(31, 119, 180), Qt::SolidLine, column(&ControlParts::error)});
            curves.push_back({tr("ė = q̇ref − q̇") + QString(" [%1/s]").arg(unit), QColor(255, 127, 14), Qt::DashLine, column(&ControlParts::errorRate)});
            axis = QString::fromUtf8("e, ė");
            note = tr("Joint %1: RMS e = %2 %3, largest |e| = %4 %3.").arg(j + 1).arg(readableNumber(s.rmsError[j]), unit, readableNumber(s.maxError[j]));
            break;
        case Show::Torque: {
            struct Part {
                QString name;
                QColor colour;
                Qt::PenStyle style;
                const Eigen::VectorXd ControlParts::*of;
            };
            const bool ct = control.law == ControlLaw::ComputedTorque;
            const Part parts[] = {
                {tr("B̂ q̈d"), QColor(31, 119, 180), Qt::SolidLine, &ControlParts::inertial},
                {tr("Ĉ q̇"), QColor(214, 39, 40), Qt::SolidLine, &ControlParts::coriolis},
                {tr("ĝ"), QColor(44, 160, 44), Qt::SolidLine, &ControlParts::gravity},
                {ct ? tr("B̂ Kp e") : tr("Kp e"), QColor(148, 103, 189), Qt::DotLine, &ControlParts::proportional},
                {ct ? tr("B̂ Kd ė") : tr("Kd ė"), QColor(140, 86, 75), Qt::DotLine, &ControlParts::derivative},
                {tr("τ applied"), QColor(40, 40, 40), Qt::DashLine, &ControlParts::tau},
            };
            for (const Part& part : parts) {
                std::vector<double> v = column(part.of);
                const bool zero = std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
                if (!zero || part.of == &ControlParts::tau) curves.push_back({part.name, part.colour, part.style, std::move(v)});
            }
            axis = QString::fromUtf8("τ%1 [%2]").arg(j + 1).arg(force);
            note = tr("Joint %1: largest |τ| = %2 %3").arg(j + 1).arg(readableNumber(s.maxTorque[j]), force);
            if (j < control.torqueLimit.size())
                note += tr(", limit %1 %2, saturated %3 % of the run").arg(readableNumber(control.torqueLimit[j]), force).arg(100 * s.saturatedFraction[j], 0, 'g', 3);
            if (!control.drives(j)) note += tr(" (no actuator: τ = 0)");
            note += ".";
            break;
        }
        case Show::Lyapunov:
        case Show::LyapunovRate: {
            const LyapunovHistory& l = *history_->lyapunov;
            if (show() == Show::Lyapunov) {
                curves.push_back({QString::fromUtf8("V"), QColor(148, 103, 189), Qt::SolidLine, l.V});
                axis = QString::fromUtf8("V [J]");
            } else {
                curves.push_back({QString::fromUtf8("dV/dt"), QColor(31, 119, 180), Qt::SolidLine, l.Vdot});
                curves.push_back({QString::fromUtf8("−q̇ᵀKd q̇"), QColor(255, 127, 14), Qt::DashLine, l.dissipation});
                axis = QString::fromUtf8("[W]");
            }
            note = control.law == ControlLaw::Pd ? tr("V = ½ q̇ᵀB q̇ + ½ eᵀK_p e + E_pot(q) − E_pot(q_ref). ")
                                                 : tr("V = ½ q̇ᵀB q̇ + ½ eᵀK_p e. ");
            note += l.largestDeparture <= kSameRate
                        ? tr("dV/dt = −q̇ᵀK_d q̇ at every instant (largest difference %1 of the largest dissipation) because "
                             "q̇ᵀ(Ḃ − 2C)q̇ = 0: the skew-symmetry the Properties tab checks. V can only fall.")
                              .arg(readableNumber(l.largestDeparture))
                        : tr("dV/dt departs from −q̇ᵀK_d q̇ (by up to %1 of the largest dissipation): dV/dt + q̇ᵀK_d q̇ = q̇ᵀ(ĝ − g) + "
                             "the power of friction and of the limits' shortfall. The skew property still holds; the controller's "
                             "ĝ is not the robot's g, or something else acts.")
                              .arg(readableNumber(l.largestDeparture));
            break;
        }
    }
    chart_->setCurves(t_, std::move(curves), axis);
    note_->setText(lowered(note));
}

}  // namespace ll::ui
