// Step 9, the control law as a derivation step (core/symbolic/control_law): its τ, with the
// derived B, C, g put in (or the controller's own B̂, Ĉ, ĝ as symbols), evaluated at random
// states equals the torque the simulation's controller computes by recursive Newton–Euler
// on its own model (another route); its closed-loop rows hold along the real dynamics
// (q̈ = B⁻¹(τ + Q − C q̇ − g) from the numeric core); g cancels from PD + g's loop with the
// exact model, and computed torque's error obeys ë + K_d ė + K_p e = 0 joint by joint; the
// step is written as text and LaTeX with its hats and dots, and left out of an exercise.
#include "test_registry.hpp"

#include <map>
#include <random>

#include "core/io/scene_file.hpp"
#include "core/pipeline/derivation_forms.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_evaluation.hpp"
#include "core/present/derivation_document.hpp"
#include "core/present/hidden_answers.hpp"
#include "core/simulation/controller.hpp"
#include "core/symbolic/control_law.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/robot_derivation.hpp"

namespace test_control_law {

using namespace ll;
using GiNaC::ex;

namespace {

Scene example(const std::string& file) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + file).scene; }

const symbolic::DerivationStep* controlStep(const symbolic::Derivation& d) {
    for (const symbolic::DerivationStep& s : d.steps)
        if (s.number == symbolic::controlStepNumber) return &s;
    return nullptr;
}

const symbolic::DerivationItem* itemOf(const symbolic::DerivationStep& s, symbolic::Quantity q, int index = -1) {
    for (const symbolic::DerivationItem& item : s.items)
        if (item.quantity == q && item.index == index) return &item;
    return nullptr;
}

std::set<std::string> symbolsOf(const ex& e) {
    std::set<std::string> out;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) out.insert(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
    return out;
}

// e with the derivation's shorthand and parameters replaced, then every symbol by name.
double valueOf(const ex& e, const symbolic::Derivation& d, const std::map<std::string, double>& values) {
    const ex x = e.subs(d.trigToFunctions).subs(d.parameterValues);
    GiNaC::exmap own;  // subs matches symbols by identity: the expression's own, by name
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) {
            const std::string name = GiNaC::ex_to<GiNaC::symbol>(*it).get_name();
            if (!values.count(name)) throw std::runtime_error("no value for " + name);
            own[*it] = values.at(name);
        }
    const ex v = x.subs(own).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v)) throw std::runtime_error("not a number");
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

// The state's values by the derivation's names: q, q̇, q̈, the reference, the error and
// the controller's model (B̂, Ĉ, ĝ at q, q̇, or at the reference for feedforward).
std::map<std::string, double> stateValues(const Scene& scene, Controller& controller, double t, const Eigen::VectorXd& q,
                                          const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) {
    const int n = scene.dof();
    const ControlParts p = controller.parts(t, q, qd);
    std::map<std::string, double> v;
    for (int i = 0; i < n; ++i) {
        const std::string k = std::to_string(i + 1);
        v["q" + k] = q[i], v["qd" + k] = qd[i], v["qdd" + k] = qdd[i];
        v["q_d" + k] = p.qRef[i], v["q_d" + k + "_dot"] = p.qdRef[i], v["q_d" + k + "_ddot"] = p.qddRef[i];
        v["e" + k] = p.error[i], v["e" + k + "_dot"] = p.errorRate[i], v["e" + k + "_ddot"] = p.qddRef[i] - qdd[i];
    }
    Scene own = scene;
    own.robot = controller.model();
    own.effects.control.reset();
    own.effects.torques.clear(), own.effects.viscous.clear(), own.effects.coulomb.clear();
    const bool atReference = controller.control().law == ControlLaw::Feedforward;
    const SceneEvaluation m = evaluateScene(own, atReference ? p.qRef : q, atReference ? p.qdRef : qd, t);
    for (int i = 0; i < n; ++i) {
        const std::string k = std::to_string(i + 1);
        v["g" + k + "_hat"] = m.terms.g[i];
        for (int j = 0; j < n; ++j) {
            const std::string ij = k + (n >= 10 ? "_" : "") + std::to_string(j + 1);
            v["b" + ij + "_hat"] = m.terms.B(i, j), v["c" + ij + "_hat"] = m.terms.C(i, j);
        }
    }
    return v;
}

