// The Debian package (label `package`): built with CPack from the build tree, its
// control fields (version = the project version --version prints; run-time and
// shlibdeps dependencies) and contents (binary, examples, desktop entry, icons, MIME
// type, metainfo, man page); then, as root, `dpkg -i`, the installed program, the MIME
// type through the system database, and `dpkg -r` leaving none of its files behind.
// Skipped without dpkg-deb; the install part also when not root or when a lagrangelab
// package is installed already (the test must not replace it).
#include "test_registry.hpp"

#include <QDir>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <unistd.h>

#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_package {

using ll::test::ProcessRun;
using ll::test::runProcess;

namespace {

const QString kAppId = "org.lagrangelab.LagrangeLab";

// dpkg, retried while another dpkg or apt holds the lock (other builds on the machine).
ProcessRun dpkg(const QStringList& args) {
    for (int attempt = 0;; ++attempt) {
        const ProcessRun r = runProcess("dpkg", args);
        if (r.exitCode == 0 || !r.err.contains("lock") || attempt == 60) return r;
        QThread::sleep(5);
    }
}

bool packageInstalled() {
    const ProcessRun r = runProcess("dpkg-query", {"-W", "-f=${Status}", "lagrangelab"});
    return r.exitCode == 0 && r.out.contains("installed") && !r.out.contains("not-installed");
}

}  // namespace

class TestPackage : public QObject {
    Q_OBJECT

    QTemporaryDir tmp_;
    QString deb_;
    QStringList files_;  // the package's regular files, absolute (/usr/…)

    QByteArray field(const char* name) const { return runProcess("dpkg-deb", {"--field", deb_, name}).out.trimmed(); }

private slots:
    void initTestCase() {
        if (QStandardPaths::findExecutable("dpkg-deb").isEmpty()) QSKIP("dpkg-deb is missing");
        QVERIFY(tmp_.isValid());
        const ProcessRun cpack = runProcess(LL_CPACK, {"--config", LL_BUILD_DIR "/CPackConfig.cmake", "-B", tmp_.path()});
        QVERIFY2(cpack.exitCode == 0, (cpack.out + cpack.err).constData());
        const QStringList debs = QDir(tmp_.path()).entryList({"*.deb"}, QDir::Files);
        QCOMPARE(debs.size(), 1);
        deb_ = tmp_.path() + "/" + debs.first();
        qInfo("%s", qPrintable(debs.first()));
    }

    void controlFields() {
        const ProcessRun info = runProcess("dpkg-deb", {"--info", deb_});
        QVERIFY2(info.exitCode == 0, info.err.constData());
        QVERIFY(info.out.contains("Depends:"));
        QCOMPARE(field("Package"), QByteArray("lagrangelab"));
        QCOMPARE(field("Version"), QByteArray(LL_VERSION));
        const QByteArray depends = field("Depends");
        qInfo("Depends: %s", depends.constData());
        // Declared: programs and data the binary loads at run time.
        for (const char* package : {"ffmpeg", "fonts-dejavu-core", LL_MATH_FONT_PACKAGE, "libegl-mesa0", "qt6-qpa-plugins"})
            QVERIFY2(depends.contains(package), package);
        // Found by dpkg-shlibdeps from the libraries the binary links.
        for (const char* package : {"libc6", "libginac11", "libcln6", "libqt6core6", "libqt6gui6", "libopenscenegraph161", "libegl1"})
            QVERIFY2(depends.contains(package), package);
    }

