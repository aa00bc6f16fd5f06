#include "core/symbolic/robot_derivation.hpp"

#include "core/model/one_based.hpp"
#include "core/symbolic/symbolic_vector.hpp"
#include <array>
#include <chrono>
#include <functional>
#include <string>
#include <sstream>

#include "core/dynamics/christoffel.hpp"
#include "core/symbolic/control_law.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/model/diagnostics.hpp"
#include "core/symbolic/trig_names.hpp"
#include "core/symbolic/link_transform.hpp"
#include "core/symbolic/trig_context.hpp"

namespace ll::symbolic {
namespace {

using GiNaC::ex;
using GiNaC::matrix;

class Stopwatch {
public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return s;
    }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

Vec3 column(const matrix& m, int c) { return {m(0, c), m(1, c), m(2, c)}; }
Vec3 translation(const matrix& T) { return column(T, 3); }
matrix toMatrix(const Vec3& v) { return matrix(3, 1, GiNaC::lst{v[0], v[1], v[2]}); }
matrix rotation(const matrix& T) {
    matrix R(3, 3);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) R(r, c) = T(r, c);
    return R;
}

// tc.reduce with a checkpoint first: the derivation can be cancelled between entries.
// (Cutting an entry into pieces to see a cancel sooner was measured: pieces small
// enough to matter made the Panda's derivation 2.5× slower. The named-quantity
// derivation keeps every entry small instead.)
ex reduceChecked(const TrigContext& tc, const ex& e, const std::function<void(const std::string&)>& checkpoint, const std::string& what) {
    checkpoint(what);
    return tc.reduce(e);
}

matrix reduceChecked(const TrigContext& tc, const matrix& m, const std::function<void(const std::string&)>& checkpoint,
                     const std::string& what) {
    matrix r(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) r(i, j) = reduceChecked(tc, m(i, j), checkpoint, what);
    return r;
}

// B(q) link by link in each link's own frame: there the Jacobian columns of link i
// depend only on the joints between, so the polynomials stay small (B never
// depends on q1). b_jk = Σ_i m_i J_v,ij·J_v,ik + J_ω,ijᵀ I_i J_ω,ik (Siciliano (7.16)).
matrix massMatrixInLinkFrames(const SymbolicRobot& robot, const std::vector<matrix>& A, const TrigContext& tc,
                              const std::function<void(const std::string&)>& checkpoint) {
    const int n = tc.size();
    const bool standard = robot.convention == DhConvention::Standard;
    matrix B(n, n);
    for (int i = 0; i < n; ++i) {
        const SymbolicJoint& link = robot.joints[i];
        // rel[f]: pose of frame i+1 (link i) in frame f, for f = 0..i+1.
        std::vector<matrix> rel(i + 2, matrix(4, 4));
        rel[i + 1] = GiNaC::ex_to<matrix>(GiNaC::unit_matrix(4));
        for (int f = i; f >= 0; --f) {
            rel[f] = reduceChecked(tc, A[f].mul(rel[f + 1]), checkpoint, "link " + idx(i) + " in frame " + std::to_string(f));
        }
        std::vector<Vec3> Jv(i + 1), Jw(i + 1);
        const Vec3 com = column(link.com, 0);
        for (int j = 0; j <= i; ++j) {
            checkpoint("J_" + idx(i) + " column " + idx(j));
            const matrix axisFrame = tc.reduce(inverseTransform(rel[standard ? j : j + 1]));  // frame in link frame
            const Vec3 z = column(axisFrame, 2);
            if (robot.joints[j].type == JointType::Revolute) {
                Jv[j] = cross(z, sub(com, translation(axisFrame)));
                Jw[j] = z;
            } else {
                Jv[j] = z;
                Jw[j] = {0, 0, 0};
            }
        }
        const matrix& I = link.inertia;
        for (int j = 0; j <= i; ++j)
            for (int k = j; k <= i; ++k) {
                ex IJw = 0;
                for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 3; ++c) IJw += Jw[j][r] * I(r, c) * Jw[k][c];
                B(j, k) += link.mass * dot(Jv[j], Jv[k]) + IJw;
            }
    }
    for (int j = 0; j < n; ++j)
        for (int k = j; k < n; ++k) {
            B(j, k) = reduceChecked(tc, B(j, k), checkpoint, "b_" + idx(j) + idx(k));
            B(k, j) = B(j, k);
        }
    return B;
}

}  // namespace

