// Random edit sessions (issue 38): the window's document driven through the commands the
// editors use — cell edits with valid, invalid and absurd values, joints added, removed
// and moved, the DH convention and angle units switched, inertia filled from a shape,
// parameters added, renamed and removed, the initial state and a typed Lagrangian's
// fields, undo and redo — in long seeded sequences over every example (10,000 edits;
// LL_EDIT_FUZZ_EDITS overrides). After every edit: no crash; an invalid document shows
// at least one error naming its field and the last valid model stays the one shown;
// every 25th valid state saved and opened again gives the same model; every 250 edits the
// workers settle on the newest valid scene (never a stale one); at the end undoing every
// edit gives the original JSON byte for byte.
#include "test_registry.hpp"

#include <QApplication>
#include <QDir>
#include <QTemporaryDir>

#include <filesystem>
#include <random>

#include "core/io/scene_file.hpp"
#include "ui/document/field_list_model.hpp"
#include "ui/document/joint_table_model.hpp"
#include "ui/document/live_simulation.hpp"
#include "ui/window/main_window.hpp"
#include "window_waits.hpp"
#include "ui/window/model_editor.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_edit_fuzz_window {

using namespace ll;
using namespace ll::ui;

namespace {

using ll::test::checked;

// How long the newest edit's simulation may take: instrumented (scripts/lab asan, tsan) a
// stiff scene's run with an edited stiffness took past 2 min (stiff_spring.json, 2026-11-29).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr int settleMs = 1200000;
#else
constexpr int settleMs = 120000;
#endif

// The newest edit's simulation is shown (its derivation may still run: the fuzz does not wait for it).
bool settled(MainWindow& w) {
    return ll::test::waitUntil(
        [&] { return w.result() && !w.liveSimulation().busy() && w.result()->request == w.liveSimulation().latestRequest(); }, settleMs);
}

std::vector<std::string> examples() {
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR))
        if (e.path().extension() == ".json" && e.path().filename() != "massless_joint.json")  // refused by design
            files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// A value for a cell: valid (near the old one), invalid, or absurd.
QString randomValue(std::mt19937& rng, const SceneJson& old) {
    static const char* const invalid[] = {"abc", "-1", "", "1/0", "nan", "2*", "q9", "1°", "−1", "inf"};
    static const char* const absurd[] = {"1e300", "-1e300", "1e-320", "1e10", "1e-12", "0", "-0"};
    std::uniform_int_distribution<int> kind(0, 9);
    const int k = kind(rng);
    if (k <= 6) {
        const double base = old.is_number() ? old.get<double>() : 0.5;
        std::uniform_real_distribution<double> f(0.5, 1.5);
        return QString::number(base == 0.0 ? f(rng) - 0.5 : base * f(rng), 'g', 6);
    }
    if (k <= 8) return invalid[std::uniform_int_distribution<int>(0, 9)(rng)];
    return absurd[std::uniform_int_distribution<int>(0, 6)(rng)];
}

void editFieldList(FieldListModel& m, std::mt19937& rng) {
    if (m.rowCount() == 0) return;
    const int row = std::uniform_int_distribution<int>(0, m.rowCount() - 1)(rng);
    const QModelIndex cell = m.index(row, FieldListModel::Value);
    const QString old = m.data(cell, Qt::EditRole).toString();
    m.setData(cell, randomValue(rng, SceneDocument::parseCell(old)), Qt::EditRole);
}

}  // namespace

class TestEditFuzzWindow : public QObject {
    Q_OBJECT
    int edits_ = 0, errorsSeen_ = 0, saved_ = 0, settles_ = 0;

private slots:
    // One session per example (each its own time limit), the edits shared out among them.
    void randomEditSessions_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("edits");
        const int total = qEnvironmentVariableIsSet("LL_EDIT_FUZZ_EDITS") ? qEnvironmentVariableIntValue("LL_EDIT_FUZZ_EDITS") : 10000;
        const std::vector<std::string> files = examples();
        const int perScene = (total + static_cast<int>(files.size()) - 1) / static_cast<int>(files.size());
        for (const std::string& f : files)
            QTest::newRow(std::filesystem::path(f).filename().string().c_str()) << QString::fromStdString(f) << perScene;
    }
    void randomEditSessions() {
        try {
            session();
        } catch (const std::exception& e) {
            QFAIL(e.what());
        }
    }

