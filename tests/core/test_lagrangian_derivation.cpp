// Lagrangian systems typed by hand: the course notes' mass–spring pair exactly, a
// hand-written planar 2R arm (relative and absolute angles) against the numeric
// dynamics of core/dynamics, the Lagrange items against B q̈ + C q̇ + g, and every
// input error with the field (and the position) it names.
#include "test_registry.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/compiled_body_poses.hpp"
#include "core/symbolic/compiled_derivation.hpp"
#include "core/symbolic/derivation_evaluator.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"
#include "core/present/derivation_document.hpp"
#include "core/present/display_tree.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_lagrangian_derivation {

using namespace ll;
using namespace ll::symbolic;
using GiNaC::ex;
using Json = nlohmann::ordered_json;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A Lagrangian scene: parameters, then the "lagrangian" block, then anything else.
std::string sceneJson(const Json& parameters, const Json& lagrangian, const Json& extra = Json::object()) {
    Json j = {{"format", "lagrangelab-scene/1"}, {"name", "test"}, {"parameters", parameters}, {"lagrangian", lagrangian}};
    for (const auto& [key, value] : extra.items()) j[key] = value;
    return j.dump();
}

Scene scene(const Json& parameters, const Json& lagrangian, const Json& extra = Json::object()) {
    Scene s = parseScene(sceneJson(parameters, lagrangian, extra));
    if (s.initial.q.size() == 0) {
        s.initial.q = Eigen::VectorXd::Zero(s.dof());
        s.initial.qd = Eigen::VectorXd::Zero(s.dof());
    }
    return s;
}

// The first error `call` throws as InputError, as "field: message"; empty if none.
template <class Call>
std::string firstError(Call call) {
    try {
        call();
    } catch (const InputError& e) {
        for (const Diagnostic& d : e.diagnostics())
            if (d.severity == Severity::Error) return d.text();  // with its hint line, if any
    }
    return {};
}

#define EXPECT_ERROR(call, ...)                                                                                            \
    do {                                                                                                                   \
        const std::string error_ = firstError([&] { (void)(call); });                                                      \
        QVERIFY2(!error_.empty(), "no InputError");                                                                        \
        for (const char* part : {__VA_ARGS__}) QVERIFY2(contains(error_, part), (error_ + "  -- lacks: " + part).c_str()); \
    } while (false)

const GiNaC::symbol& parameter(const Derivation& d, const std::string& name) {
    for (const ex& relation : d.parameterValues)
        if (GiNaC::ex_to<GiNaC::symbol>(relation.lhs()).get_name() == name) return GiNaC::ex_to<GiNaC::symbol>(relation.lhs());
    throw std::out_of_range("no parameter " + name);
}

const DerivationItem& item(const Derivation& d, const std::string& name) {
    for (const DerivationStep& step : d.steps)
        for (const DerivationItem& i : step.items)
            if (i.name == name) return i;
    throw std::out_of_range("no item " + name);
}

bool equal(const ex& a, const ex& b) { return (a - b).expand().normal().is_zero(); }

// The planar 2R arm of test_support.hpp written by hand: relative angles q1, q2 (the
// DH coordinates) or absolute angles th1, th2 = q1 + q2. COM i at l_i from joint i.
const Json kArmParameters = {{"a1", 1.0}, {"a2", 0.8},  {"l1", 0.45}, {"l2", 0.35}, {"m1", 2.0},
                             {"m2", 1.5}, {"I1", 0.17}, {"I2", 0.08}, {"g", 9.81}};
const Json kArmRelative = {{"coordinates", {"q1", "q2"}},
                           {"kinetic", "m1*l1^2*q1_dot^2/2 + I1*q1_dot^2/2 + I2*(q1_dot + q2_dot)^2/2"
                                       " + m2*((a1*sin(q1)*q1_dot + l2*sin(q1 + q2)*(q1_dot + q2_dot))^2"
                                       " + (a1*cos(q1)*q1_dot + l2*cos(q1 + q2)*(q1_dot + q2_dot))^2)/2"},
                           {"potential", "m1*g*l1*sin(q1) + m2*g*(a1*sin(q1) + l2*sin(q1 + q2))"}};
