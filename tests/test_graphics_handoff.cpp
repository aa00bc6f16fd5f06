// lagrangelab and lagrangelab-gui (app/graphics_handoff.hpp): the command-line program
// links neither Qt nor OpenSceneGraph; every command that paints is handed over to
// lagrangelab-gui with its command line unchanged, and every other command runs without
// it. LAGRANGELAB_GUI points the handover at a missing program (then a painting command
// fails in one line, exit 1, before any work), at lagrangelab itself (no endless
// handover) or at a script that prints what it got.
#include <QtTest>

#include <QFile>
#include <QTemporaryDir>

#include "process_run.hpp"

using ll::test::ProcessRun;
using ll::test::runProcess;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

QProcessEnvironment withGui(const QString& program) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("LAGRANGELAB_GUI", program);
    env.remove("QT_QPA_PLATFORM");
    return env;
}

}  // namespace

class TestGraphicsHandoff : public QObject {
    Q_OBJECT

    QTemporaryDir tmp_;
    QString missing() const { return tmp_.path() + "/no-such-gui"; }

private slots:
    // What the dynamic loader loads for each program: lagrangelab nothing at all (it is
    // linked statically, app/CMakeLists.txt) or, built with the sanitizers, the C and C++
    // run-times but neither Qt nor OpenSceneGraph; lagrangelab-gui both.
    void textProgramLoadsNeitherQtNorOsg() {
        const ProcessRun text = runProcess("ldd", {LL_CLI});
        QVERIFY2(text.exitCode == 0, text.err.constData());
        QVERIFY2(text.out.contains("statically linked") || text.out.contains("libc.so"), text.out.constData());
        for (const char* lib : {"libQt6", "libosg", "libOpenThreads", "libEGL", "libGL"})
            QVERIFY2(!text.out.contains(lib), lib);
        const ProcessRun gui = runProcess("ldd", {LL_GUI});
        QVERIFY2(gui.exitCode == 0, gui.err.constData());
        for (const char* lib : {"libQt6Gui", "libQt6Widgets", "libosg.", "libosgViewer", "libEGL"})
            QVERIFY2(gui.out.contains(lib), lib);
    }

    // With the graphics program missing, each painting command line stops at once with
    // one line naming it (exit 1) and writes nothing.
    void paintingCommandsAreHandedOver() {
        const QString out = tmp_.path() + "/out";
        // Handed over before the scene is read: a missing scene is the graphics
        // program's to report, so here it is the missing program that is reported.
        const QString noScene = tmp_.path() + "/no-scene.json";
        const QList<QStringList> painting = {
            {"derive", noScene, "--format", "pdf", "--out", out + ".pdf"},
            {"accuracy", noScene, "--out", out + "-plot.png"},
            {"derive", example("planar_2r.json"), "--format", "pdf", "--out", out + ".pdf"},
            {"derive", example("planar_2r.json"), "--format=svg", "--out", out + ".svg"},
            {"derive", example("planar_2r.json"), "--steps", "7", "--format", "png", "--out", out + ".png"},
            {"render", example("simple_pendulum.json"), "--out", out + ".gif"},
            {"accuracy", example("simple_pendulum.json"), "--out", out + "-plot.svg"},
            {"bench", "--typeset"},
            {"bench", "--render"},
            {"bench", "--gui"},
        };
        for (const QStringList& args : painting) {
            const ProcessRun r = runProcess(LL_CLI, args, tmp_.path(), withGui(missing()));
            const QByteArray line = args.join(' ').toUtf8();
            QVERIFY2(r.exitCode == 1, line.constData());
            QVERIFY2(r.out.isEmpty(), line.constData());
            QVERIFY2(r.err.startsWith("error: cannot start " + missing().toUtf8()), (line + ": " + r.err).constData());
            QCOMPARE(r.err.count('\n'), 1);
        }
        // The window too, when there is a display to open it on.
        QProcessEnvironment env = withGui(missing());
        env.insert("DISPLAY", ":98");
        const ProcessRun window = runProcess(LL_CLI, {example("planar_2r.json")}, tmp_.path(), env);
        QCOMPARE(window.exitCode, 1);
        QVERIFY2(window.err.startsWith("error: cannot start "), window.err.constData());
        QVERIFY(QDir(tmp_.path()).entryList(QDir::Files).isEmpty());
    }

