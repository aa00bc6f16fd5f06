// Views and lessons (core/io/window_view, core/io/lesson_file): every field of a view
// survives its JSON and its file text; fields of a newer version are kept and written back;
// a bad field is named with its value (and the prefix it is read under); a view file's
// scene path is written relative to the file and read back relative to here; a scene's
// "views" are checked by loadScene and opened as scene.json#NAME; a lesson opens its
// inline, included, missing and broken views without throwing, saves the broken ones as
// they were, embeds the scenes when asked, and refuses to include itself; paths resolve.
#include "test_registry.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/io/json_file.hpp"
#include "core/io/lesson_file.hpp"
#include "core/io/scene_file.hpp"
#include "core/io/scene_json.hpp"
#include "core/io/window_view.hpp"
#include "core/model/diagnostics.hpp"

namespace test_window_view {

using namespace ll;
namespace fs = std::filesystem;
using Json = scene_json::Json;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The InputError's diagnostics; empty when the call did not throw one.
template <class Call>
std::vector<Diagnostic> errorsOf(Call call) {
    try {
        call();
    } catch (const InputError& e) {
        return e.diagnostics();
    }
    return {};
}

// Every diagnostic's field and English words, one a line.
std::string text(const std::vector<Diagnostic>& diagnostics) {
    std::string all;
    for (const Diagnostic& d : diagnostics) all += d.field + ": " + d.message.english() + "\n";
    return all;
}

void writeFile(const std::string& path, const std::string& content) {
    std::ofstream out(path, std::ios::binary);
    out << content;
}

std::string readFile(const std::string& path) { return readWholeFile(path).value_or(""); }

Json parseText(const std::string& text) {
    std::vector<Diagnostic> duplicates;
    return scene_json::parseJson(text, duplicates);
}

// A view with every field set, none to its default.
WindowView fullView() {
    WindowView v;
    v.name = "intro";
    v.note = "Look at b11 first";
    v.scenePath = "planar_2r.json";
    v.language = "da";
    v.notation = "spong";
    v.present = true;
    v.size = std::array<int, 2>{1600, 900};
    v.derivation = {"entries", 7, 0.35, 1.75, std::array<int, 2>{3, 8}};
    v.pick.entry = "b11";
    v.playback = {2.5, true, 0.5, false, std::array<double, 2>{1.0, 4.25}};
    v.camera = WindowView::Camera{{3.0, -2.0, 1.5}, {0.1, 0.2, 0.3}, {0.0, 1.0, 0.0}, 45.0};
    v.show = {false, true, true, false, true};
    v.plots = {"tracking", 2, "lyapunov"};
    v.dh = WindowView::DhSteps{"rows", 2, 3, true};
    v.teach = std::vector<double>{0.5, -1.25};
    return v;
}

#define LL_SAME(field) QVERIFY2(a.field == b.field, #field)

// Compares every field (nothing once the test has failed: one failure is reported, not a cascade).
void expectSame(const WindowView& a, const WindowView& b) {
    if (QTest::currentTestFailed()) return;
    LL_SAME(name);
    LL_SAME(note);
    LL_SAME(scenePath);
    LL_SAME(sceneEmbedded);
    LL_SAME(language);
    LL_SAME(notation);
    LL_SAME(present);
    LL_SAME(size);
    LL_SAME(derivation.tab);
    LL_SAME(derivation.step);
    LL_SAME(derivation.scroll);
    LL_SAME(derivation.zoom);
    LL_SAME(derivation.through);
    LL_SAME(pick.entry);
    LL_SAME(pick.link);
    LL_SAME(playback.time);
    LL_SAME(playback.playing);
    LL_SAME(playback.speed);
    LL_SAME(playback.loop);
    LL_SAME(playback.play);
    QCOMPARE(a.camera.has_value(), b.camera.has_value());
    if (a.camera) {
        LL_SAME(camera->eye);
        LL_SAME(camera->target);
        LL_SAME(camera->up);
        LL_SAME(camera->fov);
    }
    LL_SAME(show.frames);
    LL_SAME(show.labels);
    LL_SAME(show.coms);
    LL_SAME(show.trail);
    LL_SAME(show.look);
    LL_SAME(plots.tab);
    LL_SAME(plots.joint);
    LL_SAME(plots.tracking);
    QCOMPARE(a.dh.has_value(), b.dh.has_value());
    if (a.dh) {
        LL_SAME(dh->mode);
        LL_SAME(dh->index);
        LL_SAME(dh->done);
        LL_SAME(dh->dimensions);
    }
    LL_SAME(teach);
    LL_SAME(kept);
}

// `original` through its JSON and through its file text.
void expectRoundTrip(const WindowView& original) {
    expectSame(readWindowView(windowViewJson(original)), original);
    if (QTest::currentTestFailed()) return;
    expectSame(readWindowView(parseText(serializeWindowView(original))), original);
}

// The example planar_2r.json copied into `dir`; its path.
std::string copyExample(const QTemporaryDir& dir) {
    const std::string copy = dir.path().toStdString() + "/planar_2r.json";
    fs::copy_file(std::string(LL_EXAMPLES_DIR) + "/planar_2r.json", copy, fs::copy_options::overwrite_existing);
    return copy;
}

}  // namespace