const Json kArmAbsolute = {{"coordinates", {"th1", "th2"}},
                           {"kinetic",
                            "(m1*l1^2 + I1)*th1_dot^2/2 + I2*th2_dot^2/2"
                            " + m2*((a1*sin(th1)*th1_dot + l2*sin(th2)*th2_dot)^2 + (a1*cos(th1)*th1_dot + l2*cos(th2)*th2_dot)^2)/2"},
                           {"potential", "m1*g*l1*sin(th1) + m2*g*(a1*sin(th1) + l2*sin(th2))"}};

struct NumericTerms {
    Eigen::MatrixXd B, C;
    Eigen::VectorXd g;
};

NumericTerms armDynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    const RobotModel robot = test::Planar2R{}.model();
    Effects effects;
    effects.gravity = Eigen::Vector3d(0, -9.81, 0);
    RobotData data(robot);
    forwardKinematics(robot, data, q);
    computeMassMatrix(robot, data);
    computeCoriolisMatrix(robot, data, qd);
    computePotentialGradient(robot, data, effects, q);
    return {data.B, data.C, data.g};
}

}  // namespace

class TestLagrangianDerivation : public QObject {
    Q_OBJECT
private slots:
    // The course notes' result, symbol for symbol.
    void massSpringPairIsTheCourseNotesResult() {
        const Scene s = parseScene(readFile(std::string(LL_EXAMPLES_DIR) + "/mass_spring_pair_lagrangian.json"));
        const Derivation d = deriveLagrangian(s, ParameterMode::Parametric);
        QCOMPARE(d.coordinateNames, (std::vector<std::string>{"theta1", "theta2"}));
        QCOMPARE(d.q[0].get_name(), std::string("theta1"));
        QCOMPARE(d.qd[1].get_name(), std::string("theta2_dot"));
        QCOMPARE(d.qdd[0].get_name(), std::string("theta1_ddot"));
        const ex I1 = parameter(d, "I1"), I2 = parameter(d, "I2"), K1 = parameter(d, "K1"), K2 = parameter(d, "K2"),
                 tau = parameter(d, "tau");
        const ex th1 = d.q[0], th2 = d.q[1];
        // B = diag(I1, I2), C = 0, g = ∂E_pot/∂q, Q = (0, τ)
        QVERIFY(equal(d.B(0, 0), I1) && equal(d.B(1, 1), I2) && d.B(0, 1).is_zero() && d.B(1, 0).is_zero());
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) QVERIFY(d.C(i, j).is_zero());
        QVERIFY(equal(d.g(0, 0), K1 * th1 + K2 * (th1 - th2)));
        QVERIFY(equal(d.g(1, 0), -K2 * (th1 - th2)));
        QVERIFY(d.Q(0, 0).is_zero());
        QVERIFY(equal(d.Q(1, 0), tau));
        // I1 θ̈1 + K1 θ1 + K2 (θ1 − θ2) = 0 and I2 θ̈2 − K2 (θ1 − θ2) = τ
        const ex eq1 = item(d, "equation_1").value, eq2 = item(d, "equation_2").value;
        QVERIFY(equal(eq1.lhs(), I1 * d.qdd[0] + K1 * th1 + K2 * (th1 - th2)) && eq1.rhs().is_zero());
        QVERIFY(equal(eq2.lhs(), I2 * d.qdd[1] - K2 * (th1 - th2)) && equal(eq2.rhs(), tau));
        // The Lagrange items of the notes.
        QVERIFY(equal(item(d, "L").value,
                      I1 * pow(d.qd[0], 2) / 2 + I2 * pow(d.qd[1], 2) / 2 - K1 * pow(th1, 2) / 2 - K2 * pow(th1 - th2, 2) / 2));
        QVERIFY(equal(item(d, "dL/dtheta1_dot").value, I1 * d.qd[0]));
        QVERIFY(equal(item(d, "d/dt dL/dtheta2_dot").value, I2 * d.qdd[1]));
        QVERIFY(equal(item(d, "dL/dtheta1").value, -K1 * th1 - K2 * (th1 - th2)));
        QVERIFY(equal(d.Ekin, I1 * pow(d.qd[0], 2) / 2 + I2 * pow(d.qd[1], 2) / 2));
        // Steps numbered as the robot's: 0 coordinates, 6 E_pot, 7 E_kin and B, 8 equations.
        std::vector<int> numbers;
        for (const DerivationStep& step : d.steps) numbers.push_back(step.number);
        QCOMPARE(numbers, (std::vector<int>{0, 6, 7, 8}));
        // τ is an input on θ2 only: underactuated.
        QCOMPARE(d.actuated, std::vector<int>{1});
        QVERIFY(d.underactuated);
        QCOMPARE(int(d.trigToFunctions.nops()), 0);

