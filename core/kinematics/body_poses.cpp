#include "core/kinematics/body_poses.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace ll {

BodyPoses::BodyPoses(std::vector<BodyShape> shapes, std::vector<Eigen::Vector3d> axes, ExpressionTape expressions)
    : shapes_(std::move(shapes)), axes_(std::move(axes)), expressions_(std::move(expressions)) {
    const int bodies = static_cast<int>(shapes_.size());
    if (static_cast<int>(axes_.size()) != bodies || expressions_.outputCount() != 7 * bodies || expressions_.inputCount() < 1)
        throw std::invalid_argument("BodyPoses: " + std::to_string(bodies) + " shapes, " + std::to_string(axes_.size()) + " axes and " +
                                    std::to_string(expressions_.outputCount()) + " pose expressions do not fit");
    input_.assign(expressions_.inputCount(), 0.0);
    output_.assign(expressions_.outputCount(), 0.0);
}

void BodyPoses::evaluate(const Eigen::VectorXd& q, double t, std::vector<BodyPose>& out) const {
    const int n = coordinates();
    if (q.size() != n)
        throw std::invalid_argument("q has " + std::to_string(q.size()) + " entries; the system has " + std::to_string(n) + " coordinates");
    for (int i = 0; i < n; ++i) input_[i] = q[i];
    input_[n] = t;
    expressions_.evaluate(input_.data(), output_.data());
    out.resize(shapes_.size());
    for (std::size_t b = 0; b < shapes_.size(); ++b) {
        const double* v = output_.data() + 7 * b;
        const Eigen::Vector3d start(v[0], v[1], v[2]), end(v[3], v[4], v[5]);
        BodyPose& pose = out[b];
        pose.pose.setIdentity();
        if (shapes_[b] == BodyShape::Rod) {
            const Eigen::Vector3d along = end - start;
            pose.length = along.norm();
            pose.pose.translation() = (start + end) / 2;
            if (pose.length > 0)
                pose.pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), along).toRotationMatrix();
        } else {
            pose.length = 0.0;
            pose.pose.translation() = start;
            pose.pose.linear() = Eigen::AngleAxisd(v[6], axes_[b]).toRotationMatrix();
        }
    }
}

}  // namespace ll
