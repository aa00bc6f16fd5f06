#include "core/symbolic/body_poses.hpp"

#include "core/io/lagrangian_fields.hpp"

namespace ll::symbolic {

BodyPoses::BodyPoses(const Scene& scene) {
    const LagrangianSpec& spec = scene.lagrangian.value();
    const ParameterTable table = parameterTable(scene);
    const LagrangianSymbols s = lagrangianSymbols(spec.coordinates);
    const GiNaC::lst values = table.values();
    std::vector<GiNaC::ex> outputs;
    for (int b = 0; b < static_cast<int>(spec.bodies.size()); ++b) {
        const VisualBody& body = spec.bodies[b];
        const auto add = [&](const std::string& field, const std::string& text) {
            outputs.push_back(parseLagrangianField(table, s, field, text, LagrangianField::Pose).subs(values));
        };
        for (int k = 0; k < 3; ++k)
            add(lagrangianBodyField(b, "position[" + std::to_string(k + 1) + "]"), body.position[k]);
        for (int k = 0; k < 3; ++k) add(lagrangianBodyField(b, "end[" + std::to_string(k + 1) + "]"), body.end[k]);
        add(lagrangianBodyField(b, "angle"), body.angle);
        shapes_.push_back(body.shape);
        axes_.push_back(body.axis.norm() > 0 ? body.axis.normalized() : Eigen::Vector3d::UnitZ());
    }
    std::vector<GiNaC::symbol> inputs = s.q;
    inputs.push_back(s.t);
    expressions_ = CompiledExpressions(outputs, inputs);
    input_.assign(inputs.size(), 0.0);
    output_.assign(outputs.size(), 0.0);
}

void BodyPoses::evaluate(const Eigen::VectorXd& q, double t, std::vector<BodyPose>& out) const {
    const int n = static_cast<int>(input_.size()) - 1;
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

}  // namespace ll::symbolic