// The plant's q̈ under the controller's τ (before its limits) and the scene's other forces.
Eigen::VectorXd plantAcceleration(const Scene& scene, const Eigen::VectorXd& tau, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                  double t) {
    Scene plant = scene;
    plant.effects.control.reset();
    const SceneEvaluation m = evaluateScene(plant, q, qd, t);
    return m.terms.B.ldlt().solve(tau + m.terms.Q - m.terms.C * qd - m.terms.g);
}

Scene withLaw(Scene scene, ControlLaw law) {
    scene.effects.control->law = law;
    return scene;
}

}  // namespace

class TestControlLaw : public QObject {
    Q_OBJECT

    // Each case: the scene, and what its step must show.
    struct Case {
        const char* name;
        Scene scene;
    };
    std::vector<Case> cases() {
        const Scene twoR = example("control/planar_2r_pd_gravity.json");
        return {{"2R PD + g (exact model)", twoR},
                {"2R PD", example("control/planar_2r_pd.json")},
                {"2R computed torque (exact)", withLaw(twoR, ControlLaw::ComputedTorque)},
                {"2R feedforward", withLaw(twoR, ControlLaw::Feedforward)},
                {"PUMA computed torque (exact)", example("control/puma560_computed_torque.json")},
                {"PUMA computed torque, payload unknown", example("control/puma560_payload_unknown.json")},
                {"acrobot PD on the elbow", example("control/acrobot_pd_elbow.json")},
                {"Panda trapezoidal with limits", example("control/panda_trapezoidal_saturation.json")}};
    }

private slots:
    // τ of step 9 at random states is the controller's τ before its limits (≤ 1e-9 relative),
    // and each closed-loop row holds with the plant's q̈ from the numeric core.
    void tauIsTheControllersTorque() {
        std::mt19937 rng(19);
        std::uniform_real_distribution<double> angle(-1.5, 1.5), rate(-2.0, 2.0), time(0.0, 3.0);
        for (const Case& c : cases()) {
            const auto lock = symbolic::lockGinac();
            const symbolic::Derivation d = symbolic::deriveRobot(c.scene);
            const symbolic::DerivationStep* step = controlStep(d);
            QVERIFY2(step, c.name);
            const int n = c.scene.dof();
            Controller controller(c.scene.robot, c.scene.effects);
            for (int k = 0; k < 4; ++k) {
                Eigen::VectorXd q(n), qd(n);
                for (int i = 0; i < n; ++i) q[i] = angle(rng), qd[i] = rate(rng);
                const double t = time(rng);
                const Eigen::VectorXd expected = controller.parts(t, q, qd).unsaturated;
                const Eigen::VectorXd qdd = plantAcceleration(c.scene, expected, q, qd, t);
                const std::map<std::string, double> values = stateValues(c.scene, controller, t, q, qd, qdd);
                for (int i = 0; i < n; ++i) {
                    const symbolic::DerivationItem* tau = itemOf(*step, symbolic::Quantity::ControlTorque, i);
                    QVERIFY2(tau, c.name);
                    const double got = valueOf(tau->value, d, values);
                    QVERIFY2(std::abs(got - expected[i]) <= 1e-9 * (1 + std::abs(expected[i])),
                             qPrintable(QString("%1: tau_%2 %3 vs the controller's %4").arg(c.name).arg(i + 1).arg(got).arg(expected[i])));
                    const symbolic::DerivationItem* row = itemOf(*step, symbolic::Quantity::ClosedLoop, i);
                    QVERIFY2(row, c.name);
                    const double residual = valueOf(row->value.lhs() - row->value.rhs(), d, values);
                    double scale = 1;
                    for (int j = 0; j < n; ++j) scale += std::abs(expected[j]);
                    QVERIFY2(std::abs(residual) <= 1e-8 * scale,
                             qPrintable(QString("%1: closed loop %2 is off by %3").arg(c.name).arg(i + 1).arg(residual)));
                }
            }
        }
    }

