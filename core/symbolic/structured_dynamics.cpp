#include "core/symbolic/structured_dynamics.hpp"

#include "core/model/one_based.hpp"
#include "core/symbolic/symbolic_vector.hpp"
#include <array>
#include <chrono>
#include <cmath>
#include <random>
#include <set>

#include "core/model/cancellation.hpp"
#include "core/model/diagnostics.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/link_transform.hpp"
#include "core/model/quantity_units.hpp"
#include "core/symbolic/index_list.hpp"
#include "core/symbolic/symbolic_robot.hpp"

namespace ll::symbolic {
namespace {

using GiNaC::ex;
using GiNaC::matrix;

const char* const kAxis = "xyz";

Vec3 times(const matrix& M, const Vec3& v) {
    Vec3 r;
    for (int row = 0; row < 3; ++row) r[row] = M(row, 0) * v[0] + M(row, 1) * v[1] + M(row, 2) * v[2];
    return r;
}
bool isZero(const Vec3& v) { return v[0].is_zero() && v[1].is_zero() && v[2].is_zero(); }

// The quantities of one link, all in the link's own frame (frame i+1).
class LinkQuantities {
public:
    LinkQuantities(NamedDefinitions& table, const SymbolicRobot& robot, const std::vector<bool>& revolute,
                   const std::vector<matrix>& inverseA, int link)
        : table_(table), revolute_(revolute), i_(link), frame_(idx(link)) {
        const int f0 = link + 1;
        std::vector<Vec3> z(f0 + 1), o(f0 + 1);
        z[f0] = {0, 0, 1};
        o[f0] = {0, 0, 0};
        matrix P = GiNaC::ex_to<matrix>(GiNaC::unit_matrix(4));  // pose of frame f in the link frame
        for (int f = link; f >= 0; --f) {
            const matrix product = P.mul(inverseA[f]);
            matrix named(4, 4);
            const std::string F = std::to_string(f);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 3; ++r) {
                    const std::string comp(1, kAxis[r]);
                    if (c == 3)
                        named(r, c) =
                            table_.name(product(r, c), "o" + comp + F + "_" + frame_, "{}^{" + frame_ + "}o_{" + F + "," + comp + "}",
                                        message(MessageId::MeaningOriginComponent, comp, F, frame_), 1, i_, "m");
                    else
                        named(r, c) =
                            table_.name(product(r, c), std::string(1, kAxis[c]) + comp + F + "_" + frame_,
                                        "{}^{" + frame_ + "}" + kAxis[c] + "_{" + F + "," + comp + "}",
                                        message(MessageId::MeaningAxisComponent, comp, std::string(1, kAxis[c]), F, frame_), 1, i_);
                }
            named(3, 3) = 1;
            P = named;
            z[f] = {P(0, 2), P(1, 2), P(2, 2)};
            o[f] = {P(0, 3), P(1, 3), P(2, 3)};
        }
        const bool standard = robot.convention == DhConvention::Standard;
        Z.resize(link + 1);
        O.resize(link + 1);
        JP.resize(link + 1);
        for (int j = 0; j <= link; ++j) {
            const int a = standard ? j : j + 1;  // the frame whose z is joint j's axis
            Z[j] = z[a];
            O[j] = o[a];
        }
        const SymbolicJoint& joint = robot.joints[link];
        com = {joint.com(0, 0), joint.com(1, 0), joint.com(2, 0)};
        baseOrigin = o[0];
        for (int j = 0; j <= link; ++j)
            JP[j] = vector(revolute[j] ? cross(Z[j], sub(com, O[j])) : Z[j], "J", idx(j), "J_{P," + idx(j) + ",@}^{(" + frame_ + ")}",
                           MessageId::MeaningComVelocity, {literal(frame_), literal(idx(j))}, 4, "", revolute[j] ? "m" : "");
        if (robot.hasGravity) {
            Vec3 g0{robot.gravity(0, 0), robot.gravity(1, 0), robot.gravity(2, 0)};
            matrix baseR(3, 3), R(3, 3);
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) {
                    baseR(r, c) = robot.base(c, r);  // world → frame 0
                    R(r, c) = P(r, c);               // frame 0 → link frame
                }
            gravity = vector(times(R, times(baseR, g0)), "g", "0", "g_{0,@}^{(" + frame_ + ")}", MessageId::MeaningGravity,
                             {literal(frame_)}, 6, "", "m/s²");
        }
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) inertia(r, c) = joint.inertia(r, c);
        IZ.resize(link + 1);
        for (int j = 0; j <= link; ++j) IZ[j] = times(inertia, Z[j]);
    }

    // Components named "<letter><x|y|z><index>_<link><suffix>" (Jx2_4: x of J_P,2 of link 4),
    // which the printers set as J_{x2,4}; '@' in `latex` stands for the component (x, y, z).
    // Each component means `meaning` with the component before `args`.
    Vec3 vector(const Vec3& v, const std::string& letter, const std::string& index, const std::string& latex, MessageId meaning,
                const std::vector<Message>& args, int step, const std::string& suffix = "", const std::string& unit = "") {
        Vec3 r;
        for (int c = 0; c < 3; ++c) {
            const std::string comp(1, kAxis[c]);
            std::string l = latex;
            l.replace(l.find('@'), 1, comp);
            std::vector<Message> componentArgs{literal(comp)};
            componentArgs.insert(componentArgs.end(), args.begin(), args.end());
            r[c] = table_.name(v[c], letter + comp + index + "_" + frame_ + suffix, l, Message(meaning, std::move(componentArgs)), step, i_,
                               unit);
        }
        return r;
    }

    // ∂z_a/∂q_l: z_l × z_a when revolute joint l precedes a, else 0.
    Vec3 dAxis(int a, int l) const {
        if (revolute_[l] && l < a) return cross(Z[l], Z[a]);
        return {0, 0, 0};
    }

    // ∂J_P,a/∂q_l (l ≤ this link), named.
    Vec3 dJP(int a, int l) {
        const auto key = std::make_pair(a, l);
        if (const auto it = dJPCache_.find(key); it != dJPCache_.end()) return it->second;
        Vec3 d{0, 0, 0};
        if (!revolute_[a]) d = dAxis(a, l);
        else if (l < a) d = revolute_[l] ? cross(Z[l], JP[a]) : Vec3{0, 0, 0};
        else d = cross(Z[a], JP[l]);
        if (!isZero(d))
            d = vector(d, "D", idx(a), "\\partial J_{P," + idx(a) + ",@}^{(" + frame_ + ")}/\\partial q_{" + idx(l) + "}",
                       MessageId::MeaningJacobianDerivative, {literal(idx(a)), literal(frame_), literal(idx(l))}, 8, "_" + idx(l),
                       revolute_[a] ? (revolute_[l] ? "m" : "") : (revolute_[l] ? "" : "1/m"));
        dJPCache_.emplace(key, d);
        return d;
    }

    // ∂β_jk/∂q_l for this link by the Jacobian identities (j ≤ k, j < l ≤ link).
    ex dBeta(int j, int k, int l, const ex& mass) {
        ex e = mass * (dot(dJP(j, l), JP[k]) + dot(JP[j], dJP(k, l)));
        if (revolute_[j] && revolute_[k]) {
            e += dot(dAxis(j, l), IZ[k]) + dot(IZ[j], dAxis(k, l));
            if (revolute_[l]) e += dot(Z[j], cross(Z[l], IZ[k])) - dot(IZ[j], cross(Z[l], Z[k]));
        }
        return e;
    }

    std::vector<Vec3> Z, O, JP, IZ;  // per joint j ≤ link: axis, axis origin, J_P column, I z_j
    Vec3 gravity{0, 0, 0};           // g0 in the link frame
    Vec3 com, baseOrigin;            // the centre of mass and the origin of frame 0, in the link frame
    matrix inertia{3, 3};