    void contents() {
        const ProcessRun r = runProcess("dpkg-deb", {"--contents", deb_});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        for (const QByteArray& line : r.out.split('\n'))
            if (line.startsWith('-')) files_ << QString::fromUtf8(line.mid(line.indexOf("./") + 1));
        for (const QString& file :
             {QString("/usr/bin/lagrangelab"), QString("/usr/share/lagrangelab/examples/planar_2r.json"),
              QString("/usr/share/lagrangelab/examples/hard/stiff_spring.json"), "/usr/share/applications/" + kAppId + ".desktop",
              "/usr/share/icons/hicolor/scalable/apps/" + kAppId + ".svg", "/usr/share/icons/hicolor/48x48/apps/" + kAppId + ".png",
              "/usr/share/icons/hicolor/256x256/apps/" + kAppId + ".png", "/usr/share/mime/packages/" + kAppId + ".xml",
              "/usr/share/metainfo/" + kAppId + ".metainfo.xml", QString("/usr/share/man/man1/lagrangelab.1.gz")})
            QVERIFY2(files_.contains(file), qPrintable(file));
        // Nothing outside /usr, nothing of the build or source trees, no benchmarks.
        QVERIFY(!files_.contains("/usr/bin/lagrangelab-bench"));
        for (const QString& file : files_) QVERIFY2(file.startsWith("/usr/"), qPrintable(file));
    }

    void installAndRemove() {
        if (::geteuid() != 0) QSKIP("dpkg -i needs root");
        if (packageInstalled()) QSKIP("a lagrangelab package is installed already; not replacing it");
        QVERIFY(!files_.isEmpty());
        const ProcessRun install = dpkg({"-i", deb_});
        QVERIFY2(install.exitCode == 0, (install.out + install.err).constData());
        QVERIFY(packageInstalled());
        QTemporaryDir work;
        const ProcessRun version = runProcess("/usr/bin/lagrangelab", {"--version"}, work.path());
        const ProcessRun derive =
            runProcess("/usr/bin/lagrangelab", {"derive", "/usr/share/lagrangelab/examples/simple_pendulum.json"}, work.path());
        // Typeset pages: Qt on its offscreen platform.
        const ProcessRun pages = runProcess("/usr/bin/lagrangelab",
                                            {"derive", "/usr/share/lagrangelab/examples/simple_pendulum.json", "--steps", "7", "--format",
                                             "svg", "--out", work.path() + "/b.svg"},
                                            work.path());
        const qint64 svgSize = QFileInfo(work.path() + "/b.svg").size();
        // The dpkg trigger of shared-mime-info updated the system database.
        QFile::copy("/usr/share/lagrangelab/examples/simple_pendulum.json", work.path() + "/pendulum.lagrange");
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("XDG_DATA_DIRS");
        env.remove("XDG_CURRENT_DESKTOP");
        env.insert("XDG_DATA_HOME", work.path() + "/no-home");
        const ProcessRun mime = QStandardPaths::findExecutable("mimetype").isEmpty()
                                    ? ProcessRun{0, "skipped", {}}
                                    : runProcess("xdg-mime", {"query", "filetype", "pendulum.lagrange"}, work.path(), env);

        const ProcessRun remove = dpkg({"-r", "lagrangelab"});
        QVERIFY2(remove.exitCode == 0, (remove.out + remove.err).constData());
        QVERIFY(!packageInstalled());
        for (const QString& file : files_) QVERIFY2(!QFileInfo::exists(file), qPrintable(file));
        QVERIFY(!QFileInfo::exists("/usr/share/lagrangelab"));

        // Checked after the removal, so that a failure leaves the machine clean.
        QVERIFY2(version.exitCode == 0, version.err.constData());
        QCOMPARE(version.out, QByteArray("lagrangelab " LL_VERSION "\n"));
        QVERIFY2(derive.exitCode == 0, derive.err.constData());
        QVERIFY2(pages.exitCode == 0, pages.err.constData());
        QVERIFY(svgSize > 1000);
        const ProcessRun built = runProcess(LL_CLI, {"derive", LL_EXAMPLES_DIR "/simple_pendulum.json"});
        QCOMPARE(derive.out, built.out);  // the packaged program derives what the built one does
        if (mime.out != "skipped") QCOMPARE(mime.out.trimmed(), QByteArray("application/x-lagrangelab-scene"));
    }
};

LL_TEST_GUILESS_MAIN(TestPackage)

}  // namespace test_package
#include "test_package.moc"
