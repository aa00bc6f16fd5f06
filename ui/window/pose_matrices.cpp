#include "ui/window/pose_matrices.hpp"

#include <algorithm>

#include <QMouseEvent>
#include <QPainter>

namespace ll::ui {

namespace {
constexpr double kMargin = 8;
double baseScale() { return 14.0 / mathUnitsPerEm; }  // device px per layout unit at full size
}  // namespace

PoseMatrices::PoseMatrices(QWidget* parent) : QWidget(parent) {
    setObjectName("pose-matrices");
    setBackgroundRole(QPalette::Base);
    setAutoFillBackground(true);
}

void PoseMatrices::setStep(present::DisplayStep step) {
    step_ = std::move(step);
    layoutLines();
    setMinimumHeight(sizeHint().height());  // in a scroll area: all of B, scrolled
    updateGeometry();
    update();
}

void PoseMatrices::setMark(std::optional<present::Quantity> quantity, int row, int col) {
    markQuantity_ = quantity;
    markRow_ = row;
    markCol_ = col;
    update();
}

void PoseMatrices::layoutLines() {
    lines_.clear();
    for (const present::DisplayItem& item : step_.items) lines_.push_back({layoutMath(*item.equation), {}, 1});
}

QSize PoseMatrices::sizeHint() const {
    double h = kMargin;
    for (const Line& l : lines_) h += (l.box.height() + 0.5 * mathUnitsPerEm) * baseScale();
    return QSize(320, static_cast<int>(h + kMargin));
}

void PoseMatrices::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(palette().color(QPalette::Text));
    double y = kMargin;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        Line& line = lines_[i];
        // a line wider than the widget is drawn smaller, never cut
        line.scale = std::min(baseScale(), (width() - 2 * kMargin) / std::max(1.0, line.box.width));
        line.origin = QPointF(kMargin, y + line.box.ascent * line.scale);
        const present::DisplayItem& item = step_.items[i];
        if (markQuantity_ && *markQuantity_ == item.quantity)
            for (const MathRegion& r : line.box.regions)
                if (markRow_ < 0 || (r.row == markRow_ && r.col == std::max(markCol_, 0)))
                    p.fillRect(QRectF(line.origin + r.rect.topLeft() * line.scale, r.rect.size() * line.scale), QColor(255, 214, 90, 150));
        paintMath(p, line.box, line.origin, line.scale);
        y += (line.box.height() + 0.5 * mathUnitsPerEm) * line.scale;
    }
}

void PoseMatrices::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        const Line& line = lines_[i];
        for (const MathRegion& r : line.box.regions)
            if (QRectF(line.origin + r.rect.topLeft() * line.scale, r.rect.size() * line.scale).contains(event->position())) {
                emit entryPicked(step_.items[i].quantity, r.row, r.col);
                return;
            }
        const QRectF whole(line.origin.x(), line.origin.y() - line.box.ascent * line.scale, line.box.width * line.scale,
                           line.box.height() * line.scale);
        if (whole.contains(event->position())) {  // a scalar (E_pot): the item
            emit entryPicked(step_.items[i].quantity, -1, -1);
            return;
        }
    }
}

QString PoseMatrices::text() const {
    QStringList out;
    for (const present::DisplayItem& item : step_.items) {
        const std::string label = present::renderDisplay(*item.equation->children[0], present::DisplayStyle::Text);
        out << QString::fromStdString(label + " = " + present::renderDisplay(*item.value, present::DisplayStyle::Text));
    }
    return out.join("\n\n");
}

}  // namespace ll::ui
