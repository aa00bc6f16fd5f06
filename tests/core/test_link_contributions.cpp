// Each link's share of B, C, g, E_kin and E_pot (core/dynamics/link_contributions): the
// shares sum to the robot's own (with the motors' armature on b_jj and the springs left
// to the joints), and link i's share of b_jk is the structured form's β_jk⁽ⁱ⁾, derived
// symbolically and evaluated from its compiled tape (an independent route).
#include "test_registry.hpp"

#include <random>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/link_contributions.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_link_contributions {

using namespace ll;

namespace {

Scene exampleScene(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

}  // namespace

class TestLinkContributions : public QObject {
    Q_OBJECT

private slots:
    void sharesSumToTheWhole_data() {
        QTest::addColumn<QString>("example");
        for (const char* name :
             {"planar_2r.json", "scara.json", "stanford_arm.json", "puma560.json", "ur5.json", "panda.json", "mass_spring_pair.json"})
            QTest::newRow(name) << QString(name);
    }
    void sharesSumToTheWhole() {
        QFETCH(QString, example);
        const Scene scene = exampleScene(example.toStdString());
        const int n = scene.robot.dof();
        LinkContributions shares(scene.robot, scene.effects);
        RobotData data(scene.robot);
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(-1.5, 1.5);
        for (int s = 0; s < 5; ++s) {
            Eigen::VectorXd q(n), qd(n);
            for (int j = 0; j < n; ++j) q[j] = u(rng), qd[j] = u(rng);
            shares.evaluate(q, qd);
            forwardKinematics(scene.robot, data, q);
            computeMassMatrix(scene.robot, data);
            computeCoriolisMatrix(scene.robot, data, qd);
            Eigen::VectorXd gravity = Eigen::VectorXd::Zero(n);
            addGravityTorques(scene.robot, data, scene.effects.gravity.value_or(Eigen::Vector3d::Zero()), gravity);
            Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n), C = B;
            Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
            double Ekin = 0.0;
            for (int i = 0; i < n; ++i) {
                B += shares.B(i);
                C += shares.C(i);
                g += shares.g(i);
                Ekin += shares.Ekin(i);
            }
            // The motors' armature is the joints' (diagonal), not any link's.
            Eigen::MatrixXd armature = data.B - B;
            const double scale = data.B.cwiseAbs().maxCoeff();
            QVERIFY((armature - Eigen::MatrixXd(armature.diagonal().asDiagonal())).cwiseAbs().maxCoeff() <= 1e-12 * scale);
            QVERIFY((C - data.C).cwiseAbs().maxCoeff() <= 1e-12 * std::max(1.0, data.C.cwiseAbs().maxCoeff()));
            QVERIFY((g - gravity).cwiseAbs().maxCoeff() <= 1e-12 * std::max(1.0, gravity.cwiseAbs().maxCoeff()));
            const double EkinLinks = 0.5 * qd.dot((data.B - armature) * qd);
            QVERIFY(std::abs(Ekin - EkinLinks) <= 1e-12 * std::max(1.0, std::abs(EkinLinks)));
        }
    }

    // Link i's share of b_jk is β_jk⁽ⁱ⁾ of the structured derivation (Siciliano §7.2).
    void sharesAreTheStructuredBetas() {
        const Scene scene = exampleScene("puma560.json");
        DocumentRequest request;
        request.catalogue = true;
        const auto c = deriveDisplay(scene, request, DerivationForm::Structured).catalogue;
        LinkContributions shares(scene.robot, scene.effects);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> u(-2.0, 2.0);
        int compared = 0;
        std::vector<double> values;
        for (int s = 0; s < 4; ++s) {
            Eigen::VectorXd q(6), qd(6);
            for (int j = 0; j < 6; ++j) q[j] = u(rng), qd[j] = u(rng);
            shares.evaluate(q, qd);
            c->evaluate(q.data(), qd.data(), 0.0, values);
            for (const CatalogueEntry& e : c->entries) {
                if (e.id.rfind("beta", 0) != 0) continue;
                // beta<j><k>_<i> or beta<j>_<k>_<i>: j, k are single digits for a 6-joint arm.
                std::string digits;
                for (char ch : e.id.substr(4))
                    if (std::isdigit(static_cast<unsigned char>(ch))) digits += ch;
                QCOMPARE(digits.size(), std::size_t(3));
                const int j = digits[0] - '1', k = digits[1] - '1', i = digits[2] - '1';
                QCOMPARE(i, e.link);
                const double share = shares.B(i)(j, k);
                QVERIFY2(std::abs(values[e.first] - share) <= 1e-10 * std::max(1.0, shares.B(i).cwiseAbs().maxCoeff()), e.id.c_str());
                ++compared;
            }
        }
        QVERIFY(compared >= 4 * 21);
    }
};

LL_TEST_GUILESS_MAIN(TestLinkContributions)

}  // namespace test_link_contributions
#include "test_link_contributions.moc"
