#include "ui/window/dh_axes_panel.hpp"

#include <algorithm>
#include <cmath>

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/window/relabel.hpp"

namespace ll::ui {
namespace {

QString sub(const QString& symbol, int k) { return QString("%1<sub>%2</sub>").arg(symbol).arg(k); }

// Numbers as the textbook prints them: a minus sign, not a hyphen.
QString printed(QString number) { return number.replace(QChar('-'), QChar(0x2212)); }

// An angle as the table reads it: degrees, one decimal where needed.
QString degrees(double radians) {
    const double d = radians * 180 / M_PI;
    return printed(QString::number(std::abs(d) < 5e-10 ? 0.0 : d, 'f', std::abs(d - std::round(d)) < 5e-10 ? 0 : 1)) + "°";
}

QString metres(double v) { return printed(QString::number(std::abs(v) < 5e-13 ? 0.0 : v, 'g', 4)) + " m"; }

// A table cell holding the joint variable: "q₂", "q₂ − 90°", "q₃ + 0.1 m".
QString withJoint(int i, double offset, const QString& shown) {
    if (std::abs(offset) < 5e-13) return sub("q", i);
    return sub("q", i) + (offset < 0 ? " − " : " + ") + QString(shown).remove(QChar(0x2212));
}

}  // namespace

DhAxesPanel::DhAxesPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    auto* controls = new QVBoxLayout;
    position_ = new QLabel(this);
    controls->addWidget(position_);
    first_ = new QPushButton(this);
    previous_ = new QPushButton(this);
    next_ = new QPushButton(this);
    last_ = new QPushButton(this);
    for (QPushButton* b : {previous_, next_, first_, last_}) controls->addWidget(b);
    controls->addStretch(1);
    layout->addLayout(controls);
    sentence_ = new QLabel(this);
    sentence_->setTextFormat(Qt::RichText);
    sentence_->setWordWrap(true);
    sentence_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    layout->addWidget(sentence_, 3);
    table_ = new QLabel(this);
    table_->setTextFormat(Qt::RichText);
    table_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    layout->addWidget(table_, 2);
    connect(first_, &QPushButton::clicked, this, [this] { setStep(0); });
    connect(previous_, &QPushButton::clicked, this, &DhAxesPanel::previous);
    connect(next_, &QPushButton::clicked, this, &DhAxesPanel::next);
    connect(last_, &QPushButton::clicked, this, [this] { setStep(steps() - 1); });
    (*new Relabel(this))([this] {
        first_->setText(tr("« The axes"));
        previous_->setText(tr("◀ Previous rule"));
        next_->setText(tr("Next rule ▶"));
        last_->setText(tr("The table »"));
        refresh();
    });
}

void DhAxesPanel::setRobot(const RobotModel& robot, bool isRobot, std::vector<std::pair<std::string, Eigen::Isometry3d>> overlay) {
    construction_.reset();
    if (isRobot && robot.dof() > 0) construction_ = std::make_unique<const DhConstruction>(robot, std::move(overlay));
    setStep(index_);
}

void DhAxesPanel::setStep(int index) {
    index_ = std::clamp(index, 0, steps() - 1);
    refresh();
}

void DhAxesPanel::next() { setStep(index_ + 1); }
void DhAxesPanel::previous() { setStep(index_ - 1); }

std::vector<ConstructionMark> DhAxesPanel::marks() const {
    return construction_ ? construction_->marks(index_) : std::vector<ConstructionMark>{};
}
QString DhAxesPanel::sentenceText() const { return sentence_->text(); }
QString DhAxesPanel::tableText() const { return table_->text(); }

void DhAxesPanel::refresh() {
    const bool on = construction_ != nullptr;
    for (QPushButton* b : {first_, previous_, next_, last_}) b->setEnabled(on);
    if (!on) {
        position_->clear();
        sentence_->setText(tr("A typed Lagrangian has no joint axes: finding the DH parameters needs a robot."));
        table_->clear();
        emit stepChanged(index_);
        return;
    }
    previous_->setEnabled(index_ > 0);
    first_->setEnabled(index_ > 0);
    next_->setEnabled(index_ + 1 < steps());
    last_->setEnabled(index_ + 1 < steps());
    position_->setText(tr("Rule %1 of %2").arg(index_).arg(steps() - 1));
    sentence_->setText(sentence(DhConstruction::step(index_)));
    table_->setText(table());
    emit stepChanged(index_);
}

