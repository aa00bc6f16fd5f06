#pragma once
// What a picked derivation entry (or a picked link) lights up in the 3D picture, as
// plain data a renderer applies (ui/osg_scene): the links whose inertial parameters feed
// the entry, in their own colour and as strong as their share of its value now; the
// other links faded; the axes of the joints whose coordinates it depends on and, in
// another colour, of the joints whose velocities multiply it (a c_ij).
#include <cstdint>
#include <vector>

#include "core/visual/visual_scene.hpp"

namespace ll {

enum class AxisMark { None, Coordinate, Velocity };

struct VisualEmphasis {
    // Per part of the scene: −1 faded (a link or COM that does not feed the entry), 0..1
    // the share of its link, NaN untouched (joints, the pedestal, bodies). Empty: nothing
    // emphasised, every part as built.
    std::vector<float> strength;
    std::vector<AxisMark> axes;  // per part: the axis a joint part draws (None elsewhere)

    bool active() const { return !strength.empty(); }
};

// shares: one per link (0-based), the link's share 0..1 of the entry's value, or
// negative when its parameters do not occur in the entry (empty: no link is emphasised,
// none faded). Bit k of `coordinates` (`velocities`): the entry depends on q_{k+1}
// (q̇_{k+1} multiplies it); a velocity's mark wins over a coordinate's.
VisualEmphasis visualEmphasis(const VisualScene& scene, const std::vector<double>& shares, std::uint64_t coordinates,
                              std::uint64_t velocities);

}  // namespace ll
