#include "ui/window/properties_panel.hpp"

#include "ui/window/relabel.hpp"

#include <cmath>

#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include "ui/document/entry_selection.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

PropertiesPanel::PropertiesPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    summary_ = new QLabel(this);
    body_ = new QLabel(this);
    body_->setObjectName("properties");
    body_->setTextFormat(Qt::RichText);
    body_->setWordWrap(true);
    body_->setFont(textbookFont(body_->font()));  // the sentences name q̇ and Ḃ: a font that draws their dots
    body_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    body_->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::LinksAccessibleByMouse);
    connect(body_, &QLabel::linkActivated, this, [this](const QString& link) { emit timePicked(link.toDouble()); });
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(body_);
    layout->addWidget(summary_);
    (*new Relabel(this))([this] { setProperties(properties_); });
    layout->addWidget(scroll, 1);
}

namespace {

QString withUnit(double v, const std::string& unit) {
    return readableNumber(v) + (unit.empty() ? QString() : " " + QString::fromStdString(unit));
}

QString poseText(const Eigen::VectorXd& q) {
    QStringList parts;
    for (int i = 0; i < q.size(); ++i) parts << readableNumber(q[i]);
    return "(" + parts.join(", ") + ")";
}

}  // namespace

void PropertiesPanel::setProperties(std::shared_ptr<const ModelProperties> properties) {
    properties_ = std::move(properties);
    if (!properties_) {
        summary_->setText(tr("Checking the model along the run…"));
        body_->clear();
        return;
    }
    int failed = 0, applied = 0;
    QString html = "<table cellspacing='6'>";
    for (const PropertyCheck& c : properties_->checks) {
        QString badge, detail;
        if (!c.applies) {
            badge = "<span style='color:#777'>" + tr("n/a") + "</span>";
            detail = tr("does not apply to a typed Lagrangian (it has no links to recurse over)");
        } else {
            ++applied;
            failed += !c.passed;
            badge = c.passed ? "<span style='color:#1a7f37;font-weight:bold'>✔ " + tr("pass") + "</span>"
                             : "<span style='color:#c62828;font-weight:bold'>✘ " + tr("fail") + "</span>";
            detail = QString("<tt>%1</tt> = %2 (%3 %4)")
                         .arg(QString::fromStdString(c.key), withUnit(c.value, c.unit), c.atLeast ? tr("must stay above") : tr("tolerance"),
                              withUnit(c.tolerance, c.unit));
            if (c.q.size() > 0)
                detail +=
                    " · " +
                    tr("worst at <a href='%1'>t = %2 s</a>, q = %3").arg(c.time, 0, 'g', 17).arg(readableNumber(c.time), poseText(c.q));
        }
        html +=
            QString("<tr><td valign='top' style='white-space:nowrap'>%1</td><td><b>%2</b><br>%3<br>"
                    "<span style='color:#555'>%4</span></td></tr>")
                .arg(badge, QString::fromStdString(c.title).toHtmlEscaped(), detail, QString::fromStdString(c.explanation).toHtmlEscaped());
    }
    html += "</table>";
    body_->setText(html);
    summary_->setText(failed == 0 ? tr("All %1 properties that apply hold along the run.").arg(applied)
                                  : tr("%n of the properties fails along the run: see where.", "", failed));
}

QString PropertiesPanel::text() const { return summary_->text() + "\n" + body_->text(); }

}  // namespace ll::ui