QString DhAxesPanel::sentence(const DhConstructionStep& step) const {
    const DhConstruction& c = *construction_;
    const int n = c.joints(), k = step.frame;
    const bool standard = c.found().convention == DhConvention::Standard;
    const DhFrameRule& f = c.found().frames[static_cast<std::size_t>(k)];
    const QString z = sub("z", k), o = sub("o", k), x = sub("x", k);
    QString head, text;
    switch (step.rule) {
        case DhRule::Axes:
            head = tr("The joint axes");
            text =
                tr("The robot stands at home (all q = 0). Joint i turns about (or slides along) its axis, the line marked q<sub>i</sub>. "
                   "The rules now place frames 0 to %1 on these lines, one rule at a time: z, then the origin o, then x, then y.")
                    .arg(n);
            break;
        case DhRule::Z:
            head = tr("Frame %1: z").arg(k);
            if (standard && k == n) text = tr("Frame %1 is the tool's: %2 is taken along the last joint's axis.").arg(k).arg(z);
            else if (standard)
                text = tr("%1 lies on the axis of joint %2, pointing the way q<sub>%2</sub> turns it (right-hand rule) or slides it.")
                           .arg(z)
                           .arg(k + 1);
            else if (k == 0) text = tr("%1 lies on the axis of joint 1: frame 0 is frame 1 at home as far as the rules allow.").arg(z);
            else
                text = tr("%1 lies on the axis of joint %2, pointing the way q<sub>%2</sub> turns it (right-hand rule) or slides it.")
                           .arg(z)
                           .arg(k);
            break;
        case DhRule::Origin: {
            // The two lines the origin is found from, as the convention names them.
            const QString before = standard ? sub("z", k - 1) : z, after = standard ? z : tr("the axis of joint %1").arg(k + 1);
            head = tr("Frame %1: the origin").arg(k);
            if (k == 0) {
                text = tr("%1 may lie anywhere on %2: it is taken where %2 comes nearest to the world's origin.").arg(o, z);
            } else if (f.pair == AxisPair::Last) {
                text = standard ? tr("%1 is put at the tool's origin.").arg(o)
                                : tr("%1 is where %2 meets %3, so d<sub>%4</sub> = 0.").arg(o, sub("x", k - 1), z).arg(k);
            } else {
                switch (f.pair) {
                    case AxisPair::Skew:
                        text = tr("%1 and %2 are skew: they have exactly one common normal (the magenta line). %3 is where it meets %4.")
                                   .arg(before, after, o, z);
                        break;
                    case AxisPair::Intersecting:
                        text = tr("%1 and %2 intersect: %3 is where they meet, so a<sub>%4</sub> = 0.").arg(before, after, o).arg(k);
                        break;
                    case AxisPair::Parallel:
                        text = tr("%1 and %2 are parallel: every normal to one is normal to the other, so the rule leaves the origin free. "
                                  "Chosen: the normal through the previous origin, so d<sub>%3</sub> = 0.")
                                   .arg(before, after)
                                   .arg(k);
                        break;
                    case AxisPair::Coincident:
                        text = tr("%1 and %2 lie on one line: %3 stays at the previous origin (a = 0 and d = 0 between them).")
                                   .arg(before, after, o);
                        break;
                    case AxisPair::Last: break;
                }
                if (f.antiparallel)
                    text +=
                        " " +
                        tr("The two axes point opposite ways: α = 180°. z is never turned round to avoid it, or q would turn the joint the other way.");
            }
            break;
        }
        case DhRule::X:
            head = tr("Frame %1: x").arg(k);
            if (k == 0)
                text =
                    tr("%1 is any direction perpendicular to %2: the world's x (or y) made perpendicular, so frame 0 matches the world where it can.")
                        .arg(x, z);
            else if (f.pair == AxisPair::Last)
                text = standard
                           ? tr("%1 points from the last axis to the tool's origin (along %2 when the tool's origin is on that axis).")
                                 .arg(x, sub("x", k - 1))
                           : tr("%1 = %2 (made perpendicular to %3), so θ<sub>%4</sub> = 0 at home.").arg(x, sub("x", k - 1), z).arg(k);
            else if (f.pair == AxisPair::Intersecting)
                text = tr("%1 is perpendicular to both axes: ±(%2 × %3). The sign is a choice: the one that keeps θ = 0 at home.")
                           .arg(x, standard ? sub("z", k - 1) : z, standard ? z : sub("z", k + 1));
            else if (f.pair == AxisPair::Coincident)
                text = tr("%1 is free around the one line: kept as %2, so θ = 0.").arg(x, sub("x", k - 1));
            else
                text = standard ? tr("%1 lies along the common normal, pointing from %2 to %3.").arg(x, sub("z", k - 1), z)
                                : tr("%1 lies along the common normal, pointing from %2 to the axis of joint %3.").arg(x, z).arg(k + 1);
            break;
        case DhRule::Y:
            head = tr("Frame %1: y").arg(k);
            text = tr("%1 = %2 × %3 completes a right-handed frame.").arg(sub("y", k), z, x);
            if (k >= 1) text += " " + tr("Row %1 of the table is read off frames %2 and %1.").arg(k).arg(k - 1);
            break;
    }
    QString html = QString("<p style='font-size:large'><b>%1</b></p><p>%2</p>").arg(head, text);
    if (index_ + 1 == steps()) {
        const std::vector<int> differing = c.rowsDiffering();
        QString rows;
        for (const int r : differing) rows += (rows.isEmpty() ? "" : ", ") + QString::number(r);
        html += "<p>" +
                (differing.empty()
                     ? tr("The scene's own table is the one the rules give.")
                     : tr("The scene's own table differs in row(s) %1: the rules leave choices (an origin on parallel axes, a sign of x) "
                          "that the scene made another way. Both describe the same robot.")
                           .arg(rows)) +
                "</p>";
        if (!c.found().base.isApprox(Eigen::Isometry3d::Identity(), 1e-9))
            html += "<p>" + tr("Frame 0 is not the world's frame: a base transform, which DH cannot express, places it.") + "</p>";
    }
    return html;
}

