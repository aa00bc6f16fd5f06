#pragma once
// The visual bodies of a Lagrangian scene (LagrangianSpec::bodies) posed at a state:
// their position, end and angle expressions compiled once (CompiledExpressions), so a
// 3D view can animate a trajectory sample by sample without GiNaC.
#include <vector>

#include <Eigen/Geometry>

#include "core/model/scene.hpp"
#include "core/symbolic/compiled_expressions.hpp"

namespace ll::symbolic {

struct BodyPose {
    // Box, sphere, cylinder: the centre at `position`, turned by `angle` about `axis`.
    // Rod: the centre halfway between `position` and `end`, its z axis along the rod.
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    double length = 0.0;  // rod only: |end − position|
};

class BodyPoses {
public:
    // Throws InputError (naming lagrangian.bodies[i]...) for an expression that does not
    // parse; the scene must have a `lagrangian`.
    explicit BodyPoses(const Scene& scene);

    int count() const { return static_cast<int>(shapes_.size()); }
    // out[i] is body i at q (one value per coordinate) and time t. No allocation once
    // out has count() entries.
    void evaluate(const Eigen::VectorXd& q, double t, std::vector<BodyPose>& out) const;

private:
    std::vector<BodyShape> shapes_;
    std::vector<Eigen::Vector3d> axes_;  // unit
    CompiledExpressions expressions_;    // per body: position (3), end (3), angle
    mutable std::vector<double> input_, output_;
};

}  // namespace ll::symbolic
