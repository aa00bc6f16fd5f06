// The Qt item model shows exactly the simulated samples, headed by the coordinates' names.
#include "test_registry.hpp"

#include "core/pipeline/scene_simulation.hpp"
#include "core/io/scene_file.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "test_support.hpp"
#include "ui/document/trajectory_table_model.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_trajectory_table_model {

using namespace ll;

class TestTrajectoryTableModel : public QObject {
    Q_OBJECT
private slots:
    void showsEverySampleAndColumn() {
        Scene scene;
        scene.robot = test::Planar2R{}.model();
        scene.effects.gravity = Eigen::Vector3d(0, -9.81, 0);
        scene.initial.q = Eigen::Vector2d(0.5, 0.1);
        scene.initial.qd = Eigen::Vector2d::Zero();
        scene.simulation.duration = 1.0;
        scene.simulation.outputRate = 50;
        const SimulationResult r = simulate(scene);
        ui::TrajectoryTableModel model;
        model.setTrajectory(r.trajectory);
        QCOMPARE(model.rowCount(), 51);
        QCOMPARE(model.columnCount(), 1 + 4 + 4);
        QCOMPARE(model.headerData(2, Qt::Horizontal).toString(), QString("q2"));
        QCOMPARE(model.headerData(3, Qt::Horizontal).toString(), QString::fromUtf8("q̇1"));
        QCOMPARE(model.headerData(7, Qt::Horizontal).toString(), QString("E [J]"));
        QCOMPARE(model.data(model.index(50, 0), Qt::EditRole).toDouble(), 1.0);
        QCOMPARE(model.data(model.index(25, 2), Qt::EditRole).toDouble(), r.trajectory.q[25][1]);
        QCOMPARE(model.data(model.index(10, 7), Qt::EditRole).toDouble(), r.trajectory.E[10]);
        QVERIFY(!model.data(model.index(51, 0)).isValid());
    }

    // A Lagrangian system's own coordinate names head the columns, as the derivation's
    // text writes them (Trajectory::names), not q1, q2.
    void headersAreTheCoordinateNames() {
        auto lock = symbolic::lockGinac();  // simulate derives the Lagrangian with GiNaC
        Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/mass_spring_pair_lagrangian.json").scene;
        scene.simulation.duration = 0.1;
        const SimulationResult r = simulate(scene);
        ui::TrajectoryTableModel model;
        model.setTrajectory(r.trajectory);
        QCOMPARE(model.columnCount(), 1 + 4 + 4);
        QCOMPARE(model.headerData(1, Qt::Horizontal).toString(), QString::fromUtf8("θ1"));
        QCOMPARE(model.headerData(2, Qt::Horizontal).toString(), QString::fromUtf8("θ2"));
        QCOMPARE(model.headerData(4, Qt::Horizontal).toString(), QString::fromUtf8("θ̇2"));
        QCOMPARE(model.headerData(5, Qt::Horizontal).toString(), QString::fromUtf8("E_kin [J]"));
    }
};

LL_TEST_APPLESS_MAIN(TestTrajectoryTableModel)

}  // namespace test_trajectory_table_model
#include "test_trajectory_table_model.moc"
