#include "core/symbolic/symbolic_robot.hpp"

#include <set>

#include <cmath>

#include "core/symbolic/expression.hpp"
#include "core/model/diagnostics.hpp"
#include "core/model/friction_law.hpp"
#include "core/symbolic/exact_numbers.hpp"
#include "core/symbolic/ginac_lock.hpp"

namespace ll::symbolic {
namespace {

class FieldReader {
public:
    FieldReader(const Scene& scene, ParameterMode mode, SymbolicRobot& robot)
        : scene_(scene), mode_(mode), robot_(robot), table_(parameterTable(scene)) {
        if (mode_ == ParameterMode::Parametric) robot_.parameterValues = table_.values();
    }

    // A length, mass, coefficient...: may become the textbook symbol `name`.
    GiNaC::ex value(const std::string& field, double number, const std::string& name) {
        if (mode_ == ParameterMode::Textbook && number != 0.0) return textbookSymbol(name, number);
        return read(field, number, false);
    }

    // A motor's inertia or gear ratio: a symbol unless numbers were asked for, so the
    // armature stays a term of its own in B.
    GiNaC::ex motorValue(const std::string& field, double number, const std::string& name) {
        auto lock = lockGinac();
        if (mode_ == ParameterMode::Numeric) return read(field, number, false);
        if (mode_ == ParameterMode::Parametric && scene_.expressions.count(field)) return read(field, number, false);
        robot_.motorSymbols.emplace_back(name, number);
        return textbookSymbol(name, number);
    }

    // An angle: never a textbook symbol; exact multiples of π stay exact.
    GiNaC::ex angle(const std::string& field, double number) { return read(field, number, true); }

    // A DH twist or offset: as angle(), but in textbook mode one that is not an exact
    // multiple of π/12 (0.3, 1.0472) becomes its symbol (alpha2, theta3), so the model
    // reads cos α₂ in general.
    GiNaC::ex dhAngle(const std::string& field, double number, const std::string& name) {
        const GiNaC::ex exact = read(field, number, true);
        if (mode_ != ParameterMode::Textbook || isExact(exact) || number == 0.0) return exact;
        return textbookSymbol(name, number);
    }

    GiNaC::symbol textbookSymbol(const std::string& name, double number) {
        GiNaC::symbol symbol(name);
        robot_.parameterValues.append(symbol == exactNumber(number));
        return symbol;
    }

private:
    GiNaC::ex read(const std::string& field, double number, bool isAngle) {
        const auto it = scene_.expressions.find(field);
        if (mode_ == ParameterMode::Parametric && it != scene_.expressions.end()) {
            const GiNaC::ex parsed = table_.parse(field, it->second);
            for (auto f = parsed.preorder_begin(); f != parsed.preorder_end(); ++f)  // "0.5*m1": 0.5 was typed
                if (GiNaC::is_a<GiNaC::numeric>(*f) && !GiNaC::ex_to<GiNaC::numeric>(*f).is_rational())
                    typed(exactNumber(GiNaC::ex_to<GiNaC::numeric>(*f).to_double()));
            return exactFloats(parsed);
        }
        if (it != scene_.expressions.end() && isAngle) {
            // "pi/2" stays exact in every mode.
            const GiNaC::ex e = table_.parse(field, it->second).subs(table_.values());
            if (GiNaC::is_a<GiNaC::numeric>(e.evalf())) return isExact(e) ? e : typed(exactAngle(number));
        }
        // A field typed as a number, or an expression read as its value (numbers mode).
        return typed(isAngle ? exactAngle(number) : exactNumber(number));
    }

    // x, remembered as typed when it is a number with a fractional part.
    GiNaC::ex typed(const GiNaC::ex& x) {
        if (GiNaC::is_a<GiNaC::numeric>(x) && !GiNaC::ex_to<GiNaC::numeric>(x).is_integer())
            robot_.typedDecimals.push_back(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(x)));
        return x;
    }