    // Everything else runs in lagrangelab itself: the same commands succeed with the
    // graphics program missing.
    void textCommandsRunWithoutIt() {
        const QList<QStringList> text = {
            {"--version"},
            {"help", "render"},
            {"render", "--help"},
            {"derive", example("planar_2r.json")},
            {"derive", example("planar_2r.json"), "--format", "json"},
            {"derive", example("panda.json"), "--format", "latex"},
            {"eval", example("planar_2r.json")},
            {"integrators"},
            {"accuracy", example("simple_pendulum.json"), "--integrators", "rk4", "--steps", "100,200", "--duration", "0.5"},
            {"bench", "--rhs", "--batches", "1"},
        };
        for (const QStringList& args : text) {
            const ProcessRun r = runProcess(LL_CLI, args, tmp_.path(), withGui(missing()));
            const QByteArray line = args.join(' ').toUtf8();
            QVERIFY2(r.exitCode == 0, (line + ": " + r.err).constData());
            QVERIFY2(!r.out.isEmpty(), line.constData());
            QVERIFY2(!r.err.contains("cannot start"), line.constData());
        }
        // A bad painting command line is handed over all the same: the graphics program
        // reads it with the same code and says what is wrong (here: it is missing).
        const ProcessRun bad = runProcess(LL_CLI, {"derive", example("planar_2r.json"), "--format", "pdf"}, tmp_.path(),
                                          withGui(missing()));
        QCOMPARE(bad.exitCode, 1);
    }

    // A LAGRANGELAB_GUI naming lagrangelab itself hands back once, then stops in one
    // line (it would exec itself forever).
    void noHandoverLoop() {
        const ProcessRun r = runProcess(LL_CLI, {"render", example("simple_pendulum.json"), "--out", tmp_.path() + "/loop.png"},
                                        tmp_.path(), withGui(LL_CLI), 20000);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("handed the command back"), r.err.constData());
        QCOMPARE(r.err.count('\n'), 1);
    }

    // The handover keeps the command line as typed (spaces, '=', the order), the
    // working directory and the standard streams.
    void commandLineIsKept() {
        const QString script = tmp_.path() + "/echo-gui";
        QFile f(script);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("#!/bin/sh\nfor a in \"$@\"; do printf '[%s]\\n' \"$a\"; done\npwd\necho to-stderr >&2\nexit 7\n");
        f.close();
        QVERIFY(f.setPermissions(f.permissions() | QFileDevice::ExeOwner));
        const QStringList args = {"derive", "my scene.json", "--steps", "7-8", "--format=png", "--out", "a b.png"};
        const ProcessRun r = runProcess(LL_CLI, args, tmp_.path(), withGui(script));
        QCOMPARE(r.exitCode, 7);
        QByteArray expected;
        for (const QString& a : args) expected += "[" + a.toUtf8() + "]\n";
        expected += QDir(tmp_.path()).canonicalPath().toUtf8() + "\n";
        QCOMPARE(r.out, expected);
        QCOMPARE(r.err, QByteArray("to-stderr\n"));
    }

    // Through the handover and directly, the graphics program writes the same pages.
    void handedOverPagesAreTheGraphicsProgramsPages() {
        const QString viaText = tmp_.path() + "/via-text.svg", direct = tmp_.path() + "/direct.svg";
        const QStringList args = {"derive", example("planar_2r.json"), "--steps", "7", "--format", "svg", "--out"};
        const ProcessRun a = runProcess(LL_CLI, args + QStringList{viaText}, tmp_.path());
        const ProcessRun b = runProcess(LL_GUI, args + QStringList{direct}, tmp_.path());
        QVERIFY2(a.exitCode == 0, a.err.constData());
        QVERIFY2(b.exitCode == 0, b.err.constData());
        QFile fa(viaText), fb(direct);
        QVERIFY(fa.open(QIODevice::ReadOnly) && fb.open(QIODevice::ReadOnly));
        const QByteArray pa = fa.readAll(), pb = fb.readAll();
        QVERIFY(pa.contains("<svg"));
        QCOMPARE(pa.size(), pb.size());
        QVERIFY(pa == pb);
    }
};

QTEST_GUILESS_MAIN(TestGraphicsHandoff)
#include "test_graphics_handoff.moc"