private:
    void session() {
        QFETCH(QString, scene);
        QFETCH(int, edits);
        const int perScene = edits;
        const std::string file = scene.toStdString();
        QTemporaryDir dir;
        qputenv("LAGRANGELAB_RECOVERY_DIR", dir.filePath("recovery").toLocal8Bit());
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        std::mt19937 rng(static_cast<unsigned>(std::hash<std::string>{}(std::filesystem::path(file).filename().string())));
        int& edits_ = this->edits_;
        int& errorsSeen = errorsSeen_;
        int& saved = saved_;
        int& settles = settles_;
        {
            QVERIFY2(w.openFile(QString::fromStdString(file), nullptr, true), file.c_str());
            QVERIFY(checked(w));
            SceneDocument& doc = w.document();
            const std::string original = doc.json().dump();
            int validRevision = doc.validRevision(), validSteps = 0;
            const bool robot = doc.json().contains("robot");
            for (int step = 0; step < perScene; ++step, ++edits_) {
                const std::string before = doc.json().dump();
                JointTableModel& joints = w.editor().joints();
                const int rows = joints.rowCount();
                std::uniform_int_distribution<int> action(0, 19);
                // A student fixes most mistakes before going on: from an invalid state, undo half the time.
                const int a = doc.hasErrors() && rng() % 2 ? 17 : action(rng);
                const auto anyRow = [&] { return std::uniform_int_distribution<int>(0, std::max(rows - 1, 0))(rng); };
                if (a <= 7 && robot && rows > 0) {  // a cell
                    const int column = std::uniform_int_distribution<int>(JointTableModel::A, JointTableModel::ColumnCount - 1)(rng);
                    const QModelIndex cell = joints.index(anyRow(), column);
                    joints.setData(cell, randomValue(rng, SceneDocument::parseCell(joints.data(cell, Qt::EditRole).toString())),
                                   Qt::EditRole);
                } else if (a == 8 && robot) {
                    if (rows < 8) joints.addJoint(anyRow());
                } else if (a == 9 && robot && rows > 1) {
                    joints.removeJoint(anyRow());
                } else if (a == 10 && robot && rows > 1) {
                    joints.moveJoint(anyRow(), rng() % 2 ? 1 : -1);
                } else if (a == 11 && robot) {
                    const bool modified = doc.value("/robot/convention") == "modified";
                    doc.setValue("/robot/convention", modified ? "standard" : "modified", "Convention");
                } else if (a == 12 && robot) {
                    joints.setDegrees(!joints.degrees());
                } else if (a == 13 && robot && rows > 0) {
                    static const char* const shapes[] = {"rod", "cylinder", "disc", "sphere", "box"};
                    joints.fillInertiaFromShape(anyRow(), shapes[rng() % 5], {QString::number(0.1 + (rng() % 10) / 10.0), "0.2", "0.3"});
                } else if (a == 14) {
                    const int n = w.editor().parameters().rowCount();
                    const int what = static_cast<int>(rng() % 3);
                    if (what == 0 || n == 0) {
                        w.editor().addParameter(QString("p%1").arg(rng() % 50), QString::number((rng() % 100) / 10.0));
                    } else {
                        const QString name = w.editor()
                                                 .parameters()
                                                 .data(w.editor().parameters().index(static_cast<int>(rng() % n), 0), Qt::DisplayRole)
                                                 .toString();
                        if (what == 1) w.editor().renameParameter(name, QString("r%1").arg(rng() % 50));
                        else w.editor().removeParameter(name);
                    }
                } else if (a == 15) {
                    editFieldList(w.editor().parameters(), rng);
                } else if (a == 16) {
                    editFieldList(robot ? w.editor().initialState() : w.editor().lagrangian(), rng);
                } else if (a == 17 || a == 18) {
                    doc.undoStack()->undo();
                } else {
                    doc.undoStack()->redo();
                }
                QVERIFY2(checked(w), "the check of an edit never finished");
                if (doc.hasErrors()) {
                    ++errorsSeen;
                    bool named = false;
                    for (const Diagnostic& d : doc.diagnostics())
                        named = named || (d.severity == Severity::Error && !d.field.empty() && !d.message.empty());
                    QVERIFY2(named, (file + ": an error naming no field after " + doc.json().dump()).c_str());
                    QCOMPARE(doc.validRevision(), validRevision);  // the last valid model stays on screen
                } else {
                    validRevision = doc.validRevision();
                    if (doc.json().dump() != before && ++validSteps % 25 == 0) {  // saved and opened again: the same model
                        const QString path = dir.filePath(QString("state%1.json").arg(saved++));
                        doc.saveFile(path);
                        const LoadedScene again = loadScene(path.toStdString());
                        QCOMPARE(serializeScene(again.scene), serializeScene(doc.validScene()));
                        doc.setPath(QString::fromStdString(file));
                    }
                }
                if (step % 250 == 249 || step == perScene - 1) {  // the workers end on the newest valid scene, never a stale one
                    QVERIFY(settled(w));
                    ++settles;
                    if (!doc.hasErrors() && w.result()->scene)
                        QCOMPARE(serializeScene(*w.result()->scene), serializeScene(doc.validScene()));
                }
            }
            // Undo everything: the original scene, byte for byte.
            doc.undoStack()->setIndex(0);
            QVERIFY(checked(w));
            QCOMPARE(doc.json().dump(), original);
        }
    }

private slots:
    void cleanupTestCase() {
        QVERIFY2(errorsSeen_ > edits_ / 20, "the sequences reach invalid states");
        qInfo("%d edits: %d invalid states, %d saved and reopened, %d settles", edits_, errorsSeen_, saved_, settles_);
    }
};

LL_TEST_MAIN(TestEditFuzzWindow)

}  // namespace test_edit_fuzz_window
#include "test_edit_fuzz_window.moc"
