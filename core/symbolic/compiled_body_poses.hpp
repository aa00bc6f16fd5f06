#pragma once
// The pose expressions of a Lagrangian scene's visual bodies compiled once into
// BodyPoses (core/kinematics): plain data a 3D view evaluates per frame.
#include "core/kinematics/body_poses.hpp"
#include "core/model/scene.hpp"

namespace ll::symbolic {

// Throws InputError (naming lagrangian.bodies[i]...) for an expression that does not
// parse; the scene must have a `lagrangian`. Takes the GiNaC lock.
BodyPoses compileBodyPoses(const Scene& scene);

}  // namespace ll::symbolic
