// `cmake --install` into a temporary prefix, the prefix moved, and the installed
// program run from there with the working directory elsewhere and the source and build
// trees out of reach (as root: a private mount namespace with empty tmpfs over them;
// otherwise only the working directory moves): --version, derive and render on an
// installed example, the program's own libraries (Debian's shared GiNaC), the man
// page, the desktop entry and AppStream metainfo validated, and the scene MIME type
// found for a .lagrange file through the installed MIME database.
#include "test_registry.hpp"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <unistd.h>

#include "core/io/scene_file.hpp"
#include "core/io/window_view.hpp"
#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_install {

using ll::test::ProcessRun;
using ll::test::runProcess;

namespace {

const QString kAppId = "org.lagrangelab.LagrangeLab";
const QString kSceneType = "application/x-lagrangelab-scene";

QProcessEnvironment headless() {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM", "XDG_CURRENT_DESKTOP"}) env.remove(name);
    return env;
}

// Relative paths of the files under `root`, sorted.
QStringList filesUnder(const QString& root) {
    QStringList files;
    QDirIterator it(root, QDir::Files, QDirIterator::Subdirectories | QDirIterator::FollowSymlinks);
    while (it.hasNext()) files << QDir(root).relativeFilePath(it.next());
    files.sort();
    return files;
}

// Share of pixels that differ by more than 24 in some channel.
double differingShare(const QImage& a, const QImage& b) {
    long differing = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (std::abs(qRed(p) - qRed(q)) > 24 || std::abs(qGreen(p) - qGreen(q)) > 24 || std::abs(qBlue(p) - qBlue(q)) > 24) ++differing;
        }
    return static_cast<double>(differing) / (a.width() * a.height());
}

}  // namespace

class TestInstall : public QObject {
    Q_OBJECT

    QTemporaryDir tmp_;
    QString prefix_;  // the installed prefix, after the move
    QString work_;    // the working directory of every run: outside the trees, empty
    bool hidden_ = false;

    // The installed lagrangelab with `args`, from work_, the trees hidden when possible.
    ProcessRun installed(const QStringList& args) const {
        const QString exe = prefix_ + "/bin/lagrangelab";
        if (!hidden_) return runProcess(exe, args, work_, headless());
        // tmpfs over the source tree (and the build tree when it lies elsewhere), in a
        // mount namespace of the child's own: the program cannot read either.
        const QString script = "for d in \"$1\" \"$2\"; do if [ -d \"$d\" ]; then mount -t tmpfs none \"$d\" || exit 97; fi; done; "
                               "shift 2; exec \"$@\"";
        return runProcess("unshare", QStringList{"--mount", "--", "sh", "-c", script, "sh", LL_SOURCE_DIR, LL_BUILD_DIR, exe} + args, work_,
                          headless());
    }
    QString example(const QString& name) const { return prefix_ + "/share/lagrangelab/examples/" + name; }

    static QJsonObject json(const QByteArray& text) { return QJsonDocument::fromJson(text).object(); }

private slots:
    void initTestCase() {
        QVERIFY(tmp_.isValid());
        QVERIFY2(!tmp_.path().startsWith(LL_SOURCE_DIR) && !tmp_.path().startsWith(LL_BUILD_DIR), qPrintable(tmp_.path()));
        const QString first = tmp_.path() + "/first";
        const ProcessRun install = runProcess(LL_CMAKE, {"--install", LL_BUILD_DIR, "--prefix", first});
        QVERIFY2(install.exitCode == 0, install.err.constData());
        // Move the whole prefix somewhere else, one level deeper.
        QVERIFY(QDir().mkpath(tmp_.path() + "/moved"));
        prefix_ = tmp_.path() + "/moved/prefix";
        QVERIFY(QDir().rename(first, prefix_));
        QVERIFY(!QFileInfo::exists(first));
        work_ = tmp_.path() + "/work";
        QVERIFY(QDir().mkpath(work_));
        hidden_ = ::geteuid() == 0 && !QStandardPaths::findExecutable("unshare").isEmpty() &&
                  runProcess("unshare", {"--mount", "--", "true"}).exitCode == 0;
        if (!hidden_) qWarning("not root or no mount namespace: the trees stay readable; only the working directory moves");
        else qInfo("runs in a mount namespace with tmpfs over %s and %s", LL_SOURCE_DIR, LL_BUILD_DIR);
        if (hidden_) {
            // The namespace does hide the trees.
            const ProcessRun ls =
                runProcess("unshare", {"--mount", "--", "sh", "-c", "mount -t tmpfs none \"$1\" && ls -A \"$1\"", "sh", LL_SOURCE_DIR});
            QCOMPARE(ls.exitCode, 0);
            QCOMPARE(ls.out, QByteArray());
        }
    }

