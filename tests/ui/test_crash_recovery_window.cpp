// Crash recovery proven with real processes (issue 38): this executable, started with
// --recovery-child SCENE, is a window that opens SCENE, edits it through the document as
// the table does, and waits; the tests kill it with SIGKILL once its 5 s autosave wrote
// the copy, then start windows again and check what they offer: the edits of that scene,
// named, with what changed, restored on top of the untouched file; nothing in place of
// another scene that was asked for; a warning when the file changed on disk since; two
// windows on one scene with a copy each; copies cut short or empty set aside, never
// half-loaded.
#include "test_registry.hpp"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMessageBox>
#include <QAbstractButton>
#include <QTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <csignal>
#include <iostream>

#include "core/io/scene_file.hpp"
#include "ui/document/joint_table_model.hpp"
#include "ui/window/main_window.hpp"
#include "window_waits.hpp"
#include "ui/window/autosave.hpp"
#include "ui/window/model_editor.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_crash_recovery_window {

using namespace ll::ui;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR "/") + name; }

// The child: open, edit a1 := 1.2 through the table's document, wait for the autosave,
// say where it wrote, then wait to be killed.
int recoveryChild(const QString& scene) {
    MainWindow w;
    w.setAskBeforeClosing(false);
    w.show();
    if (!w.openFile(scene, nullptr, true)) return 2;
    w.editor().joints().setData(w.editor().joints().index(0, JointTableModel::A), "1.2", Qt::EditRole);
    // The autosave timer writes the copy within 5 s of the edit.
    if (!ll::test::waitUntil([&] { return !w.autosave().ownFile().isEmpty() && QFile::exists(w.autosave().ownFile()); }, 60000)) return 3;
    std::cout << "autosaved " << w.autosave().ownFile().toStdString() << std::endl;
    return QApplication::exec();  // until SIGKILL
}

// A child window on `scene`, started, edited and autosaved; returns its process.
std::unique_ptr<QProcess> editedWindow(const QString& scene, const QString& recoveryDir) {
    auto p = std::make_unique<QProcess>();
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("LAGRANGELAB_RECOVERY_DIR", recoveryDir);
    p->setProcessEnvironment(env);
    // This test's program holds every ui test: the test's name comes first.
    p->start(QCoreApplication::applicationFilePath(), {"test_crash_recovery_window", "--recovery-child", scene});
    return p;
}

bool autosaved(QProcess& p) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 90000) {
        if (p.state() == QProcess::NotRunning) return false;
        p.waitForReadyRead(100);
        if (p.peek(4096).contains("autosaved ")) return true;
    }
    return false;
}

void killHard(QProcess& p) {
    ::kill(static_cast<pid_t>(p.processId()), SIGKILL);
    p.waitForFinished(10000);
}

bool opened(MainWindow& w, const QString& scene) {
    w.setAskBeforeClosing(false);
    w.show();
    return w.openFile(scene, nullptr, true);
}

}  // namespace

class TestCrashRecoveryWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString recovery_, arm_, spring_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        recovery_ = dir_.filePath("recovery");
        arm_ = dir_.filePath("arm.json");
        spring_ = dir_.filePath("spring.json");
        QVERIFY(QFile::copy(example("planar_2r.json"), arm_));
        QVERIFY(QFile::copy(example("mass_spring_pair_lagrangian.json"), spring_));
        for (const QString& f : {arm_, spring_}) QFile::setPermissions(f, QFile::ReadOwner | QFile::WriteOwner);
        qputenv("LAGRANGELAB_RECOVERY_DIR", recovery_.toLocal8Bit());
    }

    // start, edit, wait, kill -9; then another scene opens as asked, this scene's edits
    // are offered named with what changed, and restored on top of the untouched file.
    void killedWindowsEditsAreOfferedNamedAndRestored() {
        auto child = editedWindow(arm_, recovery_);
        QVERIFY2(autosaved(*child), child->readAllStandardError().constData());
        killHard(*child);
        const QByteArray original = [&] {
            QFile f(arm_);
            f.open(QIODevice::ReadOnly);
            return f.readAll();
        }();
        QCOMPARE(ll::loadScene(arm_.toStdString()).scene.robot.joints[0].dh.a, 1.0);  // the file is untouched

        {  // another scene: opened as asked; the arm's edits are pending apart, named
            MainWindow other;
            QVERIFY(opened(other, spring_));
            const std::vector<RecoveryCopy> left = other.autosave().leftBehind();
            QCOMPARE(int(left.size()), 1);
            QVERIFY(!other.autosave().isOwnScene(left[0]));
            QVERIFY(!other.autosave().restore(left[0]));  // never in place of the scene asked for
            QCOMPARE(other.document().path(), spring_);
            QVERIFY(!other.document().isModified());
            QVERIFY(other.autosave().question(left[0]).contains("arm.json (in " + dir_.path()));
        }

        MainWindow w;
        QVERIFY(opened(w, arm_));
        const std::vector<RecoveryCopy> left = w.autosave().leftBehind();
        QCOMPARE(int(left.size()), 1);
        QVERIFY(w.autosave().isOwnScene(left[0]));
        const QString question = w.autosave().question(left[0]);
        QVERIFY2(question.contains("arm.json (in " + dir_.path()), qPrintable(question));
        QVERIFY2(question.contains("robot.joints[0].a (joint 1): \"a1\"") && question.contains("1.2"), qPrintable(question));
        QVERIFY2(!question.contains("changed on disk"), qPrintable(question));
        QVERIFY(!w.document().isModified());  // nothing restored silently
        QVERIFY(w.autosave().restore(left[0]));
        QTRY_COMPARE_WITH_TIMEOUT(w.document().validScene().robot.joints[0].dh.a, 1.2, 30000);
        QVERIFY(w.document().isModified());
        QCOMPARE(w.document().path(), arm_);
        QVERIFY(!QFile::exists(left[0].file));           // the crashed copy is gone...
        QVERIFY(QFile::exists(w.autosave().ownFile()));  // ...after this window's own was written
        QFile f(arm_);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), original);   // still untouched until saved
        w.document().undoStack()->undo();  // undo returns to the file as it is
        QTRY_COMPARE_WITH_TIMEOUT(w.document().validScene().robot.joints[0].dh.a, 1.0, 30000);
        w.autosave().discard();
        QVERIFY(w.autosave().leftBehind().empty());
    }

    // The dialog itself, as a student meets it on the next start: it names the file and
    // what changed; "Restore the edits" restores them (its picture: LL_SHOT_DIR/recovery.png).
    void theQuestionIsAskedAndAnswered() {
        auto child = editedWindow(arm_, recovery_);
        QVERIFY(autosaved(*child));
        killHard(*child);
        MainWindow w;
        QVERIFY(opened(w, arm_));
        QString asked;
        QTimer::singleShot(300, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) return;
            asked = box->text();
            const QString shots = qEnvironmentVariable("LL_SHOT_DIR");
            if (!shots.isEmpty()) box->grab().save(shots + "/recovery.png");
            for (QAbstractButton* b : box->buttons())
                if (b->text() == "Restore the edits") b->click();
        });
        w.autosave().offer();
        QVERIFY2(asked.contains("arm.json (in ") && asked.contains("What the edits change"), qPrintable(asked));
        QTRY_COMPARE_WITH_TIMEOUT(w.document().validScene().robot.joints[0].dh.a, 1.2, 30000);
        QVERIFY(w.document().isModified());
        QVERIFY(w.autosave().leftBehind().empty());
        w.autosave().discard();
    }

    // Two windows on one scene keep a copy each; killed, both are offered; a file changed
    // on disk since is said before anything is restored.
    void twoWindowsAndAFileChangedSince() {
        auto first = editedWindow(arm_, recovery_), second = editedWindow(arm_, recovery_);
        QVERIFY(autosaved(*first));
        QVERIFY(autosaved(*second));
        const QString a = QString::fromUtf8(first->readAllStandardOutput()).section("autosaved ", 1).trimmed();
        const QString b = QString::fromUtf8(second->readAllStandardOutput()).section("autosaved ", 1).trimmed();
        QVERIFY2(a != b && QFile::exists(a) && QFile::exists(b), qPrintable(a + " " + b));
        {
            MainWindow w;  // both still running: their copies are theirs, not offered
            QVERIFY(opened(w, arm_));
            QVERIFY(w.autosave().leftBehind().empty());
        }
        killHard(*first);
        killHard(*second);
        // The file changes on disk after the edits were made.
        QJsonObject root;
        {
            QFile f(arm_);
            QVERIFY(f.open(QIODevice::ReadOnly));
            root = QJsonDocument::fromJson(f.readAll()).object();
        }
        root["name"] = "changed on disk since";
        {
            QFile f(arm_);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(QJsonDocument(root).toJson());
        }
        MainWindow w;
        QVERIFY(opened(w, arm_));
        const std::vector<RecoveryCopy> left = w.autosave().leftBehind();
        QCOMPARE(int(left.size()), 2);
        for (const RecoveryCopy& copy : left) {
            QVERIFY(w.autosave().isOwnScene(copy));
            const QString question = w.autosave().question(copy);
            const int warning = question.indexOf("has changed on disk");
            QVERIFY2(warning > 0 && warning < question.indexOf("What the edits change"), qPrintable(question));
            CrashRecovery::remove(copy);
        }
    }

    // A power loss while a copy was written: cut short or empty, it is set aside with a
    // message and never loaded.
    void copiesCutShortAreSetAside() {
        QDir().mkpath(recovery_);
        QJsonObject copy{{"format", "lagrangelab-recovery/1"},
                         {"recovery_of", arm_},
                         {"original_sha256", ""},
                         {"pid", 999999},
                         {"written", "2026-11-27T12:00:00Z"},
                         {"scene", QJsonObject{{"name", "x"}}}};
        const QByteArray json = QJsonDocument(copy).toJson();
        for (const auto& [name, bytes] :
             {std::pair{QString("cut.json"), json.left(json.size() / 2)}, {QString("empty.json"), QByteArray()}}) {
            QFile f(recovery_ + "/" + name);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        }
        MainWindow w;
        QVERIFY(opened(w, spring_));
        QStringList damaged;
        QVERIFY(w.autosave().leftBehind(&damaged).empty());
        QCOMPARE(damaged.size(), 2);
        QVERIFY(QFile::exists(recovery_ + "/cut.json.damaged") && QFile::exists(recovery_ + "/empty.json.damaged"));
        QVERIFY(!QFile::exists(recovery_ + "/cut.json"));
        QCOMPARE(w.document().path(), spring_);
    }
};

static int runCrashRecoveryWindow(int argc, char** argv) {
    QApplication app(argc, argv);
    if (argc == 3 && QByteArray(argv[1]) == "--recovery-child") return recoveryChild(QString::fromLocal8Bit(argv[2]));
    TestCrashRecoveryWindow test;
    return QTest::qExec(&test, argc, argv);
}
LL_TEST_PROGRAM(runCrashRecoveryWindow)

}  // namespace test_crash_recovery_window
#include "test_crash_recovery_window.moc"
