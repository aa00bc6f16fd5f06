#include "core/visual/visual_emphasis.hpp"

#include <cmath>
#include <limits>

namespace ll {

VisualEmphasis visualEmphasis(const VisualScene& scene, const std::vector<double>& shares, std::uint64_t coordinates,
                              std::uint64_t velocities) {
    VisualEmphasis e;
    e.strength.assign(scene.parts.size(), std::numeric_limits<float>::quiet_NaN());
    e.axes.assign(scene.parts.size(), AxisMark::None);
    for (std::size_t i = 0; i < scene.parts.size(); ++i) {
        const VisualPart& part = scene.parts[i];
        const int k = part.coordinate;
        if (k < 0 || k >= 64) continue;
        if ((part.role == PartRole::Link || part.role == PartRole::CentreOfMass) && k < static_cast<int>(shares.size()))
            e.strength[i] = shares[k] < 0 ? -1.0f : static_cast<float>(std::min(1.0, shares[k]));
        if (part.role == PartRole::Joint) {
            if ((velocities >> k) & 1u) e.axes[i] = AxisMark::Velocity;
            else if ((coordinates >> k) & 1u) e.axes[i] = AxisMark::Coordinate;
        }
    }
    return e;
}

}  // namespace ll
