#pragma once
// The visual bodies of a Lagrangian scene (LagrangianSpec::bodies) posed at a state:
// their position, end and angle expressions compiled once into a tape by the symbolic
// layer (core/symbolic/compiled_body_poses: compileBodyPoses), so a 3D view can animate
// a trajectory sample by sample with no GiNaC. Plain data: copy it for another thread.
#include <vector>

#include <Eigen/Geometry>

#include "core/math/expression_tape.hpp"
#include "core/model/lagrangian_spec.hpp"

namespace ll {

struct BodyPose {
    // Box, sphere, cylinder: the centre at `position`, turned by `angle` about `axis`.
    // Rod: the centre halfway between `position` and `end`, its z axis along the rod.
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    double length = 0.0;  // rod only: |end − position|
};

class BodyPoses {
public:
    BodyPoses() = default;
    // One shape and unit axis per body; the tape's inputs are the n coordinates and t,
    // its outputs per body position (3), end (3) and angle. Throws std::invalid_argument
    // when the sizes disagree.
    BodyPoses(std::vector<BodyShape> shapes, std::vector<Eigen::Vector3d> axes, ExpressionTape expressions);

    int count() const { return static_cast<int>(shapes_.size()); }
    int coordinates() const { return static_cast<int>(input_.size()) - 1; }
    // out[i] is body i at q (one value per coordinate) and time t. No allocation once
    // out has count() entries. Throws std::invalid_argument for a q of the wrong size.
    void evaluate(const Eigen::VectorXd& q, double t, std::vector<BodyPose>& out) const;

private:
    std::vector<BodyShape> shapes_;
    std::vector<Eigen::Vector3d> axes_;  // unit
    ExpressionTape expressions_;         // per body: position (3), end (3), angle
    mutable std::vector<double> input_, output_;
};

}  // namespace ll