        // Numeric mode: exact numbers, no parameter symbols left.
        const Derivation n = deriveLagrangian(s, ParameterMode::Numeric);
        QVERIFY(n.parameterValues.nops() == 0);
        QVERIFY(equal(n.B(0, 0), GiNaC::numeric(1, 2)) && equal(n.B(1, 1), GiNaC::numeric(1, 5)));
        QVERIFY(equal(n.g(0, 0), 14 * n.q[0] - 4 * n.q[1]));
        QVERIFY(equal(n.Q(1, 0), 1));
    }

    // L printed as the notes write it, L = E_kin − E_pot: every term with a velocity
    // (E_kin's) before every term without one (E_pot's, negated), in each example typed
    // as a Lagrangian; its value still L itself.
    void lagrangianIsPrintedKineticFirst() {
        for (const char* name : {"mass_spring_pair_lagrangian.json", "elastic_pendulum.json"}) {
            const Scene s = parseScene(readFile(std::string(LL_EXAMPLES_DIR) + "/" + name));
            const Derivation d = deriveLagrangian(s, ParameterMode::Parametric);
            const auto doc = present::displayDocument(d);
            const present::DisplayItem* L = nullptr;
            for (const auto& step : doc->steps)
                for (const auto& i : step.items)
                    if (i.quantity == Quantity::Lagrangian) L = &i;
            QVERIFY2(L && L->value && L->value->kind == present::DisplayKind::Sum, name);
            std::vector<bool> kinetic;
            for (const auto& term : L->value->children)
                kinetic.push_back(present::renderDisplay(*term, present::DisplayStyle::Text).find("\u0307") != std::string::npos);
            QVERIFY2(kinetic.size() >= 2 && kinetic.front() && !kinetic.back(), name);
            QVERIFY2(std::is_sorted(kinetic.begin(), kinetic.end(), std::greater<bool>()),
                     name);  // no velocity term after the first without
            // the same L: E_kin − E_pot
            QVERIFY(equal(item(d, "L").value, d.Ekin - d.Epot));
        }
    }

    // The Lagrange items and the matrix form say the same for a system with C ≠ 0:
    // d/dt ∂L/∂q̇ − ∂L/∂q = B q̈ + C q̇ + g, and Ḃ − 2C is skew-symmetric.
    void lagrangeItemsAgreeWithMatrixForm() {
        const Scene s = parseScene(readFile(std::string(LL_EXAMPLES_DIR) + "/elastic_pendulum.json"));
        for (const Scene& system : {s, scene(kArmParameters, kArmRelative)}) {
            const Derivation d = deriveLagrangian(system);
            const int n = static_cast<int>(d.q.size());
            for (int i = 0; i < n; ++i) {
                const std::string q = d.q[i].get_name(), qd = d.qd[i].get_name();
                const ex lagrange = item(d, "d/dt dL/d" + qd).value - item(d, "dL/d" + q).value;
                const ex matrix = item(d, "equation_" + std::to_string(i + 1)).value.lhs();
                // equal up to sin² = 1 − cos² (B and C are written without sin²)
                ex difference = (lagrange - matrix).expand();
                for (int pass = 0; pass < 4; ++pass)
                    difference = difference
                                     .subs(GiNaC::pow(GiNaC::sin(GiNaC::wild(0)), GiNaC::wild(1)) ==
                                           GiNaC::pow(GiNaC::sin(GiNaC::wild(0)), GiNaC::wild(1) - 2) *
                                               (1 - GiNaC::pow(GiNaC::cos(GiNaC::wild(0)), 2)))
                                     .expand();
                QVERIFY2(difference.is_zero(), qPrintable(QString::fromStdString(system.name + " " + q)));
                for (int j = 0; j < n; ++j) {
                    ex Bdot_ij = 0, Bdot_ji = 0;
                    for (int k = 0; k < n; ++k) {
                        Bdot_ij += d.B(i, j).diff(d.q[k]) * d.qd[k];
                        Bdot_ji += d.B(j, i).diff(d.q[k]) * d.qd[k];
                    }
                    QVERIFY(((Bdot_ij - 2 * d.C(i, j)) + (Bdot_ji - 2 * d.C(j, i))).expand().is_zero());
                }
            }
        }
        // The elastic pendulum's textbook terms.
        const Derivation d = deriveLagrangian(s, ParameterMode::Parametric);
        const ex m = parameter(d, "m"), r = d.q[0];
        QVERIFY(equal(d.B(1, 1), m * r * r) && d.B(0, 1).is_zero());
        QVERIFY(equal(d.C(0, 1), -m * r * d.qd[1]) && equal(d.C(1, 0), m * r * d.qd[1]) && equal(d.C(1, 1), m * r * d.qd[0]));
        QVERIFY(d.underactuated && d.actuated.empty());
    }

    // A hand-written 2R arm, in relative and in absolute angles, against core/dynamics.
    void planarArmAgreesWithNumericDynamics() {
        const Derivation relative = deriveLagrangian(scene(kArmParameters, kArmRelative));
        const Derivation absolute = deriveLagrangian(scene(kArmParameters, kArmAbsolute), ParameterMode::Numeric);
        const DerivationEvaluator slow(relative);
        const CompiledLagrangian fast = compileDerivation(relative), fastAbsolute = compileDerivation(absolute);
        Eigen::Matrix2d J;  // θ = J q
        J << 1, 0, 1, 1;
        std::mt19937 rng(5);
        for (int k = 0; k < 20; ++k) {
            const Eigen::VectorXd q = test::randomVector(rng, 2, 3.0), qd = test::randomVector(rng, 2, 2.0);
            const NumericTerms expected = armDynamics(q, qd);
            const ModelTerms r = fast.terms(q, qd, 0.0);
            QVERIFY2(test::scaledError(r.B, expected.B) < 1e-10, "B, relative");
            QVERIFY2(test::scaledError(r.C, expected.C) < 1e-10, "C, relative");
            QVERIFY2(test::scaledError(r.g, expected.g) < 1e-10, "g, relative");
            QVERIFY(test::scaledError(slow.value(relative.B, q, qd), expected.B) < 1e-10);
            QVERIFY(test::scaledError(slow.value(relative.C, q, qd), expected.C) < 1e-10);
            // Absolute angles: B_q = Jᵀ B_θ J, C_q = Jᵀ C_θ J, g_q = Jᵀ g_θ (J constant).
            const ModelTerms a = fastAbsolute.terms(J * q, J * qd, 0.0);
            QVERIFY2(test::scaledError(Eigen::MatrixXd(J.transpose() * a.B * J), expected.B) < 1e-10, "B, absolute");
            QVERIFY2(test::scaledError(Eigen::MatrixXd(J.transpose() * a.C * J), expected.C) < 1e-10, "C, absolute");
            QVERIFY2(test::scaledError(Eigen::VectorXd(J.transpose() * a.g), expected.g) < 1e-10, "g, absolute");
        }
        // sin² + cos² is gone from B: b22 = m2 l2² + I2 exactly.
        QVERIFY(equal(absolute.B(1, 1), GiNaC::numeric(3, 2) * GiNaC::numeric(35, 100) * GiNaC::numeric(35, 100) + GiNaC::numeric(8, 100)));
    }

    void effectsAddToQ() {
        const Scene s =
            scene({{"m", 2}, {"k", 3}, {"b", 0.5}}, {{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2"}, {"potential", "k*x^2/2"}},
                  {{"effects",
                    {{"viscous", {{{"joint", 1}, {"coefficient", "b"}}}},
                     {"torques", {{{"joint", 1}, {"kind", "constant"}, {"value", 2}}}}}}});
        const Derivation d = deriveLagrangian(s);
        QVERIFY(equal(d.Q(0, 0), 2 - parameter(d, "b") * d.qd[0]));
        QCOMPARE(d.actuated, std::vector<int>{0});
        QVERIFY(!d.underactuated);
        // Friction in `forces` is no input.
        const Derivation f =
            deriveLagrangian(scene({{"m", 2}}, {{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2"}, {"forces", {"-x_dot^3"}}}));
        QVERIFY(f.actuated.empty());
    }

    // --- input errors -------------------------------------------------------------

    void kineticEnergyMustBeQuadratic() {
        const Json p = {{"m", 1}, {"k", 2}};
        const auto derive = [&](const char* kinetic) {
            return deriveLagrangian(scene(p, {{"coordinates", {"x", "y"}}, {"kinetic", kinetic}}));
        };
        EXPECT_ERROR(derive("m*x_dot^2/2 + m*y_dot^2/2 + m*x_dot"), "lagrangian.kinetic:", "not a quadratic form", "is left over");
        EXPECT_ERROR(derive("m*x_dot^2/2 + m*y_dot^2/2 + k*x^2"), "lagrangian.kinetic:", "not a quadratic form");
        EXPECT_ERROR(derive("m*x_dot^4 + m*y_dot^2"), "lagrangian.kinetic:", "not quadratic", "x_dot");
        EXPECT_ERROR(derive("m*x_dot^2/2 + m*sqrt(y_dot^2)"), "lagrangian.kinetic:", "quadratic");
        // A mixed term that is quadratic is fine: B = [[2m, 1], [1, 2m]].
        const Derivation d = derive("m*x_dot^2 + m*y_dot^2 + x_dot*y_dot");
        QVERIFY(equal(d.B(0, 1), 1));
    }

    void dependentCoordinatesAreNamed() {
        // y moves with x: the body is at x + 2y, so (x_dot, y_dot) ∝ (1, -0.5) moves nothing.
        EXPECT_ERROR(deriveLagrangian(scene({{"m", 1}}, {{"coordinates", {"x", "y"}}, {"kinetic", "m*(x_dot + 2*y_dot)^2/2"}})),
                     "lagrangian.coordinates:", "not positive definite", "not independent or not minimal", "(x_dot, y_dot) = (1, -0.5)");
        // A coordinate with no kinetic energy at all.
        EXPECT_ERROR(deriveLagrangian(scene({{"m", 1}}, {{"coordinates", {"x", "z"}}, {"kinetic", "m*x_dot^2/2"}})),
                     "lagrangian.coordinates:", "(x_dot, z_dot) = (0, 1)");
        // Singular only where the system starts: polar coordinates at r = 0.
        const Json polar = {{"coordinates", {"r", "phi"}}, {"kinetic", "m*(r_dot^2 + r^2*phi_dot^2)/2"}};
        EXPECT_ERROR(deriveLagrangian(scene({{"m", 1}}, polar, {{"initial", {{"q", {0, 0}}}}})),
                     "lagrangian.coordinates:", "initial state q = [0, 0]");
        QVERIFY(firstError([&] { deriveLagrangian(scene({{"m", 1}}, polar, {{"initial", {{"q", {1, 0}}}}})); }).empty());
        // A negative mass.
        EXPECT_ERROR(deriveLagrangian(scene({{"m", -1}}, {{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2"}})),
                     "lagrangian.coordinates:", "negative kinetic energy");
        // B that cannot be evaluated at the start.
        EXPECT_ERROR(deriveLagrangian(scene({{"m", 1}}, {{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/(2*x)"}})),
                     "lagrangian.kinetic:", "initial state");
    }

    void conservativeForcesBelongInThePotential() {
        const Json p = {{"m", 1}, {"k", 2}, {"tau", 1}};
        const auto derive = [&](Json forces) {
            return deriveLagrangian(scene(p, {{"coordinates", {"x", "y"}}, {"kinetic", "m*(x_dot^2 + y_dot^2)/2"}, {"forces", forces}},
                                          {{"initial", {{"q", {0.1, 0.2}}}}}));
        };
        EXPECT_ERROR(derive({"-k*x", 0}), "lagrangian.forces[0]:", "conservative", "lagrangian.potential", "V = ", "x^2");
        EXPECT_ERROR(derive({"-k*y", "-k*x"}), "lagrangian.forces[0]:", "gradient of a potential", "V = ");
        EXPECT_ERROR(derive({0, "-m*9.81 - k*y^3"}), "lagrangian.forces[1]:", "conservative");
        // Not conservative: inputs, friction, a curl (a rotating field), time-dependent forces.
        for (const Json& forces :
             {Json{0, "tau"}, Json{"-k*x_dot", "-k*y_dot"}, Json{"-y", "x"}, Json{"-k*x*sin(t)", 0}, Json{"tau", "tau"}})
            QVERIFY2(firstError([&] { derive(forces); }).empty(), forces.dump().c_str());
    }

    void potentialMayNotUseVelocities() {
        EXPECT_ERROR(parseScene(
                         sceneJson({{"k", 1}}, {{"coordinates", {"x"}}, {"kinetic", "x_dot^2/2"}, {"potential", "k*x^2/2 + k*x_dot"}})),
                     "lagrangian.potential:", "velocity 'x_dot' at position 13", "coordinates only");
        EXPECT_ERROR(parseScene(sceneJson({{"k", 1}}, {{"coordinates", {"x"}}, {"kinetic", "x_dot^2/2 + t"}})),
                     "lagrangian.kinetic:", "time", "position 13");
    }

    void expressionErrorsNameFieldAndPosition() {
        const Json p = {{"m", 1}, {"k", 2}};
        const auto parse = [&](Json lagrangian) { return parseScene(sceneJson(p, lagrangian)); };
        EXPECT_ERROR(parse({{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2 + zz"}}),
                     "lagrangian.kinetic:", "unknown symbol 'zz' at position 15", "known: x, x_dot, t, m, k");
        EXPECT_ERROR(parse({{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2"}, {"potential", "k*x^2/2 +* x"}}),
                     "lagrangian.potential:", "syntax error at position 10");
        EXPECT_ERROR(parse({{"coordinates", {"x"}}, {"kinetic", "x_dot^2/(k-2)"}}), "lagrangian.kinetic:", "division by zero",
                     "'/' at position 8");
        EXPECT_ERROR(parse({{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2"}, {"forces", {"1/(x-x)"}}}),
                     "lagrangian.forces[0]:", "division by zero", "'/' at position 2");
        EXPECT_ERROR(parse({{"coordinates", {"x"}},
                            {"kinetic", "m*x_dot^2/2"},
                            {"bodies", {{{"shape", "sphere"}, {"size", {0.1}}, {"position", {"x", "y", 0}}}}}}),
                     "lagrangian.bodies[0].position[1]:", "unknown symbol 'y'");
        EXPECT_ERROR(parse({{"coordinates", {"x"}},
                            {"kinetic", "m*x_dot^2/2"},
                            {"bodies", {{{"shape", "sphere"}, {"size", {0.1}}, {"position", {"x_dot", 0, 0}}}}}}),
                     "lagrangian.bodies[0].position[0]:", "velocity");
    }

    void sceneStructureErrors() {
        const Json p = {{"m", 1}, {"k", 2}};
        const Json ok = {{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2"}};
        // Coordinate names: identifiers, unique, not reserved, not a parameter, velocity free.
        for (const auto& [names, part] : std::vector<std::pair<Json, const char*>>{{{"x", "x"}, "already taken"},
                                                                                   {{"pi"}, "reserved"},
                                                                                   {{"k"}, "already taken"},
                                                                                   {{"2x"}, "not a name"},
                                                                                   {{"x_dot"}, "_dot"},
                                                                                   {{"sin"}, "reserved"}}) {
            Json l = ok;
            l["coordinates"] = names;
            EXPECT_ERROR(parseScene(sceneJson(p, l)), "lagrangian.coordinates[", part);
        }
        EXPECT_ERROR(parseScene(sceneJson({{"x_dot", 1}}, ok)), "lagrangian.coordinates[0]:", "'x_dot'");
        // Unknown keys name their path; robot and lagrangian exclude each other.
        Json typo = ok;
        typo["kinetik"] = "x";
        EXPECT_ERROR(parseScene(sceneJson(p, typo)), "lagrangian.kinetik:", "unknown key");
        EXPECT_ERROR(parseScene(sceneJson(p, ok, {{"robot", {{"convention", "standard"}, {"joints", {{{"mass", 1}}}}}}})),
                     "lagrangian:", "either");
        EXPECT_ERROR(parseScene(sceneJson(p, {{"coordinates", {"x"}}})), "lagrangian.kinetic:", "missing");
        EXPECT_ERROR(parseScene(sceneJson(p, ok,
                                          {{"lagrangian",
                                            {{"coordinates", {"x"}},
                                             {"kinetic", "m*x_dot^2/2"},
                                             {"bodies", {{{"shape", "rod"}, {"size", {1}}, {"angle", "x"}}}}}}})),
                     "lagrangian.bodies[0].angle:", "unknown key for a rod");
        // Validation: gravity and springs belong in the potential; sizes by coordinates.
        const auto validate = [&](const Json& extra) { return requireValidScene(parseScene(sceneJson(p, ok, extra))); };
        EXPECT_ERROR(validate({{"effects", {{"gravity", {0, -9.81, 0}}}}}), "effects.gravity:", "write it in the potential");
        EXPECT_ERROR(validate({{"effects", {{"springs", {{{"joint", 1}, {"stiffness", 1}}}}}}}), "effects.springs:", "potential");
        EXPECT_ERROR(validate({{"effects", {{"viscous", {{{"joint", 2}, {"coefficient", 1}}}}}}}),
                     "effects.viscous[0].joint:", "coordinate 2 does not exist");
        EXPECT_ERROR(validate({{"initial", {{"q", {1, 2}}}}}), "initial.q:", "1 coordinates");
        EXPECT_ERROR(validate({{"effects", {{"coulomb", {{{"joint", 1}, {"force", 1}, {"model", "stick"}}}}}}}),
                     "effects.coulomb[0].model:", "tanh");
        EXPECT_ERROR(validate({{"lagrangian", {{"coordinates", {"x"}}, {"kinetic", "m*x_dot^2/2"}, {"forces", {1, 2}}}}}),
                     "lagrangian.forces:", "one per coordinate");
        QVERIFY(firstError([&] { validate({{"initial", {{"q", {1}}}}}); }).empty());
    }

    // The 3D view's bodies follow the coordinates.
    void bodiesArePosedByTheCoordinates() {
        const Scene pendulum = parseScene(readFile(std::string(LL_EXAMPLES_DIR) + "/elastic_pendulum.json"));
        const BodyPoses poses = compileBodyPoses(pendulum);
        QCOMPARE(poses.count(), 3);
        std::vector<BodyPose> out;
        poses.evaluate(Eigen::Vector2d(1.2, 0.5), 0.0, out);
        const Eigen::Vector3d bob(1.2 * std::sin(0.5), -1.2 * std::cos(0.5), 0);
        QVERIFY((out[2].pose.translation() - bob).norm() < 1e-15);  // sphere at the bob
        QVERIFY(std::abs(out[1].length - 1.2) < 1e-15);             // the spring, pivot to bob
        QVERIFY((out[1].pose.translation() - bob / 2).norm() < 1e-15);
        QVERIFY((out[1].pose.linear() * Eigen::Vector3d::UnitZ() - bob.normalized()).norm() < 1e-12);
        const Scene pair = parseScene(readFile(std::string(LL_EXAMPLES_DIR) + "/mass_spring_pair_lagrangian.json"));
        BodyPoses discs = compileBodyPoses(pair);
        discs.evaluate(Eigen::Vector2d(0.3, -0.2), 0.0, out);
        QVERIFY((out[0].pose.linear() - Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix()).norm() < 1e-15);
        QVERIFY((out[1].pose.translation() - Eigen::Vector3d(0.3 * std::cos(0.3), 0.3 * std::sin(0.3), 0.03)).norm() < 1e-15);
        QVERIFY((out[2].pose.linear() - Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix()).norm() < 1e-15);
    }

    void sceneRoundTrips() {
        for (const char* file : {"mass_spring_pair_lagrangian.json", "elastic_pendulum.json"}) {
            const Scene a = parseScene(readFile(std::string(LL_EXAMPLES_DIR) + "/" + file));
            const std::string text = serializeScene(a);
            const Scene b = parseScene(text);
            QVERIFY(a.lagrangian && b.lagrangian);
            QCOMPARE(b.lagrangian->coordinates, a.lagrangian->coordinates);
            QCOMPARE(b.lagrangian->kinetic, a.lagrangian->kinetic);
            QCOMPARE(b.lagrangian->potential, a.lagrangian->potential);
            QCOMPARE(b.lagrangian->forces, a.lagrangian->forces);
            QCOMPARE(b.lagrangian->bodies.size(), a.lagrangian->bodies.size());
            for (std::size_t i = 0; i < a.lagrangian->bodies.size(); ++i) {
                const VisualBody &x = a.lagrangian->bodies[i], &y = b.lagrangian->bodies[i];
                QVERIFY(x.name == y.name && x.shape == y.shape && x.size == y.size && x.position == y.position && x.end == y.end &&
                        x.angle == y.angle && x.axis == y.axis && x.color == y.color);
            }
            QCOMPARE(serializeScene(b), text);  // stable
            QVERIFY(!contains(text, "\"robot\""));
            QVERIFY(requireValidScene(a).empty());
        }
        const Scene s = parseScene(readFile(std::string(LL_EXAMPLES_DIR) + "/mass_spring_pair_lagrangian.json"));
        QCOMPARE(s.lagrangian->forces, (std::vector<std::string>{"0", "tau"}));
        QCOMPARE(s.lagrangian->bodies[0].size, (std::vector<double>{0.3, 0.05}));
        QCOMPARE(s.expressions.at("lagrangian.bodies[0].size[0]"), std::string("r"));
        QCOMPARE(s.dof(), 2);
    }
};

LL_TEST_APPLESS_MAIN(TestLagrangianDerivation)

}  // namespace test_lagrangian_derivation
#include "test_lagrangian_derivation.moc"
