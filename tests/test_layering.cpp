// Dependencies point one way, app → ui → core: core includes no Qt, no
// OpenSceneGraph and nothing from ui/ or app/; ui includes nothing from app/. Inside
// core the folders are layers in the order core/CMakeLists.txt lists (LL_CORE_LAYERS):
// a folder includes only itself and the folders before it, and GiNaC only from
// core/symbolic on. Inside ui the same, in the order ui/CMakeLists.txt lists
// (LL_UI_LAYERS: paint → document → window), and no Qt Widgets, Charts or OpenGL
// widgets below window. The build enforces both with per-layer include folders.
#include "test_registry.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_layering {

namespace fs = std::filesystem;

// Ordinary string literals: moc does not parse raw strings holding '#' and quotes.
const char* const kCoreForbidden = "^\\s*#\\s*include\\s*[<\"](Q[A-Za-z]|osg|ui/|app/)";
const char* const kUiForbidden = "^\\s*#\\s*include\\s*\"app/";
const char* const kTestsForbidden = "^\\s*#\\s*include\\s*[<\"]tests/";

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
                    found
                        << QString("%1:%2: %3").arg(QString::fromStdString(entry.path().string())).arg(n).arg(QString::fromStdString(line));
        }
        if (files == 0) qFatal("no sources under %s", folder);
        return found;
    }

    // The layer order as core/CMakeLists.txt (or ui/'s) declares it.
    static std::vector<std::string> coreLayers() { return layersOf("core", "LL_CORE_LAYERS"); }
    static std::vector<std::string> uiLayers() { return layersOf("ui", "LL_UI_LAYERS"); }
    static std::vector<std::string> layersOf(const char* folder, const std::string& variable) {
        std::ifstream in(fs::path(LL_SOURCE_DIR) / folder / "CMakeLists.txt");
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::smatch m;
        if (!std::regex_search(text, m, std::regex("set\\(" + variable + " ([a-z ]+)\\)"))) qFatal("no %s", variable.c_str());
        std::vector<std::string> layers;
        std::istringstream words(m[1].str());
        for (std::string w; words >> w;) layers.push_back(w);
        return layers;
    }

    static int rank(const std::vector<std::string>& layers, const std::string& folder) {
        for (std::size_t i = 0; i < layers.size(); ++i)
            if (layers[i] == folder) return static_cast<int>(i);
        return -1;
    }

    // "file:line: text" for each include of a higher core layer (or of GiNaC below
    // symbolic) in the sources of core/<folder>.
    static QStringList layerViolations(const std::vector<std::string>& layers, const std::string& folder, const std::string& file,
                                       const std::string& text) {
        QStringList found;
        const int own = rank(layers, folder), ginacFrom = rank(layers, "symbolic");
        const std::regex coreInclude("^\\s*#\\s*include\\s*\"core/([a-z_]+)/"), ginac("^\\s*#\\s*include\\s*<ginac/");
        std::istringstream lines(text);
        std::string line;
        for (int n = 1; std::getline(lines, line); ++n) {
            std::smatch m;
            const bool up = std::regex_search(line, m, coreInclude) && rank(layers, m[1].str()) > own;
            if (up || (own < ginacFrom && std::regex_search(line, ginac)))
                found << QString("%1:%2: %3").arg(QString::fromStdString(file)).arg(n).arg(QString::fromStdString(line));
        }
        return found;
    }

    // "file:line: text" for each include of a higher ui layer in the sources of ui/<folder>,
    // and, below `widgetsFrom`, of a header of `widgetHeaders` (Qt Widgets, Charts, OpenGL widgets).
    static QStringList uiLayerViolations(const std::vector<std::string>& layers, const std::string& folder, const std::string& file,
                                         const std::string& text, const std::set<std::string>& widgetHeaders) {
        QStringList found;
        const int own = rank(layers, folder), widgetsFrom = rank(layers, "window");
        const std::regex uiInclude("^\\s*#\\s*include\\s*\"ui/([a-z_]+)/"),
            qtInclude("^\\s*#\\s*include\\s*<(?:Qt[A-Za-z]+/)?(Q[A-Za-z]+)>");
        std::istringstream lines(text);
        std::string line;
        for (int n = 1; std::getline(lines, line); ++n) {
            std::smatch m;
            const bool up = std::regex_search(line, m, uiInclude) && rank(layers, m[1].str()) > own;
            const bool widget = own < widgetsFrom && std::regex_search(line, m, qtInclude) && widgetHeaders.count(m[1].str());
            if (up || widget) found << QString("%1:%2: %3").arg(QString::fromStdString(file)).arg(n).arg(QString::fromStdString(line));
        }
        return found;
    }

    // The class headers of Qt's widget modules as installed (QWidget, QChartView, QOpenGLWidget, …).
    static std::set<std::string> widgetHeaders() {
        std::set<std::string> names;
        for (const char* folder : {LL_QT_WIDGETS_INCLUDE, LL_QT_CHARTS_INCLUDE, LL_QT_OPENGLWIDGETS_INCLUDE})
            for (const auto& entry : fs::directory_iterator(folder))
                if (const std::string name = entry.path().filename().string();
                    name.size() > 1 && name[0] == 'Q' && entry.path().extension().empty())
                    names.insert(name);
        if (!names.count("QWidget") || !names.count("QChartView")) qFatal("Qt's widget headers not found");
        return names;
    }

