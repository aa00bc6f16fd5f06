#include "core/model/validation.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "core/model/quantity_units.hpp"
#include "core/model/unit_slips.hpp"
#include "core/model/usable_number.hpp"

namespace ll {
namespace {

void error(std::vector<Diagnostic>& out, std::string field, Message message, Message hint = {}) {
    out.push_back({Severity::Error, std::move(field), std::move(message), std::move(hint)});
}

void warning(std::vector<Diagnostic>& out, std::string field, Message message, Message hint = {}) {
    out.push_back({Severity::Warning, std::move(field), std::move(message), std::move(hint)});
}

// Finite and not subnormal (core/model/usable_number.hpp).
void requireFinite(std::vector<Diagnostic>& out, const std::string& field, double value) {
    if (auto why = unusableNumber(value)) error(out, field, *why);
}

// A magnitude outside any physical range for its unit is named as such, before a later
// check (a singular B, a unit slip) could blame something else for it. Zero is allowed
// (a massless link, a length not used); a value beyond `largest` or, not zero, below
// `smallest` is an error.
struct Range {
    MessageId quantity;  // its name: "length", "mass", ...
    const char* unit;
    double smallest, largest;
};
constexpr Range kLength{MessageId::QuantityLength, "m", 1e-9, 1e4};
constexpr Range kMass{MessageId::QuantityMass, "kg", 1e-9, 1e9};
constexpr Range kInertia{MessageId::QuantityInertia, "kg m²", 1e-15, 1e9};
constexpr Range kGravity{MessageId::QuantityGravity, "m/s²", 1e-6, 1e3};

// Whether `value` is in range; if not, the error says so (finite values only: the
// caller's requireFinite names the rest).
bool inRange(std::vector<Diagnostic>& out, const std::string& field, double value, const Range& r) {
    using enum MessageId;
    const double a = std::abs(value);
    if (!std::isfinite(value) || a == 0.0 || (a >= r.smallest && a <= r.largest)) return true;
    const bool large = a > r.largest;
    out.push_back(
        {Severity::Error, field, message(large ? AbsurdlyLarge : AbsurdlySmall, r.quantity, value, r.unit),
         large ? message(NoPhysicalAbove, r.quantity, r.largest, r.unit) : message(NoPhysicalBelow, r.quantity, r.smallest, r.unit)});
    return false;
}

void validateInertia(std::vector<Diagnostic>& out, int j, const Eigen::Matrix3d& I) {
    using enum MessageId;
    const std::string field = jointField(j, "inertia");
    const double scale = std::max(I.cwiseAbs().maxCoeff(), 1e-300);
    if ((I - I.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
        error(out, field, InertiaNotSymmetric);
        return;
    }
    const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
    if (moments.minCoeff() < -1e-12 * scale) {
        error(out, field, message(InertiaNotPositiveSemidefinite, moments[0], moments[1], moments[2]), InertiaOffDiagonalHint);
        return;
    }
    const double tol = 1e-9 * scale;
    const double a = moments[0], b = moments[1], c = moments[2];
    if (a + b < c - tol) warning(out, field, message(TriangleInequalityViolated, a, b, c), NoPhysicalBodyHasThisInertia);
}

// A motor's armature adds Jm G² to b_jj: it must be a finite number >= 0.
void validateMotor(std::vector<Diagnostic>& out, int j, const JointMotor& motor) {
    using enum MessageId;
    if (!motor.fromMotor) {
        requireFinite(out, jointField(j, "armature"), motor.inertia);
        if (motor.inertia < 0) error(out, jointField(j, "armature"), message(ArmatureNegative, motor.inertia));
        return;
    }
    requireFinite(out, jointField(j, "motor.inertia"), motor.inertia);
    requireFinite(out, jointField(j, "motor.gear_ratio"), motor.gearRatio);
    if (motor.inertia < 0) error(out, jointField(j, "motor.inertia"), message(RotorInertiaNegative, motor.inertia));
    if (motor.gearRatio == 0) error(out, jointField(j, "motor.gear_ratio"), GearRatioZero);
}

// The structure of a hand-typed Lagrangian; its expressions are checked when they are
// parsed (scene file) and derived (core/symbolic/lagrangian_derivation).
void validateLagrangian(std::vector<Diagnostic>& out, const Scene& scene) {
    using enum MessageId;
    const LagrangianSpec& l = *scene.lagrangian;
    if (!scene.robot.joints.empty()) error(out, "robot", RobotAndLagrangianBoth);
    if (l.coordinates.empty()) error(out, "lagrangian.coordinates", LagrangianNeedsCoordinate);
    if (!l.forces.empty() && l.forces.size() != l.coordinates.size())
        error(out, "lagrangian.forces", message(ForcesOnePerCoordinate, l.forces.size(), l.coordinates.size()));
    for (size_t b = 0; b < l.bodies.size(); ++b) {
        const VisualBody& body = l.bodies[b];
        const std::string f = "lagrangian.bodies[" + std::to_string(b) + "]";
        if (static_cast<int>(body.size.size()) != sizeCount(body.shape))
            error(out, f + ".size", message(ShapeTakesNumbers, toString(body.shape), sizeCount(body.shape), body.size.size()));
        for (size_t k = 0; k < body.size.size(); ++k)
            if (!(std::isfinite(body.size[k]) && body.size[k] > 0))
                error(out, f + ".size[" + std::to_string(k) + "]", message(MustBeFinitePositive, body.size[k]));
        if (!body.axis.allFinite() || body.axis.norm() == 0.0) error(out, f + ".axis", MustBeFiniteDirection);
    }
}

}  // namespace

std::vector<Diagnostic> validateRobotFields(const RobotModel& model) {
    using enum MessageId;
    std::vector<Diagnostic> out;
    if (model.joints.empty()) error(out, "robot.joints", RobotNeedsJoint);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) requireFinite(out, "robot.base", model.base.matrix()(r, c));
    for (int r = 0; r < 3; ++r) inRange(out, "robot.base.position[" + std::to_string(r) + "]", model.base.translation()[r], kLength);
    for (int j = 0; j < model.dof(); ++j) {
        const Joint& joint = model.joints[j];
        requireFinite(out, jointField(j, "a"), joint.dh.a);
        requireFinite(out, jointField(j, "alpha"), joint.dh.alpha);
        requireFinite(out, jointField(j, "d"), joint.dh.d);
        requireFinite(out, jointField(j, "theta"), joint.dh.theta);
        requireFinite(out, jointField(j, "mass"), joint.link.mass);
        for (int k = 0; k < 3; ++k) requireFinite(out, jointField(j, "com[" + std::to_string(k) + "]"), joint.link.com[k]);
        bool sane = inRange(out, jointField(j, "a"), joint.dh.a, kLength);
        sane = inRange(out, jointField(j, "d"), joint.dh.d, kLength) && sane;
        sane = inRange(out, jointField(j, "mass"), joint.link.mass, kMass) && sane;
        for (int k = 0; k < 3; ++k)
            sane = inRange(out, jointField(j, "com[" + std::to_string(k) + "]"), joint.link.com[k], kLength) && sane;
        static const char* const diagonal[3] = {"xx", "yy", "zz"};
        for (int k = 0; k < 3; ++k)
            sane = inRange(out, jointField(j, std::string("inertia.") + diagonal[k]), joint.link.inertia(k, k), kInertia) && sane;
        const bool inertiaFinite = joint.link.inertia.allFinite();
        if (!inertiaFinite) error(out, jointField(j, "inertia"), InertiaNotFinite);
        if (std::isfinite(joint.link.mass) && joint.link.mass < 0)
            error(out, jointField(j, "mass"), message(MassNegative, joint.link.mass));
        if (inertiaFinite && sane) validateInertia(out, j, joint.link.inertia);
        validateMotor(out, j, joint.motor);
    }
    const std::vector<Diagnostic> unitSlips = unitSlipWarnings(model);
    out.insert(out.end(), unitSlips.begin(), unitSlips.end());
    return out;
}

// A controlled joint's reference inside the joint's range, where the scene gives one. Each
// reference moves monotonically between the values it names (a quintic, a trapezoid and
// each waypoint's quintic start and end at rest), so those values are its extremes; a
// sine's are q0 ± |amplitude|.
void validateReferenceRange(std::vector<Diagnostic>& out, const Scene& scene, const Control& c) {
    const ControlReference& r = c.reference;
    const std::string at = "effects.control.reference.";
    for (int j = 0; j < scene.dof(); ++j) {
        const auto& range = scene.robot.joints[static_cast<std::size_t>(j)].range;
        if (!range || !c.drives(j)) continue;
        const std::string unit = coordinateUnit(scene.robot.joints[static_cast<std::size_t>(j)].dh.type == JointType::Revolute);
        const std::string index = "[" + std::to_string(j) + "]";
        const auto inside = [&](const std::string& field, double value) {
            if (!std::isfinite(value) || (value >= range->first && value <= range->second)) return true;
            error(out, field, message(MessageId::ReferenceOutsideRange, value, unit, j + 1, range->first, range->second));
            return false;
        };
        const auto point = [&](const char* key, const Eigen::VectorXd& q) { return j >= q.size() || inside(at + key + index, q[j]); };
        switch (r.kind) {
            case ControlReference::Kind::Hold: point("q", r.q0); break;
            case ControlReference::Kind::Step:
            case ControlReference::Kind::Quintic:
            case ControlReference::Kind::Trapezoidal: point("q0", r.q0) && point("q1", r.q1); break;
            case ControlReference::Kind::Sine:
                if (j < r.q0.size() && j < r.amplitude.size())
                    inside(at + "amplitude" + index, r.q0[j] - std::abs(r.amplitude[j])) &&
                        inside(at + "amplitude" + index, r.q0[j] + std::abs(r.amplitude[j]));
                break;
            case ControlReference::Kind::Waypoints:
                for (std::size_t k = 0; k < r.points.size(); ++k)
                    if (!point(("points[" + std::to_string(k) + "].q").c_str(), r.points[k])) break;
                break;
        }
    }
}

// A controller's gains, natural frequencies and torque limits (the reader has checked
// their signs and sizes). Beyond these a loop's own mode is faster than any servo and
// any integrator here can follow (K_p = 1e15 on the 2R took 668,000 dopri5 steps before
// the stiffness monitor stopped it; 1e200 overflowed and was then blamed on B(q)); named
// here, before a run blames something else. Computed torque's gains act on accelerations
// (ë + K_d ė + K_p e = 0): 1/s² and 1/s; the other laws' on torques.
void validateControl(std::vector<Diagnostic>& out, const Scene& scene) {
    using enum MessageId;
    if (!scene.effects.control || scene.lagrangian) return;
    const Control& c = *scene.effects.control;
    const bool accelerations = c.law == ControlLaw::ComputedTorque;
    const auto check = [&](const char* key, const Eigen::VectorXd& values, MessageId quantity, double largest, auto unitOf) {
        for (Eigen::Index i = 0; i < values.size() && i < scene.dof(); ++i) {
            const bool revolute = scene.robot.joints[static_cast<std::size_t>(i)].dh.type == JointType::Revolute;
            const std::string unit = unitOf(revolute), field = std::string("effects.control.") + key + "[" + std::to_string(i) + "]";
            requireFinite(out, field, values[i]);
            inRange(out, field, values[i], Range{quantity, unit.c_str(), 0.0, largest});
        }
    };
    check("kp", c.kp, QuantityGain, 1e9, [&](bool r) { return accelerations ? std::string("1/s²") : forceUnit(r) + "/" + coordinateUnit(r); });
    check("kd", c.kd, QuantityGain, 1e9, [&](bool r) { return accelerations ? std::string("1/s") : forceUnit(r) + "·s/" + coordinateUnit(r); });
    check("wn", c.wn, QuantityNaturalFrequency, 1e5, [](bool) { return std::string("rad/s"); });
    check("limits.torque", c.torqueLimit, QuantityTorqueLimit, 1e9, [](bool r) { return forceUnit(r); });
    validateReferenceRange(out, scene, c);
}

std::vector<Diagnostic> validateSceneFields(const Scene& scene) {
    using enum MessageId;
    std::vector<Diagnostic> out;
    if (scene.lagrangian) validateLagrangian(out, scene);
    else out = validateRobotFields(scene.robot);
    const int n = scene.dof();
    // A Lagrangian system's effects name its coordinates by number.
    const auto checkJoint = [&](const std::string& field, int joint) {
        if (joint < 0 || joint >= n)
            error(out, field + ".joint", message(scene.lagrangian ? CoordinateDoesNotExist : JointDoesNotExist, joint + 1, n));
    };
    const auto checkNonNegative = [&](const std::string& field, double value) {
        requireFinite(out, field, value);
        if (value < 0) error(out, field, message(MustBeNonNegative, value));
    };
    const Effects& e = scene.effects;
    validateControl(out, scene);
    if (scene.lagrangian && e.gravity) error(out, "effects.gravity", LagrangianNoGravityEffect);
    if (scene.lagrangian && !e.springs.empty()) error(out, "effects.springs", LagrangianNoSpringEffect);
    if (e.gravity) {
        for (int k = 0; k < 3; ++k) requireFinite(out, "effects.gravity[" + std::to_string(k) + "]", (*e.gravity)[k]);
        inRange(out, "effects.gravity", e.gravity->norm(), kGravity);
    }
    for (size_t s = 0; s < e.springs.size(); ++s) {
        const std::string f = "effects.springs[" + std::to_string(s) + "]";
        checkJoint(f, e.springs[s].joint);
        checkNonNegative(f + ".stiffness", e.springs[s].stiffness);
        requireFinite(out, f + ".rest", e.springs[s].rest);
    }
    for (size_t s = 0; s < e.viscous.size(); ++s) {
        const std::string f = "effects.viscous[" + std::to_string(s) + "]";
        checkJoint(f, e.viscous[s].joint);
        checkNonNegative(f + ".coefficient", e.viscous[s].coefficient);
    }
    for (size_t s = 0; s < e.coulomb.size(); ++s) {
        const std::string f = "effects.coulomb[" + std::to_string(s) + "]";
        checkJoint(f, e.coulomb[s].joint);
        checkNonNegative(f + ".force", e.coulomb[s].force);
        requireFinite(out, f + ".smoothing", e.coulomb[s].smoothing);
        if (!(e.coulomb[s].smoothing > 0)) error(out, f + ".smoothing", message(MustBePositive, e.coulomb[s].smoothing));
        if (scene.lagrangian && e.coulomb[s].model == CoulombModel::Stick) error(out, f + ".model", StickModelRobotsOnly);
    }
    for (size_t s = 0; s < e.torques.size(); ++s) {
        const std::string f = "effects.torques[" + std::to_string(s) + "]";
        const JointTorque& t = e.torques[s];
        checkJoint(f, t.joint);
        for (double v : {t.value, t.at, t.amplitude, t.frequency, t.phase, t.slope, t.start}) requireFinite(out, f, v);
    }
    const auto checkState = [&](const std::string& field, const Eigen::VectorXd& v) {
        if (v.size() != n) {
            error(out, field, message(scene.lagrangian ? EntriesForCoordinates : EntriesForJoints, v.size(), n));
            return;
        }
        for (int i = 0; i < n; ++i) requireFinite(out, field + "[" + std::to_string(i) + "]", v[i]);
    };
    checkState("initial.q", scene.initial.q);
    checkState("initial.qd", scene.initial.qd);
    const SimulationSettings& sim = scene.simulation;
    const auto checkPositive = [&](const std::string& field, double value) {
        if (!(std::isfinite(value) && value > 0)) error(out, field, message(MustBeFinitePositive, value));
    };
    checkPositive("simulation.duration", sim.duration);
    checkPositive("simulation.abs_tol", sim.absTol);
    checkPositive("simulation.rel_tol", sim.relTol);
    checkPositive("simulation.dt", sim.dt);
    checkPositive("simulation.output_rate", sim.outputRate);
    // Every sample is kept in memory (and plotted); ten million is already ~2 GB.
    constexpr double maxSamples = 1e7;
    if (std::isfinite(sim.duration) && std::isfinite(sim.outputRate) && sim.duration * sim.outputRate > maxSamples)
        error(out, "simulation.output_rate",
              message(TooManySamples, sim.duration, sim.outputRate, sim.duration * sim.outputRate, maxSamples));
    return out;
}

}  // namespace ll