    static bool isExact(const GiNaC::ex& e) {
        const GiNaC::ex ratio = e / GiNaC::Pi;
        return GiNaC::is_a<GiNaC::numeric>(ratio) && GiNaC::ex_to<GiNaC::numeric>(ratio).is_rational();
    }

    const Scene& scene_;
    ParameterMode mode_;
    SymbolicRobot& robot_;
    ParameterTable table_;
};

// Base rotations from roll/pitch/yaw carry 1e-17 dust; snap it so 0 and ±1 are exact.
GiNaC::ex snapped(double v) {
    for (double exact : {0.0, 1.0, -1.0})
        if (std::abs(v - exact) < 1e-14) return exactNumber(exact);
    return exactNumber(v);
}

}  // namespace

SymbolicRobot symbolicRobot(const Scene& scene, ParameterMode mode, const GiNaC::symbol& t) {
    SymbolicRobot robot;
    FieldReader reader(scene, mode, robot);
    robot.convention = scene.robot.convention;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) robot.base(r, c) = snapped(scene.robot.base.matrix()(r, c));

    const char* axes = "xyz";
    static const char* inertiaKeys[3][3] = {{"xx", "xy", "xz"}, {"xy", "yy", "yz"}, {"xz", "yz", "zz"}};
    for (int j = 0; j < scene.robot.dof(); ++j) {
        const Joint& joint = scene.robot.joints[j];
        const std::string k = std::to_string(j + 1);
        const auto field = [&](const std::string& f) { return jointField(j, f); };
        SymbolicJoint sj;
        sj.type = joint.dh.type;
        sj.a = reader.value(field("a"), joint.dh.a, "a" + k);
        sj.d = reader.value(field("d"), joint.dh.d, "d" + k);
        sj.alpha = reader.dhAngle(field("alpha"), joint.dh.alpha, "alpha" + k);
        sj.theta = reader.dhAngle(field("theta"), joint.dh.theta, "theta" + k);
        sj.mass = reader.value(field("mass"), joint.link.mass, "m" + k);
        for (int c = 0; c < 3; ++c)
            sj.com(c, 0) = reader.value(field("com[" + std::to_string(c) + "]"), joint.link.com[c], std::string(1, axes[c]) + "c" + k);
        for (int r = 0; r < 3; ++r)
            for (int c = r; c < 3; ++c) {
                const std::string key = inertiaKeys[r][c];
                sj.inertia(r, c) = reader.value(field("inertia." + key), joint.link.inertia(r, c), "I" + key + k);
                sj.inertia(c, r) = sj.inertia(r, c);
            }
        const JointMotor& motor = joint.motor;
        if (motor.armature() != 0.0 && motor.fromMotor) {
            const GiNaC::ex Jm = reader.motorValue(field("motor.inertia"), motor.inertia, "Jm" + k);
            const GiNaC::ex G = reader.motorValue(field("motor.gear_ratio"), motor.gearRatio, "G" + k);
            sj.armature = Jm * GiNaC::pow(G, 2);
        } else if (motor.armature() != 0.0) {
            sj.armature = reader.motorValue(field("armature"), motor.inertia, "Ja" + k);
        }
        robot.joints.push_back(sj);
    }

    const Effects& e = scene.effects;
    if (e.gravity) {
        robot.hasGravity = true;
        const Eigen::Vector3d& g0 = *e.gravity;
        const int nonzero = (g0.array() != 0.0).count();
        for (int c = 0; c < 3; ++c) {
            const std::string f = "effects.gravity[" + std::to_string(c) + "]";
            if (mode == ParameterMode::Textbook && nonzero == 1 && g0[c] != 0.0) {
                const GiNaC::symbol g = reader.textbookSymbol("g", std::abs(g0[c]));
                robot.gravity(c, 0) = g0[c] > 0 ? GiNaC::ex(g) : -g;
            } else {
                robot.gravity(c, 0) = reader.value(f, g0[c], "");
            }
        }
    }
    for (size_t s = 0; s < e.springs.size(); ++s) {
        const std::string f = "effects.springs[" + std::to_string(s) + "]";
        const std::string k = std::to_string(e.springs[s].joint + 1);
        robot.springs.push_back({e.springs[s].joint, reader.value(f + ".stiffness", e.springs[s].stiffness, "K" + k),
                                 reader.angle(f + ".rest", e.springs[s].rest)});
    }
    for (size_t s = 0; s < e.viscous.size(); ++s) {
        const std::string f = "effects.viscous[" + std::to_string(s) + "]";
        robot.viscous.push_back({e.viscous[s].joint,
                                 reader.value(f + ".coefficient", e.viscous[s].coefficient, "b" + std::to_string(e.viscous[s].joint + 1)),
                                 0});
    }
    for (size_t s = 0; s < e.coulomb.size(); ++s) {
        const std::string f = "effects.coulomb[" + std::to_string(s) + "]";
        const std::string k = std::to_string(e.coulomb[s].joint + 1);
        robot.coulomb.push_back({e.coulomb[s].joint, reader.value(f + ".force", e.coulomb[s].force, "Fc" + k),
                                 reader.value(f + ".smoothing", e.coulomb[s].smoothing, "vs" + k)});
    }
    for (size_t s = 0; s < e.torques.size(); ++s) {
        const JointTorque& torque = e.torques[s];
        const std::string f = "effects.torques[" + std::to_string(s) + "]";
        const auto number = [&](const std::string& key, double v) { return reader.angle(f + "." + key, v); };
        GiNaC::ex tau;
        switch (torque.kind) {
            case TorqueKind::Constant: tau = number("value", torque.value); break;
            case TorqueKind::Step: tau = number("value", torque.value) * GiNaC::step(t - number("at", torque.at)); break;
            case TorqueKind::Sine:
                tau = number("amplitude", torque.amplitude) *
                      GiNaC::sin(2 * GiNaC::Pi * number("frequency", torque.frequency) * t + number("phase", torque.phase));
                break;
            case TorqueKind::Ramp: {
                const GiNaC::ex start = number("start", torque.start);
                tau = number("slope", torque.slope) * (t - start) * GiNaC::step(t - start);
                break;
            }
        }
        robot.torques.push_back({torque.joint, tau, 0});
    }
    return robot;
}

