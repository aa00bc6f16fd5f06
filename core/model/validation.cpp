#include "core/model/validation.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "core/model/unit_slips.hpp"
#include "core/model/usable_number.hpp"

namespace ll {
namespace {

std::string fmt(double v) { return formatValue(v); }

void error(std::vector<Diagnostic>& out, std::string field, std::string message, std::string hint = {}) {
    out.push_back({Severity::Error, std::move(field), std::move(message), std::move(hint)});
}

void warning(std::vector<Diagnostic>& out, std::string field, std::string message, std::string hint = {}) {
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
    const char* quantity;
    const char* unit;
    double smallest, largest;
};
constexpr Range kLength{"length", "m", 1e-9, 1e4};
constexpr Range kMass{"mass", "kg", 1e-9, 1e9};
constexpr Range kInertia{"inertia", "kg m²", 1e-15, 1e9};
constexpr Range kGravity{"gravity", "m/s²", 1e-6, 1e3};

// Whether `value` is in range; if not, the error says so (finite values only: the
// caller's requireFinite names the rest).
bool inRange(std::vector<Diagnostic>& out, const std::string& field, double value, const Range& r) {
    const double a = std::abs(value);
    if (!std::isfinite(value) || a == 0.0 || (a >= r.smallest && a <= r.largest)) return true;
    out.push_back({Severity::Error, field,
                   std::string(a > r.largest ? "absurdly large " : "absurdly small ") + r.quantity + " " + fmt(value) + " " + r.unit,
                   std::string("no physical ") + r.quantity + " here is " + (a > r.largest ? "above " + fmt(r.largest) : "below " + fmt(r.smallest)) +
                       " " + r.unit + " (was it typed in the wrong unit, or with a wrong exponent?)"});
    return false;
}

void validateInertia(std::vector<Diagnostic>& out, int j, const Eigen::Matrix3d& I) {
    const std::string field = jointField(j, "inertia");
    const double scale = std::max(I.cwiseAbs().maxCoeff(), 1e-300);
    if ((I - I.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
        error(out, field, "inertia tensor is not symmetric");
        return;
    }
    const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
    if (moments.minCoeff() < -1e-12 * scale) {
        error(out, field,
              "inertia tensor is not positive semi-definite: principal moments " + fmt(moments[0]) + ", " +
                  fmt(moments[1]) + ", " + fmt(moments[2]),
              "off-diagonal entries are the tensor's own, i.e. minus the products of inertia");
        return;
    }
    const double tol = 1e-9 * scale;
    const double a = moments[0], b = moments[1], c = moments[2];
    if (a + b < c - tol)
        warning(out, field,
                "principal moments " + fmt(a) + ", " + fmt(b) + ", " + fmt(c) + " violate the triangle inequality (" +
                    fmt(a) + " + " + fmt(b) + " < " + fmt(c) + ")",
                "no physical body has this inertia; the model is simulated as given");
}

// A motor's armature adds Jm G² to b_jj: it must be a finite number >= 0.
void validateMotor(std::vector<Diagnostic>& out, int j, const JointMotor& motor) {
    if (!motor.fromMotor) {
        requireFinite(out, jointField(j, "armature"), motor.inertia);
        if (motor.inertia < 0) error(out, jointField(j, "armature"), "armature is negative (" + fmt(motor.inertia) + "); it must be >= 0");
        return;
    }
    requireFinite(out, jointField(j, "motor.inertia"), motor.inertia);
    requireFinite(out, jointField(j, "motor.gear_ratio"), motor.gearRatio);
    if (motor.inertia < 0)
        error(out, jointField(j, "motor.inertia"), "rotor inertia is negative (" + fmt(motor.inertia) + " kg m²); it must be >= 0");
    if (motor.gearRatio == 0)
        error(out, jointField(j, "motor.gear_ratio"),
              "gear ratio is 0 (motor turns per joint turn: 1 for a direct drive, e.g. 62.6 for PUMA joint 1)");
}

// The structure of a hand-typed Lagrangian; its expressions are checked when they are
// parsed (scene file) and derived (core/symbolic/lagrangian_derivation).
void validateLagrangian(std::vector<Diagnostic>& out, const Scene& scene) {
    const LagrangianSpec& l = *scene.lagrangian;
    if (!scene.robot.joints.empty())
        error(out, "robot", "a scene has either a robot or a lagrangian, not both");
    if (l.coordinates.empty()) error(out, "lagrangian.coordinates", "a Lagrangian system needs at least one coordinate");
    if (!l.forces.empty() && l.forces.size() != l.coordinates.size())
        error(out, "lagrangian.forces",
              "has " + std::to_string(l.forces.size()) + " entries, one per coordinate (" +
                  std::to_string(l.coordinates.size()) + ") or none are needed");
    for (size_t b = 0; b < l.bodies.size(); ++b) {
        const VisualBody& body = l.bodies[b];
        const std::string f = "lagrangian.bodies[" + std::to_string(b) + "]";
        if (static_cast<int>(body.size.size()) != sizeCount(body.shape))
            error(out, f + ".size",
                  "a " + std::string(toString(body.shape)) + " takes " + std::to_string(sizeCount(body.shape)) +
                      " numbers, got " + std::to_string(body.size.size()));
        for (size_t k = 0; k < body.size.size(); ++k)
            if (!(std::isfinite(body.size[k]) && body.size[k] > 0))
                error(out, f + ".size[" + std::to_string(k) + "]", "must be a finite number > 0, got " + fmt(body.size[k]));
        if (!body.axis.allFinite() || body.axis.norm() == 0.0)
            error(out, f + ".axis", "must be a finite nonzero direction");
    }
}

}  // namespace

std::vector<Diagnostic> validateRobotFields(const RobotModel& model) {
    std::vector<Diagnostic> out;
    if (model.joints.empty()) error(out, "robot.joints", "a robot needs at least one joint");
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
        for (int k = 0; k < 3; ++k)
            requireFinite(out, jointField(j, "com[" + std::to_string(k) + "]"), joint.link.com[k]);
        bool sane = inRange(out, jointField(j, "a"), joint.dh.a, kLength);
        sane = inRange(out, jointField(j, "d"), joint.dh.d, kLength) && sane;
        sane = inRange(out, jointField(j, "mass"), joint.link.mass, kMass) && sane;
        for (int k = 0; k < 3; ++k) sane = inRange(out, jointField(j, "com[" + std::to_string(k) + "]"), joint.link.com[k], kLength) && sane;
        static const char* const diagonal[3] = {"xx", "yy", "zz"};
        for (int k = 0; k < 3; ++k)
            sane = inRange(out, jointField(j, std::string("inertia.") + diagonal[k]), joint.link.inertia(k, k), kInertia) && sane;
        const bool inertiaFinite = joint.link.inertia.allFinite();
        if (!inertiaFinite) error(out, jointField(j, "inertia"), "inertia tensor has a non-finite entry");
        if (std::isfinite(joint.link.mass) && joint.link.mass < 0)
            error(out, jointField(j, "mass"), "mass is negative (" + fmt(joint.link.mass) + " kg); it must be >= 0");
        if (inertiaFinite && sane) validateInertia(out, j, joint.link.inertia);
        validateMotor(out, j, joint.motor);
    }
    const std::vector<Diagnostic> unitSlips = unitSlipWarnings(model);
    out.insert(out.end(), unitSlips.begin(), unitSlips.end());
    return out;
}

std::vector<Diagnostic> validateSceneFields(const Scene& scene) {
    std::vector<Diagnostic> out;
    if (scene.lagrangian)
        validateLagrangian(out, scene);
    else
        out = validateRobotFields(scene.robot);
    const int n = scene.dof();
    // A Lagrangian system's effects name its coordinates by number.
    const std::string items = scene.lagrangian ? "coordinates" : "joints";
    const auto checkJoint = [&](const std::string& field, int joint) {
        if (joint < 0 || joint >= n)
            error(out, field + ".joint",
                  std::string(scene.lagrangian ? "coordinate " : "joint ") + std::to_string(joint + 1) +
                      " does not exist (the " + (scene.lagrangian ? "system" : "robot") + " has " + items + " 1.." +
                      std::to_string(n) + ")");
    };
    const auto checkNonNegative = [&](const std::string& field, double value) {
        requireFinite(out, field, value);
        if (value < 0) error(out, field, "must be >= 0, got " + fmt(value));
    };
    const Effects& e = scene.effects;
    if (scene.lagrangian && e.gravity)
        error(out, "effects.gravity",
              "a Lagrangian system has no gravity effect: write it in the potential (lagrangian.potential, "
              "e.g. m*g*y for height y), otherwise it would be modelled twice or not at all");
    if (scene.lagrangian && !e.springs.empty())
        error(out, "effects.springs",
              "a Lagrangian system has no spring effect: write it in the potential (lagrangian.potential, "
              "e.g. K*(x - rest)^2/2)");
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
        if (!(e.coulomb[s].smoothing > 0)) error(out, f + ".smoothing", "must be > 0, got " + fmt(e.coulomb[s].smoothing));
        if (scene.lagrangian && e.coulomb[s].model == CoulombModel::Stick)
            error(out, f + ".model",
                  "the stick model is implemented for robots only; a Lagrangian system uses \"tanh\" (the default)");
    }
    for (size_t s = 0; s < e.torques.size(); ++s) {
        const std::string f = "effects.torques[" + std::to_string(s) + "]";
        const JointTorque& t = e.torques[s];
        checkJoint(f, t.joint);
        for (double v : {t.value, t.at, t.amplitude, t.frequency, t.phase, t.slope, t.start}) requireFinite(out, f, v);
    }
    const auto checkState = [&](const std::string& field, const Eigen::VectorXd& v) {
        if (v.size() != n) {
            error(out, field, "has " + std::to_string(v.size()) + " entries, the " +
                                  (scene.lagrangian ? "system" : "robot") + " has " + std::to_string(n) + " " + items);
            return;
        }
        for (int i = 0; i < n; ++i) requireFinite(out, field + "[" + std::to_string(i) + "]", v[i]);
    };
    checkState("initial.q", scene.initial.q);
    checkState("initial.qd", scene.initial.qd);
    const SimulationSettings& sim = scene.simulation;
    const auto checkPositive = [&](const std::string& field, double value) {
        if (!(std::isfinite(value) && value > 0)) error(out, field, "must be a finite number > 0, got " + fmt(value));
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
              "duration " + fmt(sim.duration) + " s at " + fmt(sim.outputRate) + " samples/s would record " +
                  fmt(sim.duration * sim.outputRate) + " samples (at most 1e+07): lower the output rate or the duration");
    return out;
}

}  // namespace ll
