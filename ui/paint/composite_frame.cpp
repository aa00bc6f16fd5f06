#include "ui/paint/composite_frame.hpp"

#include <algorithm>

#include <QPainter>

#include "core/present/message_text.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

CompositeLayout CompositeLayout::forSize(QSize size) {
    CompositeLayout l;
    const int w = size.width(), h = size.height();
    const int viewWidth = w * 60 / 100, margin = std::max(6, h / 60);
    l.view = QRect(0, 0, viewWidth, h);
    const int right = viewWidth + margin, columnWidth = w - right - margin;
    const int equationHeight = h * 48 / 100;
    l.equation = QRect(right, margin, columnWidth, equationHeight - margin);
    l.plot = QRect(right, equationHeight + margin, columnWidth, h - equationHeight - 2 * margin);
    return l;
}

CompositeFrame::CompositeFrame(const Trajectory& trajectory, const QString& sceneName, QSize frameSize, const present::DisplayStep* step,
                               present::Language language, bool showWork, double speed)
    : layout_(CompositeLayout::forSize(frameSize)), size_(frameSize) {
    const int h = frameSize.height();
    OverlayOptions overlay;
    overlay.energy = false;  // the plot stands beside the view
    overlay_ = std::make_unique<FrameOverlay>(trajectory, sceneName, layout_.view.size(), overlay, showWork, speed);
    plot_ = std::make_unique<EnergyInset>(trajectory, showWork, layout_.plot.size(), std::max(10, h / 40));

    // The panel, once: background, the step's title, its general formula, its equations.
    panel_ = QImage(frameSize, QImage::Format_RGB32);
    panel_.fill(QColor(247, 248, 250));
    QPainter p(&panel_);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::white);
    const double round = h / 90.0;
    p.drawRoundedRect(QRectF(layout_.equation).adjusted(-2, -2, 2, 2), round, round);
    p.setPen(QColor(25, 25, 35));
    if (!step) return;
    const QRectF box = QRectF(layout_.equation).adjusted(h / 60.0, h / 80.0, -h / 60.0, -h / 80.0);
    const double em = h / 28.0;                   // 26 px at 720p, 39 px at 1080p
    const double scale = em / mathUnitsPerEm;     // px per layout unit
    const double maxWidth = box.width() / scale;  // units
    double y = box.top();
    const auto place = [&](const MathBox& line, double gapAbove) {
        if (y + (gapAbove + line.ascent + line.descent) * scale > box.bottom()) return false;
        y += (gapAbove + line.ascent) * scale;
        paintMath(p, line, QPointF(box.left(), y), scale);
        y += line.descent * scale;
        return true;
    };
    // In the document's own language, as its title is (the derivation view's heading).
    const QString title = QString::fromStdString(present::messageText(MessageId::DocumentStep, language) + " " +
                                                 std::to_string(step->number) + ". " + present::messageText(step->title, language));
    QFont titleFont = textbookFont(p.font());
    titleFont.setPixelSize(static_cast<int>(0.8 * em));
    titleFont.setBold(true);
    p.setFont(titleFont);
    const QRectF titleBox = p.boundingRect(box, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, title);
    p.drawText(box, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, title);
    y = titleBox.bottom();
    if (step->formula)
        for (const MathBox& f : layoutFormula(*step->formula, maxWidth)) place(f, 10);
    for (const present::DisplayItem& item : step->items) {
        if (!item.equation) continue;
        // A matrix too wide is listed entry by entry (as the window does).
        std::vector<MathBox> lines = layoutItem(item, maxWidth, language);
        // An equation is shown whole or not at all.
        double need = 0, widest = 0;
        for (const MathBox& l : lines) need += (12 + l.ascent + l.descent) * scale, widest = std::max(widest, l.width);
        if (widest > maxWidth) continue;     // a line that cannot break
        if (y + need > box.bottom()) break;  // it fits whole: every line is placed
        for (const MathBox& l : lines) place(l, 12);
    }
}

CompositeFrame::~CompositeFrame() = default;

void CompositeFrame::paint(QImage& frame, const QImage& view, double t, const std::array<double, 4>& energies) const {
    if (frame.size() != size_ || frame.format() != view.format()) frame = QImage(size_, view.format());
    {
        QPainter p(&frame);
        p.drawImage(0, 0, panel_);
        p.drawImage(layout_.view.topLeft(), view);
    }
    overlay_->paint(frame, t, energies);  // the name and time in the view's corner (at the frame's origin)
    QPainter p(&frame);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);
    plot_->paint(p, layout_.plot.topLeft(), t, energies);
}

}  // namespace ll::ui
