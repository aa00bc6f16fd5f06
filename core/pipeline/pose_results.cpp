#include "core/pipeline/pose_results.hpp"

#include <functional>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/quantity_units.hpp"
#include "core/model/robot_data.hpp"
#include "core/present/labels.hpp"
#include "core/present/step_formula_text.hpp"

namespace ll {
namespace {

using present::DisplayItem;
using present::DisplayKind;
using present::DisplayPtr;

// v with 4 significant digits: 0.1234, 12.35, 1.235·10⁻⁵; a negative number as the
// display builder writes one (a one-term sum with its minus sign).
DisplayPtr number(double v) {
    if (v == 0) v = 0;  // no −0
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", std::abs(v));
    std::string digits = buffer, exponent;
    if (const auto e = digits.find('e'); e != std::string::npos) {
        exponent = std::to_string(std::stoi(digits.substr(e + 1)));
        digits = digits.substr(0, e);
    }
    std::snprintf(buffer, sizeof buffer, "%.17g", std::abs(v));
    DisplayPtr magnitude = present::displayNumber(digits, digits, buffer, exponent);
    return v >= 0 ? magnitude : present::displayNegated(magnitude);
}

// Entries below 1e-12 of the matrix's largest are rounding (cos(π/2) = 6·10⁻¹⁷): shown 0.
DisplayPtr matrix(const Eigen::MatrixXd& m) {
    const double negligible = 1e-12 * (m.size() > 0 ? m.cwiseAbs().maxCoeff() : 0.0);
    auto node = std::make_shared<present::DisplayNode>();
    node->kind = DisplayKind::Matrix;
    for (int i = 0; i < m.rows(); ++i) {
        std::vector<DisplayPtr> row;
        for (int j = 0; j < m.cols(); ++j) row.push_back(number(std::abs(m(i, j)) <= negligible ? 0.0 : m(i, j)));
        node->rows.push_back(std::move(row));
    }
    return node;
}

DisplayItem item(const std::string& name, present::Quantity quantity, const std::string& latexName, DisplayPtr value, Message note) {
    DisplayItem it;
    it.name = name;
    it.latexName = latexName;
    it.quantity = quantity;
    it.value = value;
    it.equation = present::displayEquation(present::displayLabel(name, latexName), value);
    it.note = std::move(note);
    return it;
}

// The unit of a joint coordinate's generalized force, velocity… by joint type.
Message perJoint(const Scene& scene, const char* revolute, const char* prismatic) {
    bool anyRevolute = false, anyPrismatic = false;
    for (const auto& j : scene.robot.joints) (j.dh.type == JointType::Revolute ? anyRevolute : anyPrismatic) = true;
    if (anyRevolute && anyPrismatic) return message(MessageId::PoseUnitsByJointType, revolute, prismatic);
    return literal(anyPrismatic ? prismatic : revolute);
}

// value, a thin space, the unit: a row the typesetter sets side by side.
DisplayPtr withUnit(DisplayPtr value, const std::string& unit) {
    if (unit.empty()) return value;
    auto u = std::make_shared<present::DisplayNode>();
    u->kind = DisplayKind::Raw;
    u->text = u->plain = " " + unit;
    u->latex = "\\,\\mathrm{" + unit + "}";
    // The typesetter sets the children side by side; text and LaTeX print the whole.
    auto row = std::make_shared<present::DisplayNode>();
    row->kind = DisplayKind::Raw;
    row->text = present::renderDisplay(*value, present::DisplayStyle::Text) + u->text;
    row->latex = present::renderDisplay(*value, present::DisplayStyle::Latex) + u->latex;
    row->plain = present::renderDisplay(*value, present::DisplayStyle::Plain);
    row->children = {std::move(value), u};
    return row;
}

// m with each entry's unit unit(i, j): once after it when they are all alike.
DisplayPtr matrixWithUnits(const Eigen::MatrixXd& m, const std::function<std::string(int, int)>& unit) {
    bool alike = true;
    for (int i = 0; i < m.rows(); ++i)
        for (int j = 0; j < m.cols(); ++j) alike = alike && unit(i, j) == unit(0, 0);
    DisplayPtr plain = matrix(m);
    if (alike) return withUnit(plain, unit(0, 0));
    auto node = std::make_shared<present::DisplayNode>(*plain);
    for (int i = 0; i < m.rows(); ++i)
        for (int j = 0; j < m.cols(); ++j) node->rows[i][j] = withUnit(node->rows[i][j], unit(i, j));
    return node;
}

}  // namespace

present::DisplayStep teachMatrices(const Scene& scene, const Eigen::VectorXd& q) {
    const int n = scene.robot.dof();
    if (scene.lagrangian || n == 0 || q.size() != n) throw std::invalid_argument("teachMatrices: a robot scene and one value per joint");
    RobotData data(scene.robot);
    forwardKinematics(scene.robot, data, q);
    computeMassMatrix(scene.robot, data);
    computePotentialGradient(scene.robot, data, scene.effects, q);
    const auto revolute = [&](int j) { return scene.robot.joints[static_cast<std::size_t>(j)].dh.type == JointType::Revolute; };
    present::DisplayStep step;
    step.number = poseStepNumber;
    step.title = MessageId::TitlePoseMatrices;
    step.items.push_back(item("E_pot", present::Quantity::PotentialEnergy, "E_{\\mathrm{pot}}",
                              withUnit(number(potentialEnergy(scene.robot, data, scene.effects, q)), "J"), {}));
    step.items.push_back(item("g", present::Quantity::GravityVector, "g(q)",
                              matrixWithUnits(data.g, [&](int i, int) { return forceUnit(revolute(i)); }), {}));
    step.items.push_back(item("B", present::Quantity::MassMatrix, "B(q)",
                              matrixWithUnits(data.B, [&](int i, int j) { return massMatrixUnit(revolute(i), revolute(j)); }), {}));
    return step;
}

present::DisplayStep poseResults(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    const int n = scene.robot.dof();
    if (scene.lagrangian || n == 0) throw std::invalid_argument("poseResults: a robot scene is needed");
    if (q.size() != n || qd.size() != n) throw std::invalid_argument("poseResults: q and q̇ need one value per joint");
    RobotData data(scene.robot);
    forwardKinematics(scene.robot, data, q);
    computeMassMatrix(scene.robot, data);
    computeCoriolisMatrix(scene.robot, data, qd);
    computePotentialGradient(scene.robot, data, scene.effects, q);
    const double ekin = kineticEnergy(data, qd), epot = potentialEnergy(scene.robot, data, scene.effects, q);

    // q shown in degrees for revolute joints (as the teach sliders), metres for prismatic.
    Eigen::VectorXd shown = q;
    for (int i = 0; i < n; ++i)
        if (scene.robot.joints[i].dh.type == JointType::Revolute) shown[i] *= 180 / std::numbers::pi;

    present::DisplayStep step;
    step.number = poseStepNumber;
    step.title = MessageId::TitlePoseResults;
    step.general =
        stepFormula("«1»", "«1»", {formulaWords(MessageId::FormulaPoseResults)},
                    {formulaWords(MessageId::FormulaAtThisPose,
                                  {"«B»(q),\\ C(q,\\dot q),\\ «g»(q),\\ E_{\\mathrm{kin}},\\ E_{\\mathrm{pot}}", "q, \\dot q"})});
    // In English here; the window writes it in its language (a sentence, not typeset).
    step.formulaText = present::formulaText(step.general, {});
    step.formulaLatex = present::formulaLatex(step.general, {});
    step.items.push_back(item("q", present::Quantity::Coordinates, "q", matrix(shown), perJoint(scene, "°", "m")));
    step.items.push_back(item("qd", present::Quantity::Velocities, "\\dot{q}", matrix(qd), perJoint(scene, "rad/s", "m/s")));
    step.items.push_back(item("Ekin", present::Quantity::KineticEnergy, "E_{\\mathrm{kin}}", number(ekin), literal("J")));
    step.items.push_back(item("Epot", present::Quantity::PotentialEnergy, "E_{\\mathrm{pot}}", number(epot), literal("J")));
    bool mixed = false;
    for (const auto& j : scene.robot.joints) mixed |= j.dh.type != scene.robot.joints[0].dh.type;
    step.items.push_back(
        item("B", present::Quantity::MassMatrix, "B(q)", matrix(data.B),
             mixed ? message(MessageId::PoseUnitsWhereTheyMeet, perJoint(scene, "kg·m²", "kg"), "kg·m") : perJoint(scene, "kg·m²", "kg")));
    step.items.push_back(item("C", present::Quantity::CoriolisMatrix, "C(q,\\dot{q})", matrix(data.C), perJoint(scene, "kg·m²/s", "kg/s")));
    step.items.push_back(item("g", present::Quantity::GravityVector, "g(q)", matrix(data.g), perJoint(scene, "N·m", "N")));
    return step;
}

}  // namespace ll
