// The entries a derivation shows, as the window picks them (core/pipeline/entry_catalogue):
// which links feed them (the 2R's b11 is fed by links 1 and 2, b22 by link 2 alone; a
// structured β_jk⁽ⁱ⁾ by link i alone; an entry that is identically zero by none), which
// coordinates and velocities occur in them, and their values from the compiled tape
// against the numeric dynamics (CRBA, Christoffel symbols, RNEA gravity: an independent
// route) at states of a simulated run, in both forms.
#include "test_registry.hpp"

#include <random>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/pipeline/derivation_forms.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_simulation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_entry_catalogue {

using namespace ll;

namespace {

Scene exampleScene(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

std::shared_ptr<const EntryCatalogue> catalogueOf(const Scene& scene, DerivationForm form) {
    DocumentRequest request;
    request.catalogue = true;
    const DerivedDocument d = deriveDisplay(scene, request, form);
    if (!d.catalogue) qFatal("no catalogue");
    return d.catalogue;
}

std::vector<int> linksOf(const EntryCatalogue& c, const std::string& id) {
    const CatalogueEntry* e = c.find(id);
    if (!e) qFatal("no entry %s", id.c_str());
    return e->links;
}

// The largest difference of the catalogue's b, c, g entries (either form) from the
// numeric dynamics, relative to each matrix's largest entry, at the states of a run.
double largestDeviation(const Scene& scene, const EntryCatalogue& c, int samples, int& compared) {
    SimulationSettings settings = scene.simulation;
    settings.duration = std::min(settings.duration, 1.0);
    const Trajectory traj = simulate(scene, settings).trajectory;
    RobotData data(scene.robot);
    std::vector<double> values;
    double worst = 0.0;
    for (int s = 0; s < samples; ++s) {
        const std::size_t k = traj.size() * static_cast<std::size_t>(s) / static_cast<std::size_t>(samples);
        const Eigen::VectorXd& q = traj.q[k];
        const Eigen::VectorXd& qd = traj.qd[k];
        forwardKinematics(scene.robot, data, q);
        computeMassMatrix(scene.robot, data);
        computeCoriolisMatrix(scene.robot, data, qd);
        computePotentialGradient(scene.robot, data, scene.effects, q);
        c.evaluate(q.data(), qd.data(), traj.t[k], values);
        const double scaleB = data.B.cwiseAbs().maxCoeff(), scaleC = std::max(data.C.cwiseAbs().maxCoeff(), 1e-12),
                     scaleG = std::max(data.g.cwiseAbs().maxCoeff(), 1e-12);
        for (const CatalogueEntry& e : c.entries) {
            if (e.row < 0) continue;
            double exact = 0.0, scale = 1.0;
            switch (e.quantity) {
                case present::Quantity::MassMatrix:
                case present::Quantity::MassMatrixEntry: exact = data.B(e.row, e.col), scale = scaleB; break;
                case present::Quantity::CoriolisMatrix:
                case present::Quantity::CoriolisEntry: exact = data.C(e.row, e.col), scale = scaleC; break;
                case present::Quantity::GravityVector:
                case present::Quantity::GravityEntry: exact = data.g(e.row), scale = scaleG; break;
                default: continue;
            }
            if (e.rows * e.cols != 1) qFatal("entry %s is not a scalar", e.id.c_str());
            worst = std::max(worst, std::abs(values[e.first] - exact) / scale);
            ++compared;
        }
    }
    return worst;
}

}  // namespace

class TestEntryCatalogue : public QObject {
    Q_OBJECT

private slots:
    // The 2R of the course notes: b11 = I1 + m1ℓc1² + I2 + m2(a1² + ℓc2² + 2a1ℓc2c2) + …
    // holds both links' parameters, b12 and b22 link 2's alone; b11 depends on q2, not q1.
    void planar2rLinks_data() {
        QTest::addColumn<int>("form");
        QTest::newRow("expanded") << static_cast<int>(DerivationForm::Expanded);
        QTest::newRow("structured") << static_cast<int>(DerivationForm::Structured);
    }
    void planar2rLinks() {
        QFETCH(int, form);
        const auto c = catalogueOf(exampleScene("planar_2r.json"), static_cast<DerivationForm>(form));
        QCOMPARE(linksOf(*c, "b11"), (std::vector<int>{0, 1}));
        QCOMPARE(linksOf(*c, "b12"), (std::vector<int>{1}));
        QCOMPARE(linksOf(*c, "b22"), (std::vector<int>{1}));
        QCOMPARE(linksOf(*c, "g2"), (std::vector<int>{1}));
        const CatalogueEntry* b11 = c->find("b11");
        QVERIFY(b11->dependsOn(1));
        QVERIFY(!b11->dependsOn(0));
        QCOMPARE(b11->unit, std::string("kg·m²"));
        // c11 = −a1 m2 ℓc2 s2 q̇2: the velocity that multiplies it is q̇2's.
        const CatalogueEntry* c11 = c->find("c11");
        QVERIFY(c11);
        QVERIFY(c11->hasVelocity(1));
        QVERIFY(!c11->hasVelocity(0));
        QCOMPARE(c11->unit, std::string("kg·m²/s"));
        QCOMPARE(c->find("g1")->unit, std::string("N·m"));
    }