private slots:
    void coreLayersPointDown() {
        const std::vector<std::string> layers = coreLayers();
        QVERIFY(layers.size() >= 6);
        QStringList bad;
        for (const auto& dir : fs::directory_iterator(fs::path(LL_SOURCE_DIR) / "core")) {
            if (!dir.is_directory()) continue;
            const std::string folder = dir.path().filename().string();
            QVERIFY2(rank(layers, folder) >= 0, qPrintable(QString::fromStdString("core/" + folder + " is not a layer")));
            // Sub-folders (a layer's message catalogues, core/model/messages) belong to their layer.
            for (const auto& entry : fs::recursive_directory_iterator(dir.path())) {
                if (!entry.is_regular_file()) continue;
                std::ifstream in(entry.path());
                const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
                bad << layerViolations(layers, folder, entry.path().string(), text);
            }
        }
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join('\n')));
    }

    // The layer check sees a back edge and GiNaC below symbolic when there is one.
    void detectsALayerViolation() {
        const std::vector<std::string> layers = coreLayers();
        QCOMPARE(layerViolations(layers, "dynamics", "f", "#include \"core/io/scene_file.hpp\"\n").size(), 1);
        QCOMPARE(layerViolations(layers, "simulation", "f", "#include <ginac/ginac.h>\n").size(), 1);
        QCOMPARE(layerViolations(layers, "io", "f", "#include \"core/dynamics/energy.hpp\"\n").size(), 0);
        QCOMPARE(layerViolations(layers, "symbolic", "f", "#include <ginac/ginac.h>\n").size(), 0);
        // The presentation layer sits on the derivation: symbolic derives and compiles and
        // never reads how a result is shown; present shows what symbolic derived.
        QVERIFY(rank(layers, "symbolic") < rank(layers, "present") && rank(layers, "present") < rank(layers, "pipeline"));
        QCOMPARE(layerViolations(layers, "symbolic", "f", "#include \"core/present/display_tree.hpp\"\n").size(), 1);
        QCOMPARE(layerViolations(layers, "present", "f", "#include \"core/symbolic/derivation.hpp\"\n").size(), 0);
        // The visual scene is plain data below the derivation: no GiNaC in it.
        QVERIFY(rank(layers, "visual") < rank(layers, "symbolic"));
        QCOMPARE(layerViolations(layers, "visual", "f", "#include <ginac/ginac.h>\n").size(), 1);
        QCOMPARE(layerViolations(layers, "visual", "f", "#include \"core/symbolic/compiled_body_poses.hpp\"\n").size(), 1);
    }

    void uiLayersPointDown() {
        const std::vector<std::string> layers = uiLayers();
        QCOMPARE(layers, (std::vector<std::string>{"paint", "document", "window"}));
        const std::set<std::string> widgets = widgetHeaders();
        QStringList bad;
        int files = 0;
        for (const auto& dir : fs::directory_iterator(fs::path(LL_SOURCE_DIR) / "ui")) {
            if (!dir.is_directory()) {
                QVERIFY2(dir.path().filename() == "CMakeLists.txt",
                         qPrintable(QString::fromStdString(dir.path().string() + " is outside the layers")));
                continue;
            }
            const std::string folder = dir.path().filename().string();
            QVERIFY2(rank(layers, folder) >= 0, qPrintable(QString::fromStdString("ui/" + folder + " is not a layer")));
            for (const auto& entry : fs::directory_iterator(dir.path())) {
                std::ifstream in(entry.path());
                const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
                bad << uiLayerViolations(layers, folder, entry.path().string(), text, widgets);
                ++files;
            }
        }
        QVERIFY(files > 50);
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join('\n')));
    }

    // The ui check sees an upward include and a widget below the window layer.
    void detectsAUiLayerViolation() {
        const std::vector<std::string> layers = uiLayers();
        const std::set<std::string> widgets = widgetHeaders();
        QCOMPARE(uiLayerViolations(layers, "paint", "f", "#include \"ui/document/scene_document.hpp\"\n", widgets).size(), 1);
        QCOMPARE(uiLayerViolations(layers, "document", "f", "#include \"ui/window/main_window.hpp\"\n", widgets).size(), 1);
        QCOMPARE(uiLayerViolations(layers, "document", "f", "#include \"ui/paint/osg_scene.hpp\"\n", widgets).size(), 0);
        QCOMPARE(uiLayerViolations(layers, "paint", "f", "#include <QWidget>\n", widgets).size(), 1);
        QCOMPARE(uiLayerViolations(layers, "document", "f", "#include <QtCharts/QChartView>\n", widgets).size(), 1);
        QCOMPARE(uiLayerViolations(layers, "document", "f", "#include <QUndoStack>\n", widgets).size(), 0);  // Qt Gui
        QCOMPARE(uiLayerViolations(layers, "window", "f", "#include <QWidget>\n", widgets).size(), 0);
    }

    // How an item reads is decided from the quantity it is (core/symbolic/derivation.hpp),
    // never from its name: no presentation code compares an item's name.
    void presentationDecidesFromKinds() {
        const std::regex byName("\\bitem(\\.|->)name\\s*(==|!=|\\.rfind|\\.find|\\.starts_with|\\.substr|\\.size)");
        QVERIFY(std::regex_search("if (item.name.rfind(\"equation_\", 0) == 0)", byName));
        QVERIFY(std::regex_search("const bool single = item->name.size() == 1;", byName));
        QVERIFY(!std::regex_search("out.name = item.name;", byName));
        QStringList bad;
        for (const char* folder : {"core/present", "core/pipeline", "ui"}) bad << offending(folder, byName);
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join('\n')));
    }

    void coreIsPureCpp() {
        const QStringList bad = offending("core", std::regex(kCoreForbidden));
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join('\n')));
    }

    void uiDoesNotReachIntoApp() {
        const QStringList bad = offending("ui", std::regex(kUiForbidden));
        QVERIFY2(bad.isEmpty(), qPrintable(bad.join('\n')));
    }

    // The program takes nothing from tests/: KDL and the other oracles stay test code
    // (the KDL timings are tests/oracle/bench_kdl.cpp, a separate executable).
    void programTakesNothingFromTests() {
        const std::regex forbidden(kTestsForbidden);
        QVERIFY(std::regex_search("#include \"tests/oracle/kdl_chain.hpp\"", forbidden));
        QVERIFY(std::regex_search("#include <tests/oracle/kdl_chain.hpp>", forbidden));
        QVERIFY(!std::regex_search("#include \"core/io/tests.hpp\"", forbidden));
        QStringList bad;
        for (const char* folder : {"app", "ui", "core"}) bad << offending(folder, forbidden);
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

LL_TEST_APPLESS_MAIN(TestLayering)

}  // namespace test_layering
#include "test_layering.moc"