    void layout() {
        // One program; the benchmarks (lagrangelab-bench) stay in the build tree.
        QCOMPARE(QDir(prefix_ + "/bin").entryList(QDir::Files), QStringList{"lagrangelab"});
        QVERIFY(QFileInfo(prefix_ + "/bin/lagrangelab").isExecutable());
        QVERIFY(!QFileInfo::exists(prefix_ + "/libexec"));
        // Every example, as in the source tree.
        const QStringList installedExamples = filesUnder(prefix_ + "/share/lagrangelab/examples");
        QVERIFY(installedExamples.contains("planar_2r.json"));
        QCOMPARE(installedExamples, filesUnder(LL_EXAMPLES_DIR));
        for (const QString& file : {"share/applications/" + kAppId + ".desktop", "share/icons/hicolor/scalable/apps/" + kAppId + ".svg",
                                    "share/mime/packages/" + kAppId + ".xml", "share/metainfo/" + kAppId + ".metainfo.xml",
                                    QString("share/man/man1/lagrangelab.1.gz")})
            QVERIFY2(QFileInfo(prefix_ + "/" + file).isFile() && QFileInfo(prefix_ + "/" + file).size() > 0, qPrintable(file));
        // The PNG icons rendered from the SVG: their size, opaque in the middle (a bob
        // of the pendulum or the backdrop), transparent at the rounded corners.
        for (int size : {16, 24, 32, 48, 64, 128, 256}) {
            const QString file = QString("%1/share/icons/hicolor/%2x%2/apps/%3.png").arg(prefix_).arg(size).arg(kAppId);
            const QImage icon(file);
            QVERIFY2(!icon.isNull(), qPrintable(file));
            QCOMPARE(icon.size(), QSize(size, size));
            QCOMPARE(qAlpha(icon.pixel(size / 2, size / 2)), 255);
            QCOMPARE(qAlpha(icon.pixel(0, 0)), 0);
        }
    }

    void binaryHoldsNoSourcePath() {
        QFile exe(prefix_ + "/bin/lagrangelab");
        QVERIFY(exe.open(QIODevice::ReadOnly));
        const QByteArray bytes = exe.readAll();
        QVERIFY(!bytes.contains(QByteArray(LL_SOURCE_DIR) + "/"));
        QVERIFY(!bytes.contains(QByteArray(LL_BUILD_DIR)));
        // KDL is a test oracle: the installed program neither links nor names it.
        QVERIFY(!bytes.contains("liborocos"));
    }

    // Linked like any Debian program: Debian's shared GiNaC, CLN, Qt and OpenSceneGraph,
    // as the dynamic loader finds them (ldd), none of them copied into the program.
    void linksDebiansSharedLibraries() {
        const ProcessRun ldd = runProcess("ldd", {prefix_ + "/bin/lagrangelab"});
        QVERIFY2(ldd.exitCode == 0, ldd.err.constData());
        for (const char* library : {"libginac.so.11", "libcln.so.6", "libQt6Core.so.6", "libQt6Widgets.so.6", "libosg.so"})
            QVERIFY2(ldd.out.contains(library), library);
        QVERIFY2(!ldd.out.contains("not found"), ldd.out.constData());
    }

