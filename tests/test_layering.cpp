// Dependencies point one way, app → ui → core: core includes no Qt, no
// OpenSceneGraph and nothing from ui/ or app/; ui includes nothing from app/.
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <regex>

namespace fs = std::filesystem;

// Ordinary string literals: moc does not parse raw strings holding '#' and quotes.
const char* const kCoreForbidden = "^\\s*#\\s*include\\s*[<\"](Q[A-Za-z]|osg|ui/|app/)";
const char* const kUiForbidden = "^\\s*#\\s*include\\s*\"app/";

class TestLayering : public QObject {
    Q_OBJECT

    // Lines of the sources under `folder` whose #include matches `forbidden`.
    static QStringList offending(const char* folder, const std::regex& forbidden) {
        QStringList found;
        int files = 0;
        for (const auto& entry : fs::recursive_directory_iterator(fs::path(LL_SOURCE_DIR) / folder)) {
            const std::string ext = entry.path().extension().string();
            if (ext != ".hpp" && ext != ".cpp" && ext != ".h") continue;
            ++files;
            std::ifstream in(entry.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                if (std::regex_search(line, forbidden))
                    found << QString("%1:%2: %3").arg(QString::fromStdString(entry.path().string())).arg(n).arg(QString::fromStdString(line));
        }
        if (files == 0) qFatal("no sources under %s", folder);
        return found;
    }

private slots:
    void coreIsPureCpp() {
        const QStringList bad = offending("core", std::regex(kCoreForbidden));
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join('\n')));
    }

    void uiDoesNotReachIntoApp() {
        const QStringList bad = offending("ui", std::regex(kUiForbidden));
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join('\n')));
    }

    // The check itself sees a violation when there is one.
    void detectsAViolation() {
        const std::regex forbidden(kCoreForbidden);
        QVERIFY(std::regex_search("#include <QWidget>", forbidden));
        QVERIFY(std::regex_search("#include <osgViewer/Viewer>", forbidden));
        QVERIFY(std::regex_search("#include \"ui/plot.hpp\"", forbidden));
        QVERIFY(!std::regex_search("#include <Eigen/Core>", forbidden));
    }
};

QTEST_APPLESS_MAIN(TestLayering)
#include "test_layering.moc"
