#pragma once
// A robot scene as URDF (lagrangelab export-urdf): a link per DH link with its mass, centre
// of mass and inertia in URDF's convention (an <inertial> frame turned as the DH frame), a
// joint per DH row with its origin from the rows (standard DH: joint i's frame is
// DH frame i−1 turned by θ_i and raised by d_i, so the joint turns about its z; modified
// DH: joint i's frame is DH frame i), viscous and Coulomb friction as <dynamics>, and a
// massless "tool" link on DH frame n. URDF robots feel gravity along −z of the root link:
// when the scene's gravity points elsewhere, a root link "world" is turned so that it
// does (its magnitude is not URDF's to say: 9.81 is assumed, a note says otherwise).
// A joint's motor (its reflected inertia, Jm G²), springs and applied torques have no place
// in URDF: left out, with a note each.
// URDF → scene → URDF → scene keeps B, C and g (tests/core/test_urdf_import).
#include <string>
#include <vector>

#include "core/model/message.hpp"
#include "core/model/scene.hpp"

namespace ll {

struct UrdfExport {
    std::string xml;
    std::vector<Message> notes;  // what URDF cannot hold
};

// Throws InputError when the scene is not a robot (a typed Lagrangian).
UrdfExport exportUrdf(const Scene& scene);

}  // namespace ll