    void version() {
        const ProcessRun r = installed({"--version"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(r.out, QByteArray("lagrangelab " LL_VERSION "\n"));
    }

    // The installed derive gives the model the build tree's program gives, for the
    // installed example and for a copy saved with the .lagrange extension.
    void derive() {
        const ProcessRun reference = runProcess(LL_CLI, {"derive", QString(LL_EXAMPLES_DIR) + "/planar_2r.json", "--format", "json"});
        QVERIFY2(reference.exitCode == 0, reference.err.constData());
        const QJsonObject expected = json(reference.out);
        QVERIFY(expected.contains("B") && expected.contains("C") && expected.contains("g"));
        QVERIFY(QFile::copy(example("planar_2r.json"), work_ + "/arm.lagrange"));
        for (const QString& scene : {example("planar_2r.json"), QString("arm.lagrange")}) {
            const ProcessRun r = installed({"derive", scene, "--format", "json"});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            const QJsonObject model = json(r.out);
            for (const char* key : {"B", "C", "g", "Q", "Ekin", "Epot"}) QCOMPARE(model[key], expected[key]);
        }
    }

    // A still of the installed double pendulum, written into the working directory:
    // the picture the build tree's program draws, and not empty.
    void render() {
        const QStringList options = {"--out", "still.png", "--at", "1", "--size", "320x240"};
        const ProcessRun r = installed(QStringList{"render", example("double_pendulum.json")} + options);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QImage still(work_ + "/still.png");
        QCOMPARE(still.size(), QSize(320, 240));
        const ProcessRun reference = runProcess(LL_CLI, QStringList{"render", QString(LL_EXAMPLES_DIR) + "/double_pendulum.json"} + options,
                                                tmp_.path(), headless());
        QVERIFY2(reference.exitCode == 0, reference.err.constData());
        const QImage expected(tmp_.path() + "/still.png");
        QVERIFY(differingShare(still, expected) < 0.001);
        QImage plain = still.copy();
        plain.fill(still.pixel(2, still.height() / 2));
        QVERIFY(differingShare(still, plain) > 0.01);  // the arm and the overlay are drawn
    }

    // The man page, written at build time from --help, lists every command.
    void manPage() {
        if (QStandardPaths::findExecutable("man").isEmpty()) QSKIP("man is not installed");
        QProcessEnvironment env = headless();
        env.insert("MANWIDTH", "120");
        const ProcessRun r = runProcess("man", {"-l", prefix_ + "/share/man/man1/lagrangelab.1.gz"}, work_, env);
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QString page = QString::fromUtf8(r.out).simplified();  // man justifies lines with extra spaces
        QVERIFY(page.contains("lagrangelab " LL_VERSION));
        const QString help = QString::fromUtf8(installed({"--help"}).out);
        int commands = 0;
        for (const QString& line : help.split('\n'))
            if (line.startsWith("  ") && line.size() > 2 && line[2].isLower()) {
                const QString name = line.mid(2).section(' ', 0, 0);
                const QString synopsis = installed({"help", name}).out.split('\n').first().mid(19);
                QVERIFY2(page.contains(synopsis.section(' ', 0, 1)), qPrintable(name));
                ++commands;
            }
        QVERIFY(commands >= 8);
        QVERIFY(page.contains("EXIT STATUS") && page.contains("3 simulation stopped early"));
    }

    void desktopEntryValidates() {
        const QString desktop = prefix_ + "/share/applications/" + kAppId + ".desktop";
        QFile file(desktop);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QMap<QString, QString> entry;
        for (const QString& line : QString::fromUtf8(file.readAll()).split('\n'))
            if (const int eq = line.indexOf('='); eq > 0) entry[line.left(eq)] = line.mid(eq + 1);
        QCOMPARE(entry["Exec"], QString("lagrangelab %f"));
        QCOMPARE(entry["Icon"], kAppId);
        QCOMPARE(entry["MimeType"], kSceneType + ";application/x-lagrangelab-view;application/x-lagrangelab-lesson;");
        if (QStandardPaths::findExecutable("desktop-file-validate").isEmpty())
            QSKIP("desktop-file-validate is not installed (desktop-file-utils)");
        const ProcessRun r = runProcess("desktop-file-validate", {desktop});
        QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
        QVERIFY2(!r.out.contains("error"), r.out.constData());
    }

    void metainfoValidates() {
        if (QStandardPaths::findExecutable("appstreamcli").isEmpty()) QSKIP("appstreamcli is not installed (appstream)");
        const ProcessRun r = runProcess("appstreamcli", {"validate", "--no-net", prefix_ + "/share/metainfo/" + kAppId + ".metainfo.xml"});
        QVERIFY2(r.exitCode == 0, (r.out + r.err).constData());
        QFile metainfo(prefix_ + "/share/metainfo/" + kAppId + ".metainfo.xml");
        QVERIFY(metainfo.open(QIODevice::ReadOnly));
        QVERIFY(metainfo.readAll().contains("<release version=\"" LL_VERSION "\""));  // the version --version prints
    }

    // xdg-mime names the scene type for an example saved as .lagrange, and for a .json
    // scene by its header, with only the installed MIME database.
    void mimeType() {
        for (const char* tool : {"update-mime-database", "xdg-mime"})
            if (QStandardPaths::findExecutable(tool).isEmpty())
                QSKIP(qPrintable(QString(tool) + " is not installed (shared-mime-info, xdg-utils)"));
        const ProcessRun update = runProcess("update-mime-database", {prefix_ + "/share/mime"});
        QVERIFY2(update.exitCode == 0, update.err.constData());
        QVERIFY(QFile::copy(example("simple_pendulum.json"), work_ + "/pendulum.lagrange"));
        QVERIFY(QFile::copy(example("simple_pendulum.json"), work_ + "/pendulum.json"));
        QFile plain(work_ + "/other.json");
        QVERIFY(plain.open(QIODevice::WriteOnly));
        plain.write("{\"format\": \"something-else/1\", \"name\": \"not a scene\"}\n");
        plain.close();
        QVERIFY(QDir().mkpath(tmp_.path() + "/empty-home"));
        // Without a desktop, xdg-mime asks `mimetype` (libfile-mimeinfo-perl), which reads
        // the MIME database; `file`, its last resort, does not. GNOME's path asks gio.
        QProcessEnvironment env = headless();
        if (QStandardPaths::findExecutable("mimetype").isEmpty()) {
            if (QStandardPaths::findExecutable("gio").isEmpty()) QSKIP("neither mimetype (libfile-mimeinfo-perl) nor gio is installed");
            env.insert("XDG_CURRENT_DESKTOP", "GNOME");
        }
        env.insert("XDG_DATA_HOME", tmp_.path() + "/empty-home");
        env.insert("XDG_DATA_DIRS", prefix_ + "/share");
        auto filetype = [&](const QString& file) {
            const ProcessRun r = runProcess("xdg-mime", {"query", "filetype", file}, work_, env);
            return QString::fromUtf8(r.out).trimmed();
        };
        QCOMPARE(filetype("pendulum.lagrange"), kSceneType);
        QCOMPARE(filetype("pendulum.json"), kSceneType);  // the magic, within the *.json glob
        QVERIFY(filetype("other.json") != kSceneType);
        // A scene as LagrangeLab saves it (its key order, its spacing), both extensions.
        const ll::Scene scene = ll::loadScene(example("simple_pendulum.json").toStdString()).scene;
        ll::saveScene(scene, (work_ + "/saved.lagrange").toStdString());
        ll::saveScene(scene, (work_ + "/saved.json").toStdString());
        QCOMPARE(filetype("saved.lagrange"), kSceneType);
        QCOMPARE(filetype("saved.json"), kSceneType);
        // A lesson by its extension, a view as LagrangeLab writes it by its header.
        QVERIFY(QFile::copy(example("lessons/euler_lagrange_intro.lesson"), work_ + "/intro.lesson"));
        QCOMPARE(filetype("intro.lesson"), QString("application/x-lagrangelab-lesson"));
        ll::WindowView view;
        view.scenePath = example("simple_pendulum.json").toStdString();
        view.derivation.step = 6;
        ll::saveWindowView(view, (work_ + "/view.json").toStdString());
        QCOMPARE(filetype("view.json"), QString("application/x-lagrangelab-view"));
        // With freedesktop.org's types only (the system's, built alone into a database of
        // its own) the same files are plain text and JSON.
        const QString freedesktop = "/usr/share/mime/packages/freedesktop.org.xml";
        if (!QFileInfo::exists(freedesktop)) QSKIP("no freedesktop.org.xml to compare with");
        QVERIFY(QDir().mkpath(tmp_.path() + "/system-share/mime/packages"));
        QVERIFY(QFile::copy(freedesktop, tmp_.path() + "/system-share/mime/packages/freedesktop.org.xml"));
        QCOMPARE(runProcess("update-mime-database", {tmp_.path() + "/system-share/mime"}).exitCode, 0);
        env.insert("XDG_DATA_DIRS", tmp_.path() + "/system-share");
        QCOMPARE(filetype("pendulum.lagrange"), QString("text/plain"));
        QCOMPARE(filetype("saved.json"), QString("application/json"));
    }
};

LL_TEST_GUILESS_MAIN(TestInstall)

}  // namespace test_install
#include "test_install.moc"
