#pragma once
// What `lagrangelab render` lays over every frame: the scene's name and the simulated
// time (top left, with the playback speed when it is not real time) and the energy
// inset (bottom right, ui/paint/energy_inset.hpp), sized from the frame's height so a 720p
// and a 1080p video look alike. Needs a QGuiApplication (fonts).
#include <array>
#include <memory>

#include <QImage>
#include <QString>

#include "core/simulation/trajectory.hpp"
#include "ui/paint/energy_inset.hpp"

namespace ll::ui {

struct OverlayOptions {
    bool time = true;
    bool energy = true;
    bool name = true;
    bool any() const { return time || energy || name; }
};

class FrameOverlay {
public:
    FrameOverlay(const Trajectory& trajectory, const QString& sceneName, QSize frameSize, const OverlayOptions& options, bool showWork,
                 double speed);
    ~FrameOverlay();

    // Paints onto `frame` (frameSize) for time t with the energies E_kin, E_pot, E, W at t.
    void paint(QImage& frame, double t, const std::array<double, 4>& energies) const;

private:
    QString name_;
    OverlayOptions options_;
    double speed_;
    int fontPixels_;
    std::unique_ptr<EnergyInset> inset_;
    QPoint insetAt_;
};

}  // namespace ll::ui
