// The one atomic-save routine and its writers: the old file stays whole when writing
// fails, no temporary file is left, permissions are kept, the .bak holds the previous
// content when asked for; trajectories go through it too.
#include "test_registry.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/io/atomic_file.hpp"
#include "core/io/trajectory_file.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_atomic_file {

using namespace ll;
namespace fs = std::filesystem;

namespace {
std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

int temporaries(const fs::path& directory) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(directory))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) ++count;
    return count;
}

SimulationResult twoSamples() {
    SimulationResult r;
    Trajectory& t = r.trajectory;
    t.n = 1;
    t.names = {"x"};
    t.t = {0.0, 0.5};
    t.q = {Eigen::VectorXd::Constant(1, 0.25), Eigen::VectorXd::Constant(1, 0.5)};
    t.qd = {Eigen::VectorXd::Constant(1, 1.0), Eigen::VectorXd::Constant(1, 0.0)};
    t.Ekin = {0.5, 0.0};
    t.Epot = {0.0, 0.5};
    t.E = {0.5, 0.5};
    t.work = {0.0, 0.0};
    return r;
}
}  // namespace

class TestAtomicFile : public QObject {
    Q_OBJECT
private slots:
    void replacesAndKeepsTheBackupWhenAsked() {
        QTemporaryDir dir;
        const fs::path path = fs::path(dir.path().toStdString()) / "scene.json";
        saveFileAtomically(path.string(), "first", Backup::Keep);
        QCOMPARE(readFile(path), std::string("first"));
        QVERIFY(!fs::exists(path.string() + ".bak"));  // nothing to keep yet
        saveFileAtomically(path.string(), "second", Backup::Keep);
        QCOMPARE(readFile(path), std::string("second"));
        QCOMPARE(readFile(path.string() + ".bak"), std::string("first"));
        saveFileAtomically(path.string(), "", Backup::Keep);  // an empty file, and then its empty backup
        saveFileAtomically(path.string(), "third", Backup::Keep);
        QCOMPARE(readFile(path.string() + ".bak"), std::string());

        const fs::path output = fs::path(dir.path().toStdString()) / "table.csv";
        writeFile(output, "old");
        saveFileAtomically(output.string(), "new", Backup::None);
        QCOMPARE(readFile(output), std::string("new"));
        QVERIFY(!fs::exists(output.string() + ".bak"));
        QCOMPARE(temporaries(dir.path().toStdString()), 0);
    }

    // A writer that fails half-way (disk full, a bug) leaves the old file as it was.
    void aFailingWriterLeavesTheOldFile() {
        QTemporaryDir dir;
        const fs::path path = fs::path(dir.path().toStdString()) / "out.csv";
        writeFile(path, "old content");
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, saveFileAtomically(
                                                         path.string(),
                                                         [](std::ostream& out) {
                                                             out << "half of the new";
                                                             throw std::runtime_error("disk full");
                                                         },
                                                         Backup::None));
        QCOMPARE(readFile(path), std::string("old content"));
        QCOMPARE(temporaries(dir.path().toStdString()), 0);
        // A missing directory: an error naming the path.
        const std::string nowhere = (fs::path(dir.path().toStdString()) / "missing" / "x.csv").string();
        try {
            saveFileAtomically(nowhere, "x", Backup::None);
            QFAIL("saved into a missing directory");
        } catch (const std::runtime_error& e) {
            QVERIFY2(std::string(e.what()).find(nowhere + ": cannot save") == 0, e.what());
        }
    }

    // The trajectory writer goes through the routine: the replaced file keeps its
    // permissions (it used to get the default ones of a new file) and no .bak appears.
    void trajectoriesAreSavedAtomically() {
        QTemporaryDir dir;
        const fs::path path = fs::path(dir.path().toStdString()) / "run.csv";
        writeFile(path, "an older run");
        fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
        saveTrajectory(twoSamples(), path.string());
        QCOMPARE(fs::status(path).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
        std::ostringstream expected;
        writeTrajectoryCsv(twoSamples().trajectory, expected);
        QCOMPARE(readFile(path), expected.str());
        QVERIFY(readFile(path).rfind("t,x,x_dot,Ekin,Epot,E,W\n", 0) == 0);
        QVERIFY(!fs::exists(path.string() + ".bak"));
        QCOMPARE(temporaries(dir.path().toStdString()), 0);
    }
};

LL_TEST_APPLESS_MAIN(TestAtomicFile)

}  // namespace test_atomic_file
#include "test_atomic_file.moc"