// A parameter kept as a symbol and named like the shorthand the derivation writes for
// its own trigonometric symbols (c1 = cos q1, s12 = sin(q1 + q2), c9_10) could not be
// told apart from it in text and LaTeX, and its plain expression would read back as
// the cosine: different mathematics. Such a scene is refused, naming the clash.
// (q1, qd1, qdd1 and t are refused as parameter names in every scene.)
void refuseShorthandParameterNames(const Scene& scene) {
    const int n = scene.robot.dof();
    for (const auto& [name, value] : scene.parameters) {
        const std::optional<TrigName> trig = parseTrigName(name, n);
        if (!trig) continue;
        std::string angle;
        for (int k : trig->indices) angle += (angle.empty() ? "q" : " + q") + std::to_string(k);
        angle = trig->indices.size() > 1 ? "(" + angle + ")" : " " + angle;
        throw InputError("parameters." + name,
                         message(MessageId::ParameterIsTrigShorthand, name, (trig->kind == 'c' ? "cos" : "sin") + angle));
    }
}

Derivation deriveRobot(const Scene& scene, const DerivationOptions& options) {
    const auto lock = lockGinac();
    int currentStep = 0;
    // Between entries: report, and stop when cancelled.
    const auto checkpoint = [&](const std::string& what) {
        throwIfCancelled(options.cancel);
        if (options.progress) options.progress(currentStep, what);
    };
    const int n = scene.robot.dof();
    std::vector<bool> revolute(n);
    for (int i = 0; i < n; ++i) revolute[i] = scene.robot.joints[i].dh.type == JointType::Revolute;
    if (options.mode == ParameterMode::Parametric) refuseShorthandParameterNames(scene);
    TrigContext tc(revolute);
    const SymbolicRobot robot = symbolicRobot(scene, options.mode, tc.t());
    for (const SymbolicJoint& joint : robot.joints) {
        tc.addConstantAngle(joint.alpha);
        tc.addConstantAngle(joint.theta);
    }
    const bool standard = robot.convention == DhConvention::Standard;
    const auto shown = [&](int step) { return step >= options.firstStep && step <= options.lastStep; };

    Derivation d;
    d.system = SystemKind::Robot;
    d.systemName = scene.name;
    d.q = tc.q();
    d.qd = tc.qd();
    d.t = tc.t();
    for (int i = 0; i < n; ++i) {
        d.coordinateNames.push_back("q" + idx(i));
        d.qdd.emplace_back("qdd" + idx(i));
    }
    Stopwatch clock;
    const auto addStep = [&](int number, Message title, StepFormula formula, std::vector<DerivationItem> items) {
        const double seconds = clock.lap();
        currentStep = number + 1;
        checkpoint("step " + std::to_string(currentStep));
        if (!shown(number)) return;
        d.steps.push_back({number, std::move(title), std::move(formula), std::move(items), seconds});
    };
    d.modifiedDH = !standard;

    // 0. DH table, with the joint variables in place.
    {
        matrix table(n, 4);
        for (int i = 0; i < n; ++i) {
            const SymbolicJoint& j = robot.joints[i];
            table(i, 0) = j.a;
            table(i, 1) = j.alpha;
            table(i, 2) = revolute[i] ? j.d : j.d + tc.q(i);
            table(i, 3) = revolute[i] ? j.theta + tc.q(i) : j.theta;
        }
        addStep(0, standard ? MessageId::TitleDhStandard : MessageId::TitleDhModified,
                stepFormula(standard ? "«1»: a_i, α_i, d_i, θ_i; «2»" : "«1»: a_{i−1}, α_{i−1}, d_i, θ_i (Craig); «2»",
                            standard ? R"(«1»:\ a_i,\ \alpha_i,\ d_i,\ \theta_i)" : R"(«1»:\ a_{i-1},\ \alpha_{i-1},\ d_i,\ \theta_i)",
                            {formulaWords(MessageId::FormulaDhRow, {"i"}), formulaWords(MessageId::FormulaDhJointVariable)},
                            {formulaWords(MessageId::FormulaDhRow, {"i"})}),
                {{"DH", Quantity::DhTable, -1, Grouping::Masses, table}});
    }

    // 1. Kinematic model.
    std::vector<matrix> A(n), T(n + 1);
    T[0] = robot.base;
    std::vector<DerivationItem> step1;
    for (int i = 0; i < n; ++i) {
        checkpoint("T_" + idx(i) + "^0");
        A[i] = linkTransform(robot.convention, robot.joints[i], tc, i);
        T[i + 1] = reduceChecked(tc, T[i].mul(A[i]), checkpoint, "T_" + idx(i) + "^0");
        step1.push_back({"A_" + idx(i), Quantity::LinkTransform, i, Grouping::Masses, A[i]});
    }
    for (int i = 0; i < n; ++i) step1.push_back({"T_" + idx(i) + "^0", Quantity::Transform, i, Grouping::Masses, T[i + 1]});
    addStep(
        1, MessageId::TitleKinematicModel,
        stepFormula(
            standard ? "A_i = Rot_z(θ_i) Trans_z(d_i) Trans_x(a_i) Rot_x(α_i),  T_i^0 = A_1 A_2 ⋯ A_i"
                     : "A_i = Rot_x(α_{i−1}) Trans_x(a_{i−1}) Rot_z(θ_i) Trans_z(d_i),  T_i^0 = A_1 A_2 ⋯ A_i",
            standard
                ? R"(A_i = \mathrm{Rot}_z(\theta_i)\,\mathrm{Trans}_z(d_i)\,\mathrm{Trans}_x(a_i)\,\mathrm{Rot}_x(\alpha_i),\quad T_i^0 = A_1 A_2 \cdots A_i)"
                : R"(A_i = \mathrm{Rot}_x(\alpha_{i-1})\,\mathrm{Trans}_x(a_{i-1})\,\mathrm{Rot}_z(\theta_i)\,\mathrm{Trans}_z(d_i),\quad T_i^0 = A_1 A_2 \cdots A_i)"),
        step1);

    // 2. Centres of mass in the base frame.
    std::vector<Vec3> p(n);
    std::vector<DerivationItem> step2;
    for (int i = 0; i < n; ++i) {
        checkpoint("p_c" + idx(i));
        const matrix& com = robot.joints[i].com;
        for (int r = 0; r < 3; ++r)
            p[i][r] = tc.reduce(T[i + 1](r, 0) * com(0, 0) + T[i + 1](r, 1) * com(1, 0) + T[i + 1](r, 2) * com(2, 0) + T[i + 1](r, 3));
        step2.push_back({"p_c" + idx(i), Quantity::ComPosition, i, Grouping::Masses, toMatrix(p[i])});
    }
    addStep(2, MessageId::TitleCentresOfMass,
            stepFormula("p_ci^0 = T_i^0 [r_ci; 1]  (r_ci: «1»)", R"(p_{ci}^0 = T_i^0 \begin{bmatrix} r_{ci} \\ 1 \end{bmatrix})",
                        {formulaWords(MessageId::FormulaComOfLink)}),
            step2);

    // Joint axes in the base frame: z_{i-1} (standard) or z_i (modified).
    std::vector<Vec3> axis(n);
    for (int i = 0; i < n; ++i) axis[i] = column(T[standard ? i : i + 1], 2);

    // 3. Angular velocities.
    if (shown(3)) {
        std::vector<DerivationItem> items;
        for (int i = 0; i < n; ++i) {
            matrix Jw(3, n), w(3, 1);
            for (int j = 0; j <= i; ++j)
                if (revolute[j])
                    for (int r = 0; r < 3; ++r) {
                        Jw(r, j) = axis[j][r];
                        w(r, 0) += axis[j][r] * tc.qd(j);
                    }
            items.push_back({"J_w" + idx(i), Quantity::AngularJacobian, i, Grouping::Masses, Jw});
            items.push_back({"w_" + idx(i), Quantity::AngularVelocity, i, Grouping::Velocities, tc.reduce(w)});
        }
        addStep(3, MessageId::TitleAngularVelocities,
                stepFormula("ω_i^0 = Σ_{j≤i, «1»} z_j «q'_»j = J_ω,i «q'»",
                            R"(\omega_i^0 = \sum_{j \le i} z_{j} «q'_»j = J_{\omega,i}\,«q'»)",
                            {formulaWords(MessageId::FormulaRevoluteJoints)}),
                items);
    }

    // 4. Velocities of the centres of mass: J_v,ci = ∂p_ci/∂q.
    if (shown(4)) {
        std::vector<DerivationItem> items;
        for (int i = 0; i < n; ++i) {
            matrix Jv(3, n), v(3, 1);
            for (int j = 0; j <= i; ++j) {
                checkpoint("J_v,c" + idx(i) + " column " + idx(j));
                for (int r = 0; r < 3; ++r) {
                    Jv(r, j) = tc.reduce(tc.diffq(p[i][r], j));
                    v(r, 0) += Jv(r, j) * tc.qd(j);
                }
            }
            items.push_back({"J_v_c" + idx(i), Quantity::ComJacobian, i, Grouping::Masses, Jv});
            items.push_back({"v_c" + idx(i), Quantity::ComVelocity, i, Grouping::Velocities, tc.reduce(v)});
        }
        addStep(4, MessageId::TitleComVelocities,
                stepFormula("v_ci^0 = d/dt p_ci^0 = J_v,ci «q'»,  J_v,ci = ∂p_ci^0/∂«q»",
                            R"(v_{ci}^0 = \dot{p}_{ci}^0 = J_{v,ci}\,«q'»,\quad J_{v,ci} = \frac{\partial p_{ci}^0}{\partial «q»})"),
                items);
    }

    // 5. Link inertia tensors in the base frame.
    if (shown(5)) {
        std::vector<DerivationItem> items;
        for (int i = 0; i < n; ++i) {
            const matrix R = rotation(T[i + 1]);
            items.push_back({"I_l" + idx(i) + "^0", Quantity::LinkInertia, i, Grouping::Masses,
                             reduceChecked(tc, R.mul(robot.joints[i].inertia).mul(R.transpose()), checkpoint, "I_l" + idx(i) + "^0")});
        }
        addStep(5, MessageId::TitleLinkInertias, stepFormula("I_li^0 = R_i^0 I_li (R_i^0)ᵀ", R"(I_{li}^0 = R_i^0\, I_{li}\, (R_i^0)^T)"),
                items);
    }

    // 6. Potential energy: gravity and springs, if declared.
    ex Epot = 0;
    if (robot.hasGravity)
        for (int i = 0; i < n; ++i) Epot -= robot.joints[i].mass * dot(column(robot.gravity, 0), p[i]);
    for (const SymbolicTerm& spring : robot.springs)
        Epot += GiNaC::numeric(1, 2) * spring.value * GiNaC::pow(tc.q(spring.joint) - spring.extra, 2);
    // A spring on a revolute joint is written in q_i itself, not in c_i, s_i.
    Epot = reduceChecked(tc, Epot, checkpoint, "E_pot");
    d.Epot = Epot;
    addStep(6, MessageId::TitlePotentialEnergy,
            stepFormula(std::string(robot.hasGravity ? "E_pot = −Σ_i m_i g0ᵀ p_ci^0" : "E_pot = 0 («1»)") +
                            (robot.springs.empty() ? "" : " + Σ_j ½ K_j («q_»j − «q_»j,rest)²"),
                        std::string(robot.hasGravity ? R"(E_{\mathrm{pot}} = -\sum_{i} m_i\, g_0^T p_{ci}^0)" : R"(E_{\mathrm{pot}} = 0)") +
                            (robot.springs.empty() ? "" : R"( + \sum_j \tfrac{1}{2} K_j («q_»j - «q_»{j,\mathrm{rest}})^2)"),
                        {formulaWords(MessageId::FormulaNoGravity)}),
            {{"E_pot", Quantity::PotentialEnergy, -1, Grouping::Masses, Epot}});

    // 7. Kinetic energy and B(q); the motors' rotors add their armature to b_jj.
    d.B = massMatrixInLinkFrames(robot, A, tc, checkpoint);
    auto motorLock = lockGinac();
    matrix motors(n, n);
    bool hasMotors = false;
    for (int j = 0; j < n; ++j)
        if (!robot.joints[j].armature.is_zero()) {
            motors(j, j) = robot.joints[j].armature;
            d.B(j, j) += motors(j, j);
            hasMotors = true;
        }
    ex Ekin = 0;
    for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) Ekin += GiNaC::numeric(1, 2) * d.B(j, k) * tc.qd(j) * tc.qd(k);
    d.Ekin = reduceChecked(tc, Ekin, checkpoint, "E_kin");
    std::string motorValues;
    for (const auto& [name, value] : robot.motorSymbols) {
        std::ostringstream number;
        number << value;
        motorValues += (motorValues.empty() ? "" : ", ") + name + " = " + number.str();
    }
    if (!motorValues.empty()) motorValues = " (" + motorValues + ")";
    std::vector<DerivationItem> step7;
    if (hasMotors) step7.push_back({"B_m", Quantity::MotorInertia, -1, Grouping::Masses, motors});
    step7.push_back({"B", Quantity::MassMatrix, -1, Grouping::Masses, d.B});
    step7.push_back({"E_kin", Quantity::KineticEnergy, -1, Grouping::Velocities, d.Ekin});
    StepFormula formula7 =
        stepFormula(std::string("E_kin = ½ Σ_i (m_i v_ciᵀ v_ci + ω_iᵀ I_li^0 ω_i)") +
                        (hasMotors ? " + ½ Σ_j Jm_j G_j² «q'_»j²" : "") + " = ½ «q'»ᵀ «B»(«q») «q'»" +
                        (hasMotors ? ";  «1»: «B» = «B»_links + «B»_m, «B»_m = diag(Jm_j G_j²) («2»)" : ""),
                    std::string(
                        R"(E_{\mathrm{kin}} = \tfrac{1}{2}\sum_i \left(m_i\, v_{ci}^T v_{ci} + \omega_i^T I_{li}^0\, \omega_i\right))") +
                        (hasMotors ? R"( + \tfrac{1}{2}\sum_j J_{m,j} G_j^2 «q'_»j^2)" : "") + R"( = \tfrac{1}{2}\,«q'»^T «B»(«q»)\,«q'»)" +
                        (hasMotors ? R"(,\quad «B» = «B»_{\mathrm{links}} + «B»_m,\ «B»_m = \mathrm{diag}(J_{m,j} G_j^2)\ «1»)" : ""),
                    {formulaWords(MessageId::FormulaMotorsArmature, {"G_j «q'_»j", "«b»_jj"}),
                     formulaWords(MessageId::FormulaArmatureGiven)},
                    {formulaWords(MessageId::FormulaRotorTurnsAt, {"j", "G_j «q'_»j"})});
    if (hasMotors) formula7.text.push_back(formulaMath(motorValues));
    addStep(7, MessageId::TitleKineticEnergy, std::move(formula7), step7);

    // 8. Equations of motion (Lagrange–d'Alembert).
    d.g = matrix(n, 1);
    for (int i = 0; i < n; ++i) {
        checkpoint("g_" + idx(i));
        d.g(i, 0) = reduceChecked(tc, tc.diffq(Epot, i), checkpoint, "g_" + idx(i));
    }
    std::vector<matrix> dB(n);
    for (int k = 0; k < n; ++k) {
        dB[k] = matrix(n, n);
        for (int i = 0; i < n; ++i)
            for (int j = i; j < n; ++j) {
                checkpoint("db_" + idx(i) + idx(j) + "/dq_" + idx(k));
                dB[k](i, j) = dB[k](j, i) = tc.diffq(d.B(i, j), k);
            }
    }
    d.C = matrix(n, n);
    christoffelMatrix<ex>(n, dB, tc.qd(), d.C);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) d.C(i, j) = reduceChecked(tc, d.C(i, j), checkpoint, "c_" + idx(i) + idx(j));
    d.Q = effectForces(robot, tc.qd());
    d.actuated = actuatedJoints(scene.effects, n);  // the torques' joints and a controller's
    d.underactuated = static_cast<int>(d.actuated.size()) < n;

    std::vector<DerivationItem> step8{{"g", Quantity::GravityVector, -1, Grouping::Masses, d.g},
                                      {"C", Quantity::CoriolisMatrix, -1, Grouping::Velocities, d.C},
                                      {"Q", Quantity::GeneralizedForces, -1, Grouping::Masses, d.Q}};
    for (int i = 0; i < n; ++i) {
        ex lhs = d.g(i, 0);
        for (int j = 0; j < n; ++j) lhs += d.B(i, j) * d.qdd[j] + d.C(i, j) * tc.qd(j);
        step8.push_back({"equation_" + idx(i), Quantity::EquationOfMotion, i, Grouping::Masses, lhs == d.Q(i, 0)});
    }
    addStep(
        8, MessageId::TitleEquationsOfMotion,
        stepFormula(
            "«g» = ∂E_pot/∂«q»;  c_ij = Σ_k ½ (∂«b»_ij/∂«q_»k + ∂«b»_ik/∂«q_»j − ∂«b»_jk/∂«q_»i) «q'_»k;  "
            "«Q»: «1»;  «B» «q''» + C «q'» + «g» = «Q»;  «q''» = «B»⁻¹ («Q» − C «q'» − «g»);  «2»",
            R"(«g» = \frac{\partial E_{\mathrm{pot}}}{\partial «q»},\quad c_{ij} = \sum_k \tfrac{1}{2}\left(\frac{\partial «b»_{ij}}{\partial «q_»k} + \frac{\partial «b»_{ik}}{\partial «q_»j} - \frac{\partial «b»_{jk}}{\partial «q_»i}\right)«q'_»k,\quad «B»«q''» + C«q'» + «g» = «Q»,\quad «q''» = «B»^{-1}(«Q» - C«q'» - «g»))",
            {formulaWords(MessageId::FormulaNonConservativeOnly), formulaActuation(d.actuated, d.coordinateNames)}),
        step8);

    // 9. The control law, when the scene declares a controller: B, C, g at work.
    if (scene.effects.control && shown(controlStepNumber)) {
        checkpoint("tau");
        DerivationStep step = controlLawStep(scene, d, [&](const ex& e) { return tc.reduce(e); });
        step.seconds = clock.lap();
        d.steps.push_back(std::move(step));
    }

    d.trigToFunctions = tc.toFunctions();
    d.parameterValues = robot.parameterValues;
    d.symbolLinks = linkSymbols(robot);
    d.typedDecimals = robot.typedDecimals;
    return d;
}

}  // namespace ll::symbolic