GiNaC::matrix effectForces(const SymbolicRobot& robot, const std::vector<GiNaC::symbol>& qd) {
    GiNaC::matrix Q(static_cast<unsigned>(qd.size()), 1);
    for (const SymbolicTerm& torque : robot.torques) Q(torque.joint, 0) += torque.value;
    for (const SymbolicTerm& f : robot.viscous) Q(f.joint, 0) += viscousFrictionForce<GiNaC::ex>(f.value, qd[f.joint]);
    for (const SymbolicTerm& f : robot.coulomb) Q(f.joint, 0) += tanhCoulombForce<GiNaC::ex>(f.value, qd[f.joint], f.extra);
    return Q;
}

namespace {

void collectSymbols(const GiNaC::ex& e, std::set<std::string>& out) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) out.insert(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
}

}  // namespace

std::map<std::string, int> linkSymbols(const SymbolicRobot& robot) {
    std::map<std::string, int> owner;
    std::set<std::string> shared;
    for (std::size_t i = 0; i < robot.joints.size(); ++i) {
        const SymbolicJoint& j = robot.joints[i];
        std::set<std::string> names;
        collectSymbols(j.mass, names);
        collectSymbols(j.com, names);
        collectSymbols(j.inertia, names);
        for (const std::string& name : names) {
            const auto [it, inserted] = owner.emplace(name, static_cast<int>(i));
            if (!inserted && it->second != static_cast<int>(i)) shared.insert(name);
        }
    }
    // A length of the DH table (a1 in a COM written as lc1 − a1) is the geometry's, not a link's.
    for (const SymbolicJoint& j : robot.joints)
        for (const GiNaC::ex* e : {&j.a, &j.alpha, &j.d, &j.theta}) collectSymbols(*e, shared);
    for (const std::string& name : shared) owner.erase(name);
    return owner;
}

}  // namespace ll::symbolic