    // Each structured β_jk⁽ⁱ⁾ (and every other named quantity of a link) is link i's alone.
    void structuredNamesAreTheirLinks() {
        const auto c = catalogueOf(exampleScene("puma560.json"), DerivationForm::Structured);
        int betas = 0;
        for (const CatalogueEntry& e : c->entries) {
            if (e.id.rfind("beta", 0) != 0) continue;
            ++betas;
            QVERIFY2(e.link >= 0, e.id.c_str());
            QCOMPARE(e.links, std::vector<int>{e.link});
            // beta<j>_<k>_<i>: the link is the last index.
            QCOMPARE(e.link + 1, std::stoi(e.id.substr(e.id.rfind('_') + 1)));
        }
        QVERIFY(betas >= 21);
        QVERIFY(c->find("beta23_4"));
    }

    // An entry that is identically zero (the PUMA's g1: joint 1's axis is vertical) is fed
    // by no link; every entry whose tape value vanishes at random states has no links.
    void zeroEntriesHighlightNothing_data() {
        QTest::addColumn<int>("form");
        QTest::newRow("expanded") << static_cast<int>(DerivationForm::Expanded);
        QTest::newRow("structured") << static_cast<int>(DerivationForm::Structured);
    }
    void zeroEntriesHighlightNothing() {
        QFETCH(int, form);
        const auto c = catalogueOf(exampleScene("puma560.json"), static_cast<DerivationForm>(form));
        QVERIFY(linksOf(*c, "g1").empty());
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-2.0, 2.0);
        std::vector<double> largest(static_cast<std::size_t>(c->values.outputCount()), 0.0), values;
        for (int s = 0; s < 5; ++s) {
            std::vector<double> q(6), qd(6);
            for (double& x : q) x = u(rng);
            for (double& x : qd) x = u(rng);
            c->evaluate(q.data(), qd.data(), 0.0, values);
            for (std::size_t k = 0; k < values.size(); ++k) largest[k] = std::max(largest[k], std::abs(values[k]));
        }
        int zeros = 0;
        for (const CatalogueEntry& e : c->entries) {
            if (!e.perLink || e.rows * e.cols != 1) continue;
            const bool zero = largest[e.first] < 1e-12;
            zeros += zero;
            QVERIFY2(zero == e.links.empty(), e.id.c_str());
        }
        QVERIFY(zeros >= 2);  // g1 and the c_ij that vanish
    }

    // The values the window shows at a time of the run are the numeric dynamics' at the
    // trajectory's state then (≤ 1e-9 of the matrix's scale), on every robot example.
    void valuesMatchTheDynamics_data() {
        QTest::addColumn<QString>("example");
        QTest::addColumn<int>("form");
        for (const char* name :
             {"planar_2r.json", "scara.json", "stanford_arm.json", "puma560.json", "puma560_modified.json", "ur5.json"}) {
            QTest::newRow((std::string(name) + " auto").c_str()) << QString(name) << static_cast<int>(DerivationForm::Auto);
            QTest::newRow((std::string(name) + " structured").c_str()) << QString(name) << static_cast<int>(DerivationForm::Structured);
        }
        QTest::newRow("panda.json auto") << QString("panda.json") << static_cast<int>(DerivationForm::Auto);
    }
    void valuesMatchTheDynamics() {
        QFETCH(QString, example);
        QFETCH(int, form);
        const Scene scene = exampleScene(example.toStdString());
        const auto c = catalogueOf(scene, static_cast<DerivationForm>(form));
        int compared = 0;
        const double worst = largestDeviation(scene, *c, 7, compared);
        const int n = scene.robot.dof();
        QCOMPARE(compared, 7 * (2 * n * n + n));  // every b_jk, c_ij and g_j at every state
        qInfo("%s: largest deviation %.2e", qPrintable(example), worst);
        QVERIFY(worst <= 1e-9);
    }

    // Every pickable item of a typed Lagrangian is in the catalogue and evaluates; its
    // E_kin at a state is the trajectory's.
    void lagrangianEntries() {
        const Scene scene = exampleScene("mass_spring_pair_lagrangian.json");
        const auto c = catalogueOf(scene, DerivationForm::Auto);
        const CatalogueEntry* ekin = c->find("E_kin");
        QVERIFY(ekin);
        SimulationSettings settings = scene.simulation;
        settings.duration = 0.5;
        const Trajectory traj = simulate(scene, settings).trajectory;
        std::vector<double> values;
        const std::size_t k = traj.size() / 2;
        c->evaluate(traj.q[k].data(), traj.qd[k].data(), traj.t[k], values);
        QVERIFY(std::abs(values[ekin->first] - traj.Ekin[k]) <= 1e-9 * std::max(1.0, std::abs(traj.Ekin[k])));
        QVERIFY(ekin->links.empty());
        QVERIFY(ekin->velocities != 0);
    }

    // Ids as typed: beta23_4 finds beta2_3_4; an unknown id finds nothing.
    void findAsTyped() {
        const auto c = catalogueOf(exampleScene("planar_2r.json"), DerivationForm::Structured);
        QVERIFY(c->find("B12"));
        QVERIFY(!c->find("b99"));
        const CatalogueEntry* b11 = c->find("b11");
        QCOMPARE(c->at(b11->step, b11->item), b11);
        const auto fed = c->fedBy(0);
        QVERIFY(std::find(fed.begin(), fed.end(), b11) != fed.end());
        QVERIFY(std::find(fed.begin(), fed.end(), c->find("b22")) == fed.end());
    }
};

LL_TEST_GUILESS_MAIN(TestEntryCatalogue)

}  // namespace test_entry_catalogue
#include "test_entry_catalogue.moc"
