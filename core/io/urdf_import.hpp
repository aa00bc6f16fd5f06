#pragma once
// A URDF robot as a scene (Debian's liburdfdom reads the file): the chain of joints from a
// base link to a tip link becomes joint axes at home, and the axes a DH table by the
// textbook's rules (core/kinematics/dh_from_axes.hpp); each moving joint's link, with the
// links fixed to it lumped in (masses added, the centre of mass combined, the inertias
// moved to it by the parallel-axis theorem), is re-expressed in its DH frame. URDF's
// joint damping and friction become viscous and Coulomb friction; gravity is −9.81 m/s²
// along the root link's z, as URDF robots stand (turned into the base link's frame when
// --base names another link). Joint limits have no place in a scene
// and are not kept. Bad input throws InputError naming the file or the option (--base,
// --tip) and the value.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/kinematics/dh_from_axes.hpp"
#include "core/model/message.hpp"
#include "core/model/scene.hpp"

namespace ll {

struct UrdfImportOptions {
    std::string base;  // the chain's first link; the root link when empty
    std::string tip;   // its last link; when empty the chain follows the only branch that moves
    DhConvention convention = DhConvention::Standard;
};

struct UrdfImport {
    Scene scene;
    DhFromAxes dh;                        // the frames and why each went where it went
    std::string baseLink, tipLink;        // the chain's ends
    std::vector<std::string> jointNames;  // the URDF's moving joints, joint 1 first
    // Each URDF link of the chain at home in the base link's frame (the overlay of the
    // URDF's own frames on the DH frames), in chain order.
    std::vector<std::pair<std::string, Eigen::Isometry3d>> linkFrames;
    std::vector<Message> notes;  // what was left out, said once each
};

// `xml` is the URDF's text; `path` names it in messages (and is where relative paths
// would be resolved).
UrdfImport importUrdf(const std::string& xml, const std::string& path, const UrdfImportOptions& options);
UrdfImport importUrdfFile(const std::string& path, const UrdfImportOptions& options);

}  // namespace ll