    // What the derived terms do in the loop: PD + g with the exact model has no g left
    // (at rest, q̇ = q̈ = 0, its left side is 0 while g(q) is not); computed torque with the
    // exact model leaves ë_i + K_d,i ė_i + K_p,i e_i = 0 on each joint, in e_i, ė_i, ë_i
    // alone; a model the controller owns is written with b̂, ĉ, ĝ, not expanded.
    void derivedTermsCancel() {
        const auto lock = symbolic::lockGinac();
        const Scene twoR = example("control/planar_2r_pd_gravity.json");
        {
            const symbolic::Derivation d = symbolic::deriveRobot(twoR);
            const symbolic::DerivationStep& step = *controlStep(d);
            std::map<std::string, double> atRest{{"q1", 0.3}, {"q2", -0.7}, {"qd1", 0}, {"qd2", 0}, {"qdd1", 0}, {"qdd2", 0}};
            for (int i = 0; i < 2; ++i) {
                QCOMPARE(valueOf(itemOf(step, symbolic::Quantity::ClosedLoop, i)->value.lhs(), d, atRest), 0.0);
                QVERIFY(std::abs(valueOf(d.g(i, 0), d, atRest)) > 1.0);
            }
            QVERIFY(symbolsOf(itemOf(step, symbolic::Quantity::ControlTorque, 0)->value).count("g1_hat") == 0);
        }
        for (const Scene& scene : {withLaw(twoR, ControlLaw::ComputedTorque), example("control/puma560_computed_torque.json")}) {
            const symbolic::Derivation d = symbolic::deriveRobot(scene);
            const symbolic::DerivationStep& step = *controlStep(d);
            Controller controller(scene.robot, scene.effects);
            for (int i = 0; i < scene.dof(); ++i) {
                const ex row = itemOf(step, symbolic::Quantity::ClosedLoop, i)->value;
                const std::string k = std::to_string(i + 1);
                QVERIFY(row.rhs().is_zero());
                QCOMPARE(symbolsOf(row.lhs()), (std::set<std::string>{"e" + k, "e" + k + "_dot", "e" + k + "_ddot"}));
                std::map<std::string, double> unit{{"e" + k, 1.0}, {"e" + k + "_dot", 0.0}, {"e" + k + "_ddot", 0.0}};
                QCOMPARE(valueOf(row.lhs(), d, unit), controller.control().kp[i]);
                unit["e" + k] = 0.0, unit["e" + k + "_dot"] = 1.0;
                QCOMPARE(valueOf(row.lhs(), d, unit), controller.control().kd[i]);
            }
        }
        {
            const symbolic::Derivation d = symbolic::deriveRobot(example("control/puma560_payload_unknown.json"));
            const std::set<std::string> names = symbolsOf(itemOf(*controlStep(d), symbolic::Quantity::ControlTorque, 1)->value);
            QVERIFY(names.count("b12_hat") && names.count("c22_hat") && names.count("g2_hat"));
        }
        // a scene without a controller has no step 9
        QVERIFY(!controlStep(symbolic::deriveRobot(example("planar_2r.json"))));
    }

