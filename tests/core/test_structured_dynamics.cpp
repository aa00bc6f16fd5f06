// The structured derivation (named link quantities, B, C, g as sums over them) against
// the numeric dynamics (CRBA, spatial Christoffel derivatives, RNEA gravity: an
// independent route) on every example, on examples with general DH twists (π/3, 0.3),
// and on seeded random chains up to 10 joints; its ∂b_jk/∂q_l against finite
// differences of the numeric B; Ḃ − 2C skew; cancellation.
#include "test_registry.hpp"

#include <filesystem>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/diagnostics.hpp"
#include "core/present/message_text.hpp"
#include "core/symbolic/derivation_evaluator.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/symbolic/structured_dynamics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_structured_dynamics {

using namespace ll;
using namespace ll::symbolic;

namespace {

Scene exampleScene(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

std::vector<std::string> robotExamples() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(LL_EXAMPLES_DIR))
        if (entry.path().extension() == ".json" && !exampleScene(entry.path().filename().string()).lagrangian)
            names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// Joint j's twist set to `alpha` (the written expression dropped).
void setTwist(Scene& scene, int j, double alpha) {
    scene.robot.joints[j].dh.alpha = alpha;
    scene.expressions.erase(jointField(j, "alpha"));
}

// One twist π/3 and another 0.3: neither is a multiple of π/2.
Scene withGeneralTwists(Scene scene) {
    const int n = scene.robot.dof();
    setTwist(scene, n > 1 ? 1 : 0, std::numbers::pi / 3);
    if (n > 2) setTwist(scene, 2, 0.3);
    else setTwist(scene, 0, 0.3);
    return scene;
}

Scene randomChain(int n, unsigned seed, DhConvention convention, bool prismatic) {
    std::mt19937 rng(seed);
    Scene scene;
    scene.name = "random " + std::to_string(n);
    scene.robot = test::randomRobot(rng, n, convention, prismatic);
    scene.effects.gravity = Eigen::Vector3d(0.3, -0.2, -9.81);
    return scene;
}

double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return test::scaledError(a, b); }

struct Numbers {
    Eigen::MatrixXd B, C;
    Eigen::VectorXd g;
};

Numbers numeric(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    RobotData data(scene.robot);
    forwardKinematics(scene.robot, data, q);
    computeMassMatrix(scene.robot, data);
    computeCoriolisMatrix(scene.robot, data, qd);
    computePotentialGradient(scene.robot, data, scene.effects, q);
    return {data.B, data.C, data.g};
}

Numbers structured(const StructuredDynamics& s, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    const DefinitionValues v(*s.table, structuredInputs(s, {q.data(), q.data() + q.size()}, {qd.data(), qd.data() + qd.size()}));
    Numbers out{Eigen::MatrixXd(s.n, s.n), Eigen::MatrixXd(s.n, s.n), Eigen::VectorXd(s.n)};
    for (int i = 0; i < s.n; ++i) {
        out.g[i] = v(s.g(i, 0));
        for (int j = 0; j < s.n; ++j) {
            out.B(i, j) = v(s.B(i, j));
            out.C(i, j) = v(s.C(i, j));
        }
    }
    return out;
}

void compareWithNumeric(const Scene& scene, const StructuredDynamics& s, int states, double tolerance) {
    std::mt19937 rng(7);
    for (int k = 0; k < states; ++k) {
        const Eigen::VectorXd q = test::randomVector(rng, s.n, 2.0), qd = test::randomVector(rng, s.n, 2.0);
        const Numbers a = structured(s, q, qd), b = numeric(scene, q, qd);
        for (const auto& [what, x, y] : {std::tuple{"B", a.B, b.B}, {"C", a.C, b.C}, {"g", Eigen::MatrixXd(a.g), Eigen::MatrixXd(b.g)}}) {
            const double e = relativeError(x, y);
            QVERIFY2(e <= tolerance, qPrintable(QString("%1 %2: relative error %3").arg(QString::fromStdString(scene.name), what).arg(e)));
        }
    }
}

}  // namespace

