#pragma once
// The slide-ready frame of `render --layout composite` and File → Export → Video
// (composite): one picture holding the 3D view (left 60 %, full height, with the name
// and time in its corner), and beside it the derivation step's key equation (its title,
// its general formula and as many of its equations as fit, typeset as the window does)
// above the energy plot with a cursor moving along it. Sizes follow the frame's height,
// so 1280×720 and 1920×1080 look alike. Needs a QGuiApplication (fonts).
#include <array>
#include <memory>

#include <QImage>
#include <QRect>
#include <QString>

#include "core/present/display_document.hpp"
#include "core/simulation/trajectory.hpp"
#include "ui/paint/energy_inset.hpp"
#include "ui/paint/frame_overlay.hpp"

namespace ll::ui {

// Where the parts of a composite frame of `size` go.
struct CompositeLayout {
    QRect view, equation, plot;
    static CompositeLayout forSize(QSize size);
};

class CompositeFrame {
public:
    // `step` (may be null: an empty equation panel) is read here only; `language` the
    // document's, for the names of a matrix's entries listed one by one.
    CompositeFrame(const Trajectory& trajectory, const QString& sceneName, QSize frameSize, const present::DisplayStep* step,
                   present::Language language, bool showWork, double speed);
    ~CompositeFrame();

    const CompositeLayout& layout() const { return layout_; }
    // The full frame: `view` (layout().view's size, the 3D render) at the left, the time and
    // name over it, the equation panel and the energy plot with the cursor at t.
    void paint(QImage& frame, const QImage& view, double t, const std::array<double, 4>& energies) const;

private:
    CompositeLayout layout_;
    QSize size_;
    QImage panel_;                           // the equation panel and the plot's frame, painted once
    std::unique_ptr<FrameOverlay> overlay_;  // name and time over the view
    std::unique_ptr<EnergyInset> plot_;
};

}  // namespace ll::ui