class TestWindowView : public QObject {
    Q_OBJECT

private slots:
    void everyFieldRoundTrips() {
        expectRoundTrip(fullView());
        WindowView axes = fullView();
        axes.dh = WindowView::DhSteps{"axes", 3, 2, false};
        expectRoundTrip(axes);
        WindowView link;  // a picked link instead of an entry
        link.pick.link = 2;
        expectRoundTrip(link);
        expectRoundTrip(WindowView{});
        // The field names of the format, as documented.
        const Json json = windowViewJson(fullView());
        QCOMPARE(json["format"], Json(kViewFormat));
        QCOMPARE(json["derivation"]["through"], Json::parse("[3, 8]"));
        QCOMPARE(json["dh"], Json::parse(R"({"mode": "rows", "joint": 2, "done": 3, "dimensions": true})"));
        QCOMPARE(windowViewJson(axes)["dh"], Json::parse(R"({"mode": "axes", "frame": 3, "done": 2})"));
        QVERIFY(!windowViewJson(fullView(), false).contains("format"));
    }

    void unknownFieldsAreKept() {
        const Json json = Json::parse(R"({"format": "lagrangelab-view/1", "future": {"effects": [1, 2]},
            "camera": {"eye": [1, 2, 3], "target": [0, 0, 0], "roll": 3}, "derivation": {"step": 2, "highlight": true}})");
        WindowView view;
        const auto errors = errorsOf([&] { view = readWindowView(json); });
        QVERIFY2(errors.empty(), text(errors).c_str());
        std::vector<std::string> paths = view.keptPaths();
        std::sort(paths.begin(), paths.end());
        QCOMPARE(paths, (std::vector<std::string>{"camera.roll", "derivation.highlight", "future"}));
        const Json written = windowViewJson(view);
        QCOMPARE(written["future"], Json::parse(R"({"effects": [1, 2]})"));
        QCOMPARE(written["camera"]["roll"], Json(3));
        QCOMPARE(written["camera"]["eye"], Json::parse("[1.0, 2.0, 3.0]"));
        QCOMPARE(written["derivation"]["highlight"], Json(true));
        QCOMPARE(written["derivation"]["step"], Json(2));
        expectSame(readWindowView(parseText(serializeWindowView(view))), view);
        // A section the view no longer has is not brought back by its kept fields: what
        // is written always reads again, and as the view was.
        const Json axes = Json::parse(R"({"camera": {"eye": [1, 2, 3], "target": [0, 0, 0], "roll": 3},
                                          "dh": {"mode": "axes", "frame": 1, "spin": 2}})");
        WindowView dropped = readWindowView(axes);
        dropped.camera.reset();
        dropped.dh.reset();
        WindowView again;
        const auto rereadErrors = errorsOf([&] { again = readWindowView(windowViewJson(dropped)); });
        QVERIFY2(rereadErrors.empty(), text(rereadErrors).c_str());
        QVERIFY(!again.camera);
        QVERIFY(!again.dh);
    }

    void badInputNamesFieldAndValue() {
        struct Case {
            const char* json;
            const char* field;
            const char* value;
        };
        const Case cases[] = {
            {R"({"derivation": {"step": 11}})", "derivation.step", "11"},
            {R"({"playback": {"time": -1}})", "playback.time", "-1"},
            {R"({"camera": {"eye": [0, 0], "target": [0, 0, 0]}})", "camera.eye", "[0,0]"},
            {R"({"language": "fr"})", "language", "fr"},
            {R"({"size": [10, 10]})", "size", "[10,10]"},
            {R"({"teach": ["a"]})", "teach", "[\"a\"]"},
            {R"({"format": "lagrangelab-view/9"})", "format", "lagrangelab-view/9"},
            {R"({"derivation": {"through": [5, 2]}})", "derivation.through", "[5,2]"},
            {R"({"dh": {"mode": "axes", "frame": 1, "done": 5}})", "dh.done", "5"},
            {R"({"camera": {"eye": [1, 1, 1], "target": [1, 1, 1]}})", "camera.eye", ""},
        };
        for (const Case& c : cases) {
            const auto errors = errorsOf([&] { readWindowView(Json::parse(c.json)); });
            const std::string what = std::string(c.json) + " gave\n" + text(errors);
            QVERIFY2(errors.size() == 1, what.c_str());
            QCOMPARE(errors[0].field, std::string(c.field));
            QVERIFY2(contains(errors[0].message.english(), c.value), what.c_str());
        }
        // Every error at once, each under the prefix it is read at.
        const auto errors = errorsOf([] { readWindowView(Json::parse(R"({"derivation": {"step": 11}, "language": "fr"})"), "views.intro"); });
        QCOMPARE(errors.size(), std::size_t(2));
        std::vector<std::string> fields{errors[0].field, errors[1].field};
        std::sort(fields.begin(), fields.end());
        QCOMPARE(fields, (std::vector<std::string>{"views.intro.derivation.step", "views.intro.language"}));
        QVERIFY(!errorsOf([] { readWindowView(Json::parse("[1]")); }).empty());
    }

    void viewFileHasItsScenePathRelative() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string folder = dir.path().toStdString();
        const std::string scene = copyExample(dir);
        WindowView view = fullView();
        view.scenePath = scene;
        const std::string file = folder + "/view.json";
        saveWindowView(view, file);
        const std::string written = readFile(file);
        QCOMPARE(parseText(written)["scene"], Json("planar_2r.json"));
        QVERIFY2(!contains(written, folder), written.c_str());
        const WindowView loaded = loadWindowView(file);
        QVERIFY2(fs::equivalent(loaded.scenePath, scene), loaded.scenePath.c_str());
        view.scenePath = loaded.scenePath;
        expectSame(loaded, view);
        // In a folder below the scene's.
        fs::create_directory(folder + "/views");
        saveWindowView(view, folder + "/views/v.json");
        QCOMPARE(parseText(readFile(folder + "/views/v.json"))["scene"], Json("../planar_2r.json"));
        QVERIFY(fs::equivalent(loadWindowView(folder + "/views/v.json").scenePath, scene));
        // A scene without a name is the view of the scene as it opens.
        const WindowView plain = loadWindowView(scene);
        QCOMPARE(plain.scenePath, scene);
        QVERIFY(!plain.camera && !plain.derivation.step);
    }

    void sceneViews() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        Json json = readJsonFile(std::string(LL_EXAMPLES_DIR) + "/planar_2r.json");
        json["views"] = Json::parse(R"({"intro": {"note": "the mass matrix", "derivation": {"step": 4}, "plots": {"tab": "energy"}}})");
        const std::string file = dir.path().toStdString() + "/scene.json";
        writeFile(file, json.dump(2));
        auto errors = errorsOf([&] { loadScene(file); });
        QVERIFY2(errors.empty(), text(errors).c_str());

        const WindowView intro = loadWindowView(file + "#intro");
        QCOMPARE(intro.name, std::string("intro"));
        QCOMPARE(intro.note, std::string("the mass matrix"));
        QCOMPARE(intro.derivation.step, std::optional<int>(4));
        QCOMPARE(intro.plots.tab, std::optional<std::string>("energy"));
        QVERIFY2(fs::equivalent(intro.scenePath, file), intro.scenePath.c_str());

        errors = errorsOf([&] { loadWindowView(file + "#nope"); });
        QVERIFY(!errors.empty());
        QVERIFY2(contains(text(errors), "nope") && contains(text(errors), "intro"), text(errors).c_str());

        json["views"]["intro"]["derivation"]["step"] = 99;
        writeFile(file, json.dump(2));
        // A broken view does not stop its scene from opening: a warning names it.
        const LoadedScene loaded = loadScene(file);
        const auto warning = std::find_if(loaded.warnings.begin(), loaded.warnings.end(),
                                          [](const Diagnostic& d) { return contains(d.field, "views.intro.derivation.step"); });
        QVERIFY2(warning != loaded.warnings.end() && contains(warning->message.english(), "99"), text(loaded.warnings).c_str());
        errors = errorsOf([&] { loadWindowView(file + "#intro"); });
        QVERIFY2(!errors.empty() && contains(errors[0].field, "views.intro.derivation.step"), text(errors).c_str());
    }

    void lessons() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string folder = dir.path().toStdString();
        const std::string scene = copyExample(dir);
        WindowView saved = fullView();
        saved.name = "saved";
        saved.note = "its own note";
        saved.scenePath = scene;
        saveWindowView(saved, folder + "/v.json");
        const Json missing = Json::parse(R"({"include": "missing.json"})");
        const Json broken = Json::parse(R"({"derivation": {"step": 42}})");
        Json root = Json::parse(R"({"format": "lagrangelab-lesson/1", "title": "T", "views": [
            {"name": "first", "scene": "planar_2r.json", "derivation": {"step": 2}},
            {"include": "v.json", "note": "N"}], "extra": 1})");
        root["views"].push_back(missing);
        root["views"].push_back(broken);
        const std::string path = folder + "/lesson.json";
        writeFile(path, root.dump(2));

        Lesson lesson;
        auto errors = errorsOf([&] { lesson = loadLesson(path); });
        QVERIFY2(errors.empty(), text(errors).c_str());
        QCOMPARE(lesson.title, std::string("T"));
        QCOMPARE(lesson.views.size(), std::size_t(4));
        QVERIFY2(lesson.views[0].problems.empty(), text(lesson.views[0].problems).c_str());
        QVERIFY2(lesson.views[1].problems.empty(), text(lesson.views[1].problems).c_str());
        QCOMPARE(lesson.views[0].view.derivation.step, std::optional<int>(2));
        QVERIFY(fs::equivalent(lesson.views[0].view.scenePath, scene));
        // The included view's fields, its note overridden.
        WindowView included = saved;
        included.note = "N";
        included.scenePath = lesson.views[1].view.scenePath;
        QVERIFY(fs::equivalent(included.scenePath, scene));
        expectSame(lesson.views[1].view, included);
        QCOMPARE(lesson.views[1].include, std::string("v.json"));
        QVERIFY(!lesson.views[2].problems.empty());
        QVERIFY2(contains(text(lesson.views[2].problems), "missing.json"), text(lesson.views[2].problems).c_str());
        QVERIFY(!lesson.views[3].problems.empty());
        QVERIFY2(contains(text(lesson.views[3].problems), "derivation.step"), text(lesson.views[3].problems).c_str());

        QCOMPARE(viewOfLesson(lesson, "first", path).derivation.step, std::optional<int>(2));
        QCOMPARE(viewOfLesson(lesson, "2", path).note, std::string("N"));
        QCOMPARE(viewOfLesson(lesson, "saved", path).note, std::string("N"));
        QVERIFY(!errorsOf([&] { viewOfLesson(lesson, "9", path); }).empty());
        QVERIFY(!errorsOf([&] { viewOfLesson(lesson, "4", path); }).empty());  // broken: its problem
        // No name: the first view, also where later views have no name.
        errors = errorsOf([&] { QCOMPARE(loadWindowView(path).name, std::string("first")); });
        QVERIFY2(errors.empty(), text(errors).c_str());
        QCOMPARE(loadWindowView(path + "#2").note, std::string("N"));

        // Saved and opened again: the broken views as written, the include as written.
        const std::string copy = folder + "/again.json";
        saveLesson(lesson, copy);
        const Json savedJson = readJsonFile(copy);
        QCOMPARE(savedJson["views"][1]["include"], Json("v.json"));
        QCOMPARE(savedJson["views"][1]["note"], Json("N"));
        QCOMPARE(savedJson["views"][2], missing);
        QCOMPARE(savedJson["views"][3], broken);
        QCOMPARE(savedJson["extra"], Json(1));
        QCOMPARE(savedJson["views"][0]["scene"], Json("planar_2r.json"));
        const Lesson again = loadLesson(copy);
        QCOMPARE(again.views.size(), std::size_t(4));
        QCOMPARE(again.title, std::string("T"));
        QCOMPARE(again.views[1].include, std::string("v.json"));
        QCOMPARE(again.views[2].written, missing);
        QCOMPARE(again.views[3].written, broken);
        QVERIFY(!again.views[2].problems.empty() && !again.views[3].problems.empty());
        QCOMPARE(again.kept["extra"], Json(1));
        expectSame(again.views[1].view, lesson.views[1].view);

        // Saved into another folder: the includes (and a broken view's) point at the same files.
        std::filesystem::create_directory(folder + "/sub");
        saveLesson(lesson, folder + "/sub/moved.json");
        const Lesson moved = loadLesson(folder + "/sub/moved.json");
        QCOMPARE(moved.views[1].include, std::string("../v.json"));
        QVERIFY(moved.views[1].problems.empty());
        expectSame(moved.views[1].view, lesson.views[1].view);
        QCOMPARE(moved.views[2].written["include"], Json("../missing.json"));
        QVERIFY(std::filesystem::equivalent(moved.views[0].view.scenePath, lesson.views[0].view.scenePath));

        // Embedded: every good view holds its scene, and opens with it.
        const std::string embedded = folder + "/embedded.json";
        saveLesson(lesson, embedded, true);
        const Json embeddedJson = readJsonFile(embedded);
        QCOMPARE(embeddedJson["views"].size(), std::size_t(4));
        for (int i : {0, 1}) {
            const Json& s = embeddedJson["views"][static_cast<std::size_t>(i)]["scene"];
            QVERIFY2(s.is_object() && s.value("format", "") == std::string(scene_json::kFormat), s.dump().c_str());
        }
        QCOMPARE(embeddedJson["views"][2], missing);
        const Lesson opened = loadLesson(embedded);
        QCOMPARE(opened.views.size(), std::size_t(4));
        for (int i : {0, 1}) {
            QVERIFY2(opened.views[static_cast<std::size_t>(i)].problems.empty(), text(opened.views[static_cast<std::size_t>(i)].problems).c_str());
            QVERIFY(opened.views[static_cast<std::size_t>(i)].view.sceneEmbedded.has_value());
        }
        QCOMPARE(opened.views[1].view.note, std::string("N"));
    }

    void lessonIncludingItself() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        copyExample(dir);
        const std::string path = dir.path().toStdString() + "/lesson.json";
        Json root = Json::parse(R"({"format": "lagrangelab-lesson/1", "views": [{"name": "a", "scene": "planar_2r.json"}]})");
        root["views"].push_back(Json{{"include", std::string("lesson.json") + '#' + "1"}});  // moc misreads '#' in a raw string
        writeFile(path, root.dump());
        Lesson lesson;
        const auto errors = errorsOf([&] { lesson = loadLesson(path); });
        QVERIFY2(errors.empty(), text(errors).c_str());
        QCOMPARE(lesson.views.size(), std::size_t(2));
        QVERIFY(lesson.views[0].problems.empty());
        QVERIFY(!lesson.views[1].problems.empty());
        QVERIFY2(contains(text(lesson.views[1].problems), "itself"), text(lesson.views[1].problems).c_str());
        // Not a lesson at all: the file is named.
        writeFile(path, R"({"format": "lagrangelab-view/1"})");
        const auto notLesson = errorsOf([&] { loadLesson(path); });
        QVERIFY2(!notLesson.empty() && contains(notLesson[0].field, path), text(notLesson).c_str());
    }

    void paths() {
        QCOMPARE(resolvedPath("a.json", "dir"), std::string("dir/a.json"));
        QCOMPARE(resolvedPath("/x/y/a.json", "dir"), std::string("/x/y/a.json"));
        QCOMPARE(resolvedPath("", "dir"), std::string());
        QCOMPARE(relativePath("/usr/share/x.json", "/home/u"), std::string("/usr/share/x.json"));
        QCOMPARE(relativePath("/home/u/a/b.json", "/home/u"), std::string("a/b.json"));
        QCOMPARE(relativePath("/home/u/b.json", "/home/u/c"), std::string("../b.json"));
    }
};

LL_TEST_APPLESS_MAIN(TestWindowView)

}  // namespace test_window_view
#include "test_window_view.moc"