class TestStructuredDynamics : public QObject {
    Q_OBJECT
private slots:
    void agreesWithNumericOnEveryExample_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("mode");
        QTest::addColumn<bool>("general");
        for (const std::string& name : robotExamples())
            for (int mode : {int(ParameterMode::Parametric), int(ParameterMode::Numeric), int(ParameterMode::Textbook)})
                for (bool general : {false, true})
                    QTest::newRow((name + "/" + std::to_string(mode) + (general ? "/twists" : "")).c_str())
                        << QString::fromStdString(name) << mode << general;
    }
    void agreesWithNumericOnEveryExample() {
        QFETCH(QString, file);
        QFETCH(int, mode);
        QFETCH(bool, general);
        Scene scene = exampleScene(file.toStdString());
        if (general) scene = withGeneralTwists(scene);
        DerivationOptions options;
        options.mode = ParameterMode(mode);
        const StructuredDynamics s = deriveStructured(scene, options);
        auto lock = lockGinac();
        compareWithNumeric(scene, s, 3, 1e-10);
    }

    // The expanded (textbook) derivation takes any DH angle too: it used to stop with
    // "rem: arguments must be polynomials over the rationals".
    void expandedFormTakesAnyTwist_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("mode");
        for (const std::string& name : robotExamples()) {
            if (exampleScene(name).robot.dof() > 6) continue;  // the Panda: structured form only (above)
            for (int mode : {int(ParameterMode::Parametric), int(ParameterMode::Numeric), int(ParameterMode::Textbook)})
                QTest::newRow((name + "/" + std::to_string(mode)).c_str()) << QString::fromStdString(name) << mode;
        }
    }
    void expandedFormTakesAnyTwist() {
        QFETCH(QString, file);
        QFETCH(int, mode);
        const Scene scene = withGeneralTwists(exampleScene(file.toStdString()));
        DerivationOptions options;
        options.mode = ParameterMode(mode);
        const Derivation d = deriveRobot(scene, options);
        auto lock = lockGinac();
        const DerivationEvaluator eval(d);
        std::mt19937 rng(3);
        for (int k = 0; k < 2; ++k) {
            const Eigen::VectorXd q = test::randomVector(rng, d.q.size(), 2.0), qd = test::randomVector(rng, d.q.size(), 2.0);
            const Numbers b = numeric(scene, q, qd);
            QVERIFY2(relativeError(eval.value(d.B, q, qd), b.B) <= 1e-10, "B");
            QVERIFY2(relativeError(eval.value(d.C, q, qd), b.C) <= 1e-10, "C");
            QVERIFY2(relativeError(eval.value(d.g, q, qd), Eigen::MatrixXd(b.g)) <= 1e-10, "g");
        }
    }

    void agreesWithNumericOnRandomChains_data() {
        QTest::addColumn<int>("n");
        QTest::addColumn<int>("convention");
        for (int n : {3, 5, 7, 10})
            for (int c : {int(DhConvention::Standard), int(DhConvention::Modified)})
                QTest::newRow((std::to_string(n) + (c == int(DhConvention::Standard) ? " standard" : " modified")).c_str()) << n << c;
    }
    void agreesWithNumericOnRandomChains() {
        QFETCH(int, n);
        QFETCH(int, convention);
        // joints 3, 6, 9 prismatic; random twists, offsets, COMs and full inertia tensors
        const Scene scene = randomChain(n, 1000 + n, DhConvention(convention), true);
        DerivationOptions options;
        options.mode = ParameterMode::Numeric;
        const StructuredDynamics s = deriveStructured(scene, options);
        auto lock = lockGinac();
        compareWithNumeric(scene, s, 2, 1e-10);
    }

    // ∂b_jk/∂q_l from the identities against central differences of the numeric B, and
    // Ḃ − 2C skew-symmetric, from the structured C, as a polynomial identity over the
    // names and in numbers.
    void massDerivativesAndSkewSymmetry_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("puma560") << "puma560.json";
        QTest::newRow("puma560 modified") << "puma560_modified.json";
        QTest::newRow("stanford") << "stanford_arm.json";
        QTest::newRow("random 6") << "";
    }
    void massDerivativesAndSkewSymmetry() {
        QFETCH(QString, file);
        const Scene scene = file.isEmpty() ? randomChain(6, 42, DhConvention::Modified, true) : exampleScene(file.toStdString());
        const StructuredDynamics s = deriveStructured(scene);
        auto lock = lockGinac();
        const int n = s.n;
        std::mt19937 rng(11);
        const Eigen::VectorXd q = test::randomVector(rng, n, 2.0), qd = test::randomVector(rng, n, 2.0);
        const DefinitionValues v(*s.table, structuredInputs(s, {q.data(), q.data() + n}, {qd.data(), qd.data() + n}));
        Eigen::MatrixXd Bdot = Eigen::MatrixXd::Zero(n, n);
        for (int l = 0; l < n; ++l) {
            const double h = 1e-5;
            Eigen::VectorXd qp = q, qm = q;
            qp[l] += h;
            qm[l] -= h;
            const Eigen::MatrixXd fd = (numeric(scene, qp, qd).B - numeric(scene, qm, qd).B) / (2 * h);
            Eigen::MatrixXd mine(n, n);
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) mine(j, k) = v(s.dB[l](j, k));
            QVERIFY2(relativeError(mine, fd) < 1e-7, qPrintable(QString("dB/dq%1: %2").arg(l + 1).arg(relativeError(mine, fd))));
            Bdot += mine * qd[l];
        }
        Eigen::MatrixXd C(n, n);
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) C(j, k) = v(s.C(j, k));
        const Eigen::MatrixXd N = Bdot - 2 * C;
        QVERIFY2((N + N.transpose()).cwiseAbs().maxCoeff() < 1e-10 * std::max(1.0, N.cwiseAbs().maxCoeff()), "N + N^T");
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                GiNaC::ex sum = 0;
                for (int l = 0; l < n; ++l) sum += (s.dB[l](j, k) + s.dB[l](k, j)) * s.trig->qd(l);
                QVERIFY(((sum - 2 * s.C(j, k) - 2 * s.C(k, j))).expand().is_zero());
            }
    }

    // Which ∂b_jk/∂q_l vanish identically: the structured form's zeros match finite
    // differences of the numeric B at random states. The PUMA 560: 48 of the 126
    // with j ≤ k are non-zero, none in q1 (nothing depends on it) or q6 (the last link's
    // COM lies on its axis, its inertia is symmetric about it).
    void zeroPatternOfMassDerivatives_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("nonZero");
        QTest::newRow("puma560") << "puma560.json" << 48;
        QTest::newRow("stanford") << "stanford_arm.json" << -1;
        QTest::newRow("panda") << "panda.json" << -1;
    }
    void zeroPatternOfMassDerivatives() {
        QFETCH(QString, file);
        QFETCH(int, nonZero);
        const Scene scene = exampleScene(file.toStdString());
        const StructuredDynamics s = deriveStructured(scene);
        auto lock = lockGinac();
        const int n = s.n;
        std::mt19937 rng(5);
        Eigen::MatrixXd largest = Eigen::MatrixXd::Zero(n * n, n);  // max |∂b_jk/∂q_l| over states, by finite differences
        for (int state = 0; state < 3; ++state) {
            const Eigen::VectorXd q = test::randomVector(rng, n, 3.0), qd = Eigen::VectorXd::Zero(n);
            for (int l = 0; l < n; ++l) {
                Eigen::VectorXd qp = q, qm = q;
                qp[l] += 1e-5;
                qm[l] -= 1e-5;
                const Eigen::MatrixXd fd = (numeric(scene, qp, qd).B - numeric(scene, qm, qd).B) / 2e-5;
                for (int j = 0; j < n; ++j)
                    for (int k = 0; k < n; ++k) largest(j * n + k, l) = std::max(largest(j * n + k, l), std::abs(fd(j, k)));
            }
        }
        int count = 0;
        for (int l = 0; l < n; ++l)
            for (int j = 0; j < n; ++j)
                for (int k = j; k < n; ++k) {
                    const bool symbolic = !s.dB[l](j, k).is_zero(), fd = largest(j * n + k, l) > 1e-8;
                    QVERIFY2(symbolic == fd, qPrintable(QString("db%1%2/dq%3: structured %4, finite differences %5")
                                                            .arg(j + 1)
                                                            .arg(k + 1)
                                                            .arg(l + 1)
                                                            .arg(symbolic)
                                                            .arg(largest(j * n + k, l))));
                    count += symbolic;
                }
        QCOMPARE(count, s.nonZeroMassDerivatives());
        if (nonZero >= 0) {
            QCOMPARE(count, nonZero);
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) {
                    QVERIFY(s.dB[0](j, k).is_zero());
                    QVERIFY(s.dB[n - 1](j, k).is_zero());
                }
        }
        // b_jk depends on q_{min(j,k)+1..n} only, structurally
        for (int j = 0; j < n; ++j)
            for (int k = j; k < n; ++k) QCOMPARE(s.coordinatesOfB(j, k) & ((std::uint64_t(1) << (j + 1)) - 1), std::uint64_t(0));
    }

    // Names are hash-consed: no two entries hold the same value or its negative, and
    // none is a number, a symbol or number·symbol.
    void everyQuantityIsNamedOnce() {
        const StructuredDynamics s = deriveStructured(randomChain(6, 9, DhConvention::Standard, true));
        auto lock = lockGinac();
        std::set<std::string> seen;
        for (const NamedDefinition& d : s.table->entries()) {
            QVERIFY(!GiNaC::is_a<GiNaC::numeric>(d.value) && !GiNaC::is_a<GiNaC::symbol>(d.value));
            std::ostringstream a, b;
            a << d.value;
            b << (-d.value).expand();
            QVERIFY2(!seen.count(a.str()) && !seen.count(b.str()), a.str().c_str());
            seen.insert(a.str());
            QVERIFY(seen.insert(d.name).second);
            for (int dep : d.dependencies) QVERIFY(dep < s.table->indexOf(d.symbol));
        }
    }

    // Cancelled from its progress callback half-way, a 10-joint derivation throws
    // Cancelled at the next name and hands nothing back.
    void cancellingStopsEarly() {
        const Scene scene = randomChain(10, 77, DhConvention::Standard, true);
        std::atomic<bool> cancel{false};
        int calls = 0;
        DerivationOptions options;
        options.cancel = &cancel;
        options.progress = [&](int, const std::string&) {
            if (++calls == 8) cancel = true;
        };
        bool cancelled = false;
        try {
            (void)deriveStructured(scene, options);
        } catch (const Cancelled&) {
            cancelled = true;
        }
        QVERIFY(cancelled);
        QCOMPARE(calls, 8);
        // and the same derivation uncancelled is whole
        cancel = false;
        options.progress = nullptr;
        const StructuredDynamics s = deriveStructured(scene, options);
        auto lock = lockGinac();
        compareWithNumeric(scene, s, 1, 1e-10);
    }

    // The flag set when the derivation reports its last stage (C) still stops it: the
    // loops after the last progress report (the zero test of ∂b, naming ∂b, C) check
    // it too, so it never runs to the end once cancelled.
    void cancellingInTheLastStageStops() {
        const Scene scene = randomChain(10, 78, DhConvention::Standard, false);
        for (const char* stage : {"db/dq", "C"}) {
            std::atomic<bool> cancel{false};
            DerivationOptions options;
            options.cancel = &cancel;
            options.progress = [&](int, const std::string& what) {
                if (what == stage) cancel = true;
            };
            bool cancelled = false;
            try {
                (void)deriveStructured(scene, options);
            } catch (const Cancelled&) {
                cancelled = true;
            }
            QVERIFY2(cancelled, stage);
        }
    }

    // The table checks its flag before every new name: a cancelled name() adds nothing,
    // a cancelled unfold() leaves its memo whole (the same expansion afterwards).
    void tableStopsBetweenNames() {
        const auto lock = lockGinac();
        TrigContext tc({true, true});
        NamedDefinitions table(tc);
        std::atomic<bool> cancel{false};
        table.setCancel(&cancel);
        const GiNaC::ex a = table.name(tc.c(0) * tc.c(1) + 2, "a1", "a_{1}", literal("first"), 1);
        const GiNaC::ex b = table.name(a * a + tc.s(1), "b1", "b_{1}", literal("second"), 1);
        cancel = true;
        QVERIFY_THROWS_EXCEPTION(Cancelled, table.name(a * b + 1, "c1", "c_{1}", literal("third"), 1));
        QCOMPARE(table.size(), 2);
        QVERIFY_THROWS_EXCEPTION(Cancelled, table.unfold(b * b));
        cancel = false;
        const GiNaC::ex expected = tc.reduce(GiNaC::pow(GiNaC::pow(tc.c(0) * tc.c(1) + 2, 2) + tc.s(1), 2));
        QVERIFY((table.unfold(b * b) - expected).expand().is_zero());
    }

    // A scene parameter spelled like a name the structured form generates is refused,
    // naming the parameter and what the generated name means; the numbers mode (where
    // parameters are substituted) derives it.
    void parameterClashingWithAGeneratedNameIsRefused() {
        Scene scene = exampleScene("planar_2r.json");
        DerivationOptions options;
        const StructuredDynamics s = deriveStructured(scene, options);
        std::string generated;
        {
            const auto lock = lockGinac();
            generated = s.table->entries().front().name;
        }
        scene.parameters.emplace_back(generated, 0.5);
        try {
            (void)deriveStructured(scene, options);
            QFAIL("the clash was not refused");
        } catch (const InputError& e) {
            const std::string what = e.what();
            QVERIFY2(what.find("parameters." + generated) != std::string::npos, e.what());
            QVERIFY2(what.find("rename the parameter") != std::string::npos, e.what());
            // what the name means is a message too: the Danish sentence is Danish throughout
            const std::string danish = present::messageText(e.diagnostics().front().message, present::Language::Danish);
            QVERIFY2(danish.find("omdøb parameteren") != std::string::npos, danish.c_str());
            for (const char* english : {" of ", "frame", "contribution", "derivative", "column", "velocity", "weight"})
                QVERIFY2(danish.find(english) == std::string::npos, danish.c_str());
        }
        options.mode = ParameterMode::Numeric;
        (void)deriveStructured(scene, options);
    }
};

LL_TEST_GUILESS_MAIN(TestStructuredDynamics)

}  // namespace test_structured_dynamics
#include "test_structured_dynamics.moc"
