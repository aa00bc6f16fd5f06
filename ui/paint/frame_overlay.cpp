#include "ui/paint/frame_overlay.hpp"

#include <algorithm>

#include <QCoreApplication>
#include <QPainter>

namespace ll::ui {

FrameOverlay::FrameOverlay(const Trajectory& trajectory, const QString& sceneName, QSize frameSize, const OverlayOptions& options,
                           bool showWork, double speed)
    : name_(sceneName), options_(options), speed_(speed), fontPixels_(std::max(9, frameSize.height() / 42)) {
    if (options_.energy) {
        const QSize size(std::clamp(frameSize.width() * 32 / 100, 120, 900), std::clamp(frameSize.height() * 30 / 100, 80, 600));
        inset_ = std::make_unique<EnergyInset>(trajectory, showWork, size, std::max(8, fontPixels_ * 85 / 100));
        const int margin = fontPixels_;
        insetAt_ = QPoint(frameSize.width() - size.width() - margin, frameSize.height() - size.height() - margin);
    }
}

FrameOverlay::~FrameOverlay() = default;

void FrameOverlay::paint(QImage& frame, double t, const std::array<double, 4>& energies) const {
    if (!options_.any()) return;
    QPainter p(&frame);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);
    const int f = fontPixels_;
    QStringList lines;
    if (options_.name && !name_.isEmpty()) lines << name_;
    if (options_.time) {
        QString time = QCoreApplication::translate("FrameOverlay", "t = %1 s").arg(t, 0, 'f', 2);
        if (std::abs(speed_ - 1) > 1e-12) time += QCoreApplication::translate("FrameOverlay", "   (%1× real time)").arg(speed_, 0, 'g', 3);
        lines << time;
    }
    if (!lines.isEmpty()) {
        QFont bold = p.font();
        bold.setPixelSize(f);
        bold.setBold(true);
        QFont plain = bold;
        plain.setBold(false);
        double width = 0;
        for (int i = 0; i < lines.size(); ++i)
            width = std::max(width, QFontMetricsF(i == 0 && options_.name ? bold : plain).horizontalAdvance(lines[i]));
        const double lineHeight = 1.35 * f;
        const QRectF box(f * 0.6, f * 0.6, width + 1.2 * f, lines.size() * lineHeight + 0.5 * f);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 210));
        p.drawRoundedRect(box, 0.4 * f, 0.4 * f);
        p.setPen(QColor(25, 25, 35));
        for (int i = 0; i < lines.size(); ++i) {
            p.setFont(i == 0 && options_.name && !name_.isEmpty() ? bold : plain);
            p.drawText(QPointF(box.left() + 0.6 * f, box.top() + 0.25 * f + (i + 0.78) * lineHeight), lines[i]);
        }
    }
    if (inset_) inset_->paint(p, insetAt_, t, energies);
}

}  // namespace ll::ui