    // Written as a textbook prints it: the hats in text (b̂) and LaTeX (\hat{b}), the error's
    // dots, the title and the closed-loop rows as equations; the step is left out of an
    // exercise, whose answers (g, B) it would give away.
    void writtenAndHidden() {
        const auto lock = symbolic::lockGinac();
        const symbolic::Derivation d = symbolic::deriveRobot(example("control/puma560_payload_unknown.json"));
        const std::string text = present::derivationDocument(d, present::DocumentFormat::Text, "parameters");
        const std::string latex = present::derivationDocument(d, present::DocumentFormat::Latex, "parameters");
        QVERIFY(text.find("Step 9. Control law: computed torque") != std::string::npos);
        QVERIFY(text.find("b\u0302") != std::string::npos && text.find("e\u03071") != std::string::npos);
        QVERIFY(latex.find("\\hat{b}_{11}") != std::string::npos && latex.find("\\ddot{q}_{d1}") != std::string::npos);
        QVERIFY(latex.find("\\hat{B}(q)") != std::string::npos);  // the general formula
        const auto display = present::displayDocument(d);
        QVERIFY(display->step(symbolic::controlStepNumber));
        const present::DisplayDocument hidden =
            present::withAnswersHidden(*display, {{symbolic::lastModelStep, symbolic::Quantity::GravityVector, -1, 0, -1}});
        QVERIFY(!hidden.step(symbolic::controlStepNumber));
        QVERIFY(hidden.step(symbolic::lastModelStep));
    }

    // The structured form (the Panda's): step 9 over step 8's entries by name, computed
    // torque's rows the same error equations, each τ_i with every non-zero b_ij of its row.
    void inTheStructuredForm() {
        const Scene panda = example("control/panda_trapezoidal_saturation.json");
        DocumentRequest request;
        request.format = present::DocumentFormat::Display;
        const DerivedDocument derived = deriveDisplay(panda, request, DerivationForm::Structured);
        QCOMPARE(derived.display->form.id, MessageId::FormStructured);
        const present::DisplayStep* step = derived.display->step(symbolic::controlStepNumber);
        QVERIFY(step);
        const Controller controller(panda.robot, panda.effects);
        const auto text = [](const present::DisplayItem& item) {
            return present::renderDisplay(*item.equation, present::DisplayStyle::Text);
        };
        int rows = 0, torques = 0;
        for (const present::DisplayItem& item : step->items) {
            if (item.quantity == symbolic::Quantity::ClosedLoop) {
                const std::string k = std::to_string(item.row + 1);
                std::ostringstream expected;
                expected << "e\u0308" << k << " + " << controller.control().kd[item.row] << " e\u0307" << k << " + " << controller.control().kp[item.row]
                         << " e" << k << " = 0";
                QCOMPARE(QString::fromStdString(text(item)), QString::fromStdString(expected.str()));
                ++rows;
            }
            if (item.quantity == symbolic::Quantity::ControlTorque) {
                const std::string shown = text(item);
                for (int j = 0; j < panda.dof(); ++j) {
                    const int lo = std::min(item.row, j) + 1, hi = std::max(item.row, j) + 1;
                    const std::string b = "b" + std::to_string(lo) + std::to_string(hi) + " (";
                    QVERIFY2(shown.find(b) != std::string::npos, shown.c_str());
                }
                ++torques;
            }
        }
        QCOMPARE(rows, panda.dof());
        QCOMPARE(torques, panda.dof());
        // `derive --format text|latex` of the structured form: the step before the end
        for (const auto format : {present::DocumentFormat::Text, present::DocumentFormat::Latex}) {
            FormRequest asked;
            asked.document.format = format;
            const std::string written = deriveInForm(panda, asked).derived.document;
            const bool text = format == present::DocumentFormat::Text;
            const std::size_t at = written.find(text ? "Step 9. Control law: computed torque" : "\\section*{Step 9: Control law: computed torque");
            QVERIFY2(at != std::string::npos, written.substr(written.size() > 600 ? written.size() - 600 : 0).c_str());
            QVERIFY(written.find("e\u03081 + 20 e\u03071 + 100 e1 = 0") != std::string::npos || !text);
            QVERIFY(text || written.rfind("\\end{document}") > at);
        }
    }
};

LL_TEST_APPLESS_MAIN(TestControlLaw)

}  // namespace test_control_law
#include "test_control_law.moc"