QString DhAxesPanel::table() const {
    const DhConstruction& c = *construction_;
    const bool standard = c.found().convention == DhConvention::Standard;
    const int found = c.rowsFound(index_);
    QString html = "<table cellspacing=0 cellpadding=3 border=1 style='border-color:#bbb'><tr><th>i</th>";
    html += standard ? QString("<th>θ<sub>i</sub></th><th>d<sub>i</sub></th><th>a<sub>i</sub></th><th>α<sub>i</sub></th>")
                     : QString("<th>α<sub>i−1</sub></th><th>a<sub>i−1</sub></th><th>θ<sub>i</sub></th><th>d<sub>i</sub></th>");
    html += "</tr>";
    for (int i = 1; i <= c.joints(); ++i) {
        const DhRow& row = c.found().rows[static_cast<std::size_t>(i - 1)];
        const bool revolute = row.type == JointType::Revolute;
        const QString theta = revolute ? withJoint(i, row.theta, degrees(row.theta)) : degrees(row.theta);
        const QString d = revolute ? metres(row.d) : withJoint(i, row.d, metres(row.d));
        QStringList cells =
            standard ? QStringList{theta, d, metres(row.a), degrees(row.alpha)} : QStringList{degrees(row.alpha), metres(row.a), theta, d};
        html += QString("<tr><td align=center>%1</td>").arg(i);
        for (const QString& cell : cells) html += QString("<td align=right>%1</td>").arg(i <= found ? cell : QString("…"));
        html += "</tr>";
    }
    return html + "</table>";
}

}  // namespace ll::ui