private:
    NamedDefinitions& table_;
    const std::vector<bool>& revolute_;
    int i_;
    std::string frame_;
    std::map<std::pair<int, int>, Vec3> dJPCache_;
};

// A scene parameter spelled like a generated name (Jx1_2, beta1_1_2) would make the
// printed sums ambiguous: JSON's expr would not parse back, codegen would declare the
// name twice. Refused with the clash named, as a scene input error.
void refuseGeneratedNameClashes(const Scene& scene, const NamedDefinitions& table) {
    std::set<std::string> parameters;
    for (const auto& [name, value] : scene.parameters) parameters.insert(name);
    for (const NamedDefinition& d : table.entries())
        if (parameters.count(d.name))
            throw InputError("parameters." + d.name, message(MessageId::ParameterIsGeneratedName, d.name, d.meaning));
}

}  // namespace

int StructuredDynamics::nonZeroMassDerivatives() const {
    int count = 0;
    for (int l = 0; l < n; ++l)
        for (int j = 0; j < n; ++j)
            for (int k = j; k < n; ++k) count += dB[l](j, k).is_zero() ? 0 : 1;
    return count;
}

StructuredDynamics deriveStructured(const Scene& scene, const DerivationOptions& options) {
    const auto lock = lockGinac();
    const auto start = std::chrono::steady_clock::now();
    const int n = scene.robot.dof();
    int step = 0;
    const auto checkpoint = [&](int s, const std::string& what) {
        step = s;
        throwIfCancelled(options.cancel);
        if (options.progress) options.progress(step, what);
    };
    if (options.mode == ParameterMode::Parametric) refuseShorthandParameterNames(scene);
    std::vector<bool> revolute(n);
    for (int i = 0; i < n; ++i) revolute[i] = scene.robot.joints[i].dh.type == JointType::Revolute;

    StructuredDynamics s;
    s.systemName = scene.name;
    s.convention = scene.robot.convention;
    s.n = n;
    s.trig = std::make_shared<TrigContext>(revolute);
    TrigContext& tc = *s.trig;
    const SymbolicRobot robot = symbolicRobot(scene, options.mode, tc.t());
    for (const SymbolicJoint& j : robot.joints) {
        tc.addConstantAngle(j.alpha);
        tc.addConstantAngle(j.theta);
    }
    s.table = std::make_shared<NamedDefinitions>(tc);
    NamedDefinitions& table = *s.table;
    table.setCancel(options.cancel);  // checked before every name: stops within one name's work

    std::vector<matrix> inverseA(n);
    for (int f = 0; f < n; ++f) inverseA[f] = tc.reduce(inverseTransform(linkTransform(robot.convention, robot.joints[f], tc, f)));

    s.B = matrix(n, n);
    s.g = matrix(n, 1);
    s.beta.assign(n, std::vector<std::vector<ex>>(n));
    s.dB.assign(n, matrix(n, n));
    for (int i = 0; i < n; ++i) {
        checkpoint(1, "frames of link " + idx(i));
        LinkQuantities link(table, robot, revolute, inverseA, i);
        const ex& m = robot.joints[i].mass;
        const std::string L = idx(i);
        checkpoint(7, "beta^(" + L + ")");
        for (int j = 0; j <= i; ++j)
            for (int k = j; k <= i; ++k) {
                ex beta = m * dot(link.JP[j], link.JP[k]);
                if (revolute[j] && revolute[k]) beta += dot(link.Z[j], link.IZ[k]);
                s.beta[j][k].push_back(table.name(beta, "beta" + idx(j) + "_" + idx(k) + "_" + L,
                                                  "\\beta_{" + indexList({j, k}) + "}^{(" + L + ")}",
                                                  message(MessageId::MeaningContribution, L, indexList({j, k})), 7, i,
                                                  massMatrixUnit(revolute[j], revolute[k])));
            }
        if (robot.hasGravity) {
            checkpoint(6, "gamma^(" + L + ")");
            // g0ᵀ p_ci in the world = g0^(i)·(p_ci − o_0) in the link frame + g0ᵀ of the base's offset.
            ex offset = 0;
            for (int r = 0; r < 3; ++r) offset += robot.gravity(r, 0) * robot.base(r, 3);
            s.Epot -= m * (dot(link.gravity, sub(link.com, link.baseOrigin)) + offset);
            for (int j = 0; j <= i; ++j)
                s.g(j, 0) -=
                    m * table.name(dot(link.gravity, link.JP[j]), "gamma" + idx(j) + "_" + L, "\\gamma_{" + idx(j) + "}^{(" + L + ")}",
                                   message(MessageId::MeaningGravityLever, idx(j), L), 6, i, revolute[j] ? "m²/s²" : "m/s²");
        }
        for (int j = 0; j <= i; ++j) {
            checkpoint(8, "dbeta_" + idx(j) + "k^(" + L + ")");  // a 12-joint link has ~400 of them: check often
            for (int k = j; k <= i; ++k)
                for (int l = j + 1; l <= i; ++l)  // ∂β_jk/∂q_l = 0 for l ≤ min(j, k) = j
                    s.dB[l](j, k) += table.name(link.dBeta(j, k, l, m), "delta" + idx(j) + "_" + idx(k) + "_" + L + "_" + idx(l),
                                                "\\partial\\beta_{" + indexList({j, k}) + "}^{(" + L + ")}/\\partial q_{" + idx(l) + "}",
                                                message(MessageId::MeaningDerivative, "beta" + idx(j) + "_" + idx(k) + "_" + L, idx(l)), 8,
                                                i, massMatrixUnit(revolute[j], revolute[k]) + (revolute[l] ? "" : "/m"));
        }
    }
    s.armature.assign(n, ex(0));
    for (int j = 0; j < n; ++j) {
        s.armature[j] = robot.joints[j].armature;
        for (int k = j; k < n; ++k) {
            ex b = j == k ? s.armature[j] : ex(0);
            for (const ex& beta : s.beta[j][k]) b += beta;
            s.B(j, k) = s.B(k, j) = b;
        }
    }
    for (int j = 0; j < n; ++j) {
        s.Ekin += GiNaC::numeric(1, 2) * s.B(j, j) * GiNaC::pow(tc.qd(j), 2);
        for (int k = j + 1; k < n; ++k) s.Ekin += s.B(j, k) * tc.qd(j) * tc.qd(k);
    }
    checkpoint(8, "db/dq");
    // A sum of named terms can vanish identically with no term zero on its own (the
    // PUMA's wrist: m (z_j × J_P,l)·J_P,l and terms that cancel through its symmetric
    // inertia). Such a ∂b_jk/∂q_l is found in numbers: its value at two random states
    // is rounding residue (≤ 1e-9 of the size of its terms).
    {
        std::mt19937 rng(20261123);
        std::uniform_real_distribution<double> u(-3.0, 3.0);
        std::vector<DefinitionValues> states;
        for (int k = 0; k < 2; ++k) {
            std::vector<double> q(n), qd(n, 0.0);
            for (double& x : q) x = u(rng);
            s.trigToFunctions = tc.toFunctions();
            s.parameterValues = robot.parameterValues;
            s.symbolLinks = linkSymbols(robot);
            states.emplace_back(table, structuredInputs(s, q, qd), options.cancel);
        }
        for (int l = 0; l < n; ++l) {
            throwIfCancelled(options.cancel);
            for (int j = 0; j < n; ++j)
                for (int k = j; k < n; ++k) {
                    const ex& e = s.dB[l](j, k);
                    if (e.is_zero()) continue;
                    bool zero = true;
                    for (const DefinitionValues& v : states) zero = zero && std::abs(v(e)) <= 1e-9 * v.magnitude(e);
                    if (zero) s.dB[l](j, k) = 0;
                }
        }
    }
    for (int l = 0; l < n; ++l)
        for (int j = 0; j < n; ++j)
            for (int k = j; k < n; ++k) {
                if (s.dB[l](j, k).is_zero()) continue;
                s.dB[l](j, k) = s.dB[l](k, j) = table.name(s.dB[l](j, k), "Db" + idx(j) + "_" + idx(k) + "_" + idx(l),
                                                           "\\partial b_{" + indexList({j, k}) + "}/\\partial q_{" + idx(l) + "}",
                                                           message(MessageId::MeaningDerivative, "b" + indexList({j, k}), idx(l)), 8, -1,
                                                           massMatrixUnit(revolute[j], revolute[k]) + (revolute[l] ? "" : "/m"));
            }
    checkpoint(8, "C");
    s.C = matrix(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            throwIfCancelled(options.cancel);
            ex c = 0;
            for (int k = 0; k < n; ++k) c += GiNaC::numeric(1, 2) * (s.dB[k](i, j) + s.dB[j](i, k) - s.dB[i](j, k)) * tc.qd(k);
            s.C(i, j) = c.expand();
        }
    for (const SymbolicTerm& spring : robot.springs) {
        s.g(spring.joint, 0) += spring.value * (tc.q(spring.joint) - spring.extra);
        s.Epot += GiNaC::numeric(1, 2) * spring.value * GiNaC::pow(tc.q(spring.joint) - spring.extra, 2);
    }
    for (int j = 0; j < n; ++j) s.g(j, 0) = s.g(j, 0).expand();
    throwIfCancelled(options.cancel);
    if (options.mode == ParameterMode::Parametric) refuseGeneratedNameClashes(scene, table);
    s.Q = effectForces(robot, tc.qd());
    for (int i = 0; i < n; ++i) s.qdd.emplace_back("qdd" + idx(i));
    s.parameterValues = robot.parameterValues;
    s.symbolLinks = linkSymbols(robot);
    s.trigToFunctions = tc.toFunctions();
    table.setCancel(nullptr);  // the flag may not outlive this call
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return s;
}

GiNaC::lst structuredInputs(const StructuredDynamics& s, const std::vector<double>& q, const std::vector<double>& qd) {
    GiNaC::lst in;
    const TrigContext& tc = *s.trig;
    for (int i = 0; i < s.n; ++i) {
        in.append(tc.q(i) == q[i]);
        in.append(tc.c(i) == std::cos(q[i]));
        in.append(tc.s(i) == std::sin(q[i]));
        in.append(tc.qd(i) == qd[i]);
    }
    for (const ex& rel : s.parameterValues) in.append(rel);
    return in;
}

}  // namespace ll::symbolic
