#include "core/symbolic/compiled_body_poses.hpp"

#include "core/symbolic/compiled_expressions.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_fields.hpp"

namespace ll::symbolic {

BodyPoses compileBodyPoses(const Scene& scene) {
    const auto lock = lockGinac();
    const LagrangianSpec& spec = scene.lagrangian.value();
    const ParameterTable table = parameterTable(scene);
    const LagrangianSymbols s = lagrangianSymbols(spec.coordinates);
    const GiNaC::lst values = table.values();
    std::vector<GiNaC::ex> outputs;
    std::vector<BodyShape> shapes;
    std::vector<Eigen::Vector3d> axes;
    for (int b = 0; b < static_cast<int>(spec.bodies.size()); ++b) {
        const VisualBody& body = spec.bodies[b];
        const auto add = [&](const std::string& field, const std::string& text) {
            outputs.push_back(parseLagrangianField(table, s, field, text, LagrangianField::Pose).subs(values));
        };
        for (int k = 0; k < 3; ++k) add(lagrangianBodyField(b, "position[" + std::to_string(k) + "]"), body.position[k]);
        for (int k = 0; k < 3; ++k) add(lagrangianBodyField(b, "end[" + std::to_string(k) + "]"), body.end[k]);
        add(lagrangianBodyField(b, "angle"), body.angle);
        shapes.push_back(body.shape);
        axes.push_back(body.axis.norm() > 0 ? body.axis.normalized() : Eigen::Vector3d::UnitZ());
    }
    std::vector<GiNaC::symbol> inputs = s.q;
    inputs.push_back(s.t);
    return BodyPoses(std::move(shapes), std::move(axes), compileExpressions(outputs, inputs));
}

}  // namespace ll::symbolic
