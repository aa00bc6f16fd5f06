// Physical validation on every example: each corrupted field gives an error that
// names it; published parameter sets that break the triangle inequality warn and
// still simulate; a joint that moves nothing is named.
#include "test_registry.hpp"

#include <filesystem>

#include "core/io/scene_file.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_validation {

using namespace ll;

namespace {
std::vector<std::string> exampleFiles() {
    std::vector<std::string> files;
    // examples/hard/ holds scenes built to break things (a joint that moves no mass, a
    // 1e4 s symplectic run...); test_hard_cases checks each one's own property.
    for (const auto& entry : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR))
        if (entry.path().extension() == ".json" && entry.path().parent_path().filename() != "hard") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

bool namesError(const std::vector<Diagnostic>& diagnostics, const std::string& field) {
    for (const Diagnostic& d : diagnostics)
        if (d.severity == Severity::Error && d.field == field) return true;
    return false;
}
}  // namespace

class TestValidation : public QObject {
    Q_OBJECT
private slots:
    void examplesAreValidAndSimulate() {
        const auto files = exampleFiles();
        QVERIFY(files.size() >= 12);
        for (const std::string& file : files) {
            const LoadedScene loaded = loadScene(file);
            SimulationSettings s = loaded.scene.simulation;
            s.duration = 0.2;
            const SimulationResult r = simulate(loaded.scene, s);
            QVERIFY2(r.status == SimulationStatus::Completed, qPrintable(QString::fromStdString(file + ": " + r.message.english())));
            QVERIFY2(r.stats.maxRelEnergyError < 1e-4, qPrintable(QString::fromStdString(file)));
        }
    }

    void everyCorruptedFieldIsNamed() {
        for (const std::string& file : exampleFiles()) {
            const Scene original = loadScene(file).scene;
            for (int j = 0; j < original.robot.dof(); ++j) {
                const auto expectError = [&](const char* what, const std::string& field, auto corrupt) {
                    Scene scene = original;
                    corrupt(scene.robot.joints[j]);
                    const auto diagnostics = validateScene(scene);
                    QVERIFY2(namesError(diagnostics, field),
                             qPrintable(QString::fromStdString(file + ": " + what + " not reported at " + field)));
                };
                expectError("negative mass", jointField(j, "mass"), [](Joint& x) { x.link.mass = -1.0; });
                expectError("NaN mass", jointField(j, "mass"), [](Joint& x) { x.link.mass = std::nan(""); });
                expectError("infinite a", jointField(j, "a"), [](Joint& x) { x.dh.a = INFINITY; });
                expectError("NaN alpha", jointField(j, "alpha"), [](Joint& x) { x.dh.alpha = std::nan(""); });
                expectError("NaN com", jointField(j, "com[1]"), [](Joint& x) { x.link.com[1] = std::nan(""); });
                expectError("non-PSD inertia", jointField(j, "inertia"), [](Joint& x) { x.link.inertia(0, 0) = -1.0; });
                expectError("asymmetric inertia", jointField(j, "inertia"), [](Joint& x) { x.link.inertia(0, 1) += 0.5; });
            }
            Scene scene = original;
            scene.initial.q.resize(scene.dof() + 1);
            scene.initial.q.setZero();
            QVERIFY(namesError(validateScene(scene), "initial.q"));
            scene = original;
            scene.effects.springs.push_back({scene.dof(), 1.0, 0.0});  // one past the last joint (coordinate)
            QVERIFY(namesError(validateScene(scene), "effects.springs[" + std::to_string(scene.effects.springs.size() - 1) + "].joint"));
            scene = original;
            scene.simulation.duration = 1e9;  // 1e11 samples at 100 Hz: refused, not bad_alloc
            QVERIFY(namesError(validateScene(scene), "simulation.output_rate"));
            scene = original;
            scene.simulation.integrator = "rk45";
            QVERIFY(namesError(validateScene(scene), "simulation.integrator"));
        }
    }

    void publishedTriangleViolationsWarnAndSimulate() {
        const LoadedScene puma = loadScene(std::string(LL_EXAMPLES_DIR) + "/puma560.json");
        bool warnedLink1 = false;
        for (const Diagnostic& d : puma.warnings)
            warnedLink1 |=
                d.field.find("robot.joints[0].inertia") != std::string::npos && d.message.english().find("triangle") != std::string::npos;
        QVERIFY(warnedLink1);
        const LoadedScene stanford = loadScene(std::string(LL_EXAMPLES_DIR) + "/stanford_arm.json");
        bool warnedLink5 = false;
        for (const Diagnostic& d : stanford.warnings) warnedLink5 |= d.field.find("robot.joints[4].inertia") != std::string::npos;
        QVERIFY(warnedLink5);
    }

    void massiveLessJointIsNamed() {
        RobotModel robot = test::Planar2R{}.model();
        robot.joints.push_back(Joint{});  // joint 3: no mass, no inertia
        const auto diagnostics = validateRobot(robot);
        QVERIFY(namesError(diagnostics, jointField(2, "mass")));  // the one value that explains it
        bool mentionsJoint = false;
        for (const Diagnostic& d : diagnostics) mentionsJoint |= d.message.english().find("joint 3") != std::string::npos;
        QVERIFY(mentionsJoint);
    }
};

LL_TEST_APPLESS_MAIN(TestValidation)

}  // namespace test_validation
#include "test_validation.moc"
