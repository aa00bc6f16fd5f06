#include "core/io/window_view.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/io/atomic_file.hpp"
#include "core/io/json_file.hpp"
#include "core/io/lesson_file.hpp"
#include "core/model/usable_number.hpp"

namespace ll {

namespace {

using namespace scene_json;

const Keys kLanguages{"en", "da"};
const Keys kNotations{"notes", "spong", "craig", "siciliano"};
const Keys kDerivationTabs{"typeset", "text", "entries", "exercise"};
const Keys kPlotTabs{"energy", "joints", "teach", "torques", "properties", "work-precision", "dh-steps", "tracking"};
const Keys kTrackings{"error", "torque", "lyapunov", "rate"};
const Keys kDhModes{"rows", "axes"};
constexpr int kLastStep = 10;  // core/pipeline/pose_results.hpp's poseStepNumber (io is below pipeline)

// Reads one view, collecting every error with its field; unknown keys go to `kept`.
class ViewReader {
public:
    explicit ViewReader(std::string path) : root_(std::move(path)) {}

    WindowView read(const Json& value) {
        if (!value.is_object()) fail(root_, expectedGot(MessageId::WantedObject, value));
        const Json& v = value;
        keep(v, "", {"format", "name", "note", "scene", "language", "notation", "present", "size", "derivation", "pick", "playback",
                     "camera", "show", "plots", "dh", "teach"});
        if (const Json* f = member(v, "format"); f && !(f->is_string() && f->get<std::string>() == kViewFormat))
            error("format", expectedGot(alternatives({kViewFormat}), *f));
        text(v, "name", view_.name);
        text(v, "note", view_.note);
        if (const Json* scene = member(v, "scene")) {
            if (scene->is_string()) view_.scenePath = scene->get<std::string>();
            else if (scene->is_object()) view_.sceneEmbedded = *scene;
            else error("scene", expectedGot(MessageId::WantedSceneReference, *scene));
        }
        view_.language = choice(v, "language", kLanguages);
        view_.notation = choice(v, "notation", kNotations);
        view_.present = flag(v, "present");
        if (const Json* size = member(v, "size")) {
            const auto w = size->is_array() && size->size() == 2 ? wholeIn((*size)[0], 320, 7680) : std::nullopt;
            const auto h = size->is_array() && size->size() == 2 ? wholeIn((*size)[1], 320, 7680) : std::nullopt;
            if (w && h) view_.size = std::array<int, 2>{*w, *h};
            else error("size", expectedGot(MessageId::WantedPixelSize, *size));
        }
        if (const Json* d = section(v, "derivation", {"tab", "step", "scroll", "zoom", "through"})) {
            view_.derivation.tab = choice(*d, "derivation.tab", kDerivationTabs);
            view_.derivation.step = whole(*d, "derivation.step", 0, kLastStep);
            view_.derivation.scroll = number(*d, "derivation.scroll", 0, 1);
            view_.derivation.zoom = number(*d, "derivation.zoom", 0.25, 8);
            if (const Json* t = member(*d, "through")) {
                const auto a = t->is_array() && t->size() == 2 ? wholeIn((*t)[0], 0, kLastStep) : std::nullopt;
                const auto b = t->is_array() && t->size() == 2 ? wholeIn((*t)[1], 0, kLastStep) : std::nullopt;
                if (a && b && *a <= *b) view_.derivation.through = std::array<int, 2>{*a, *b};
                else error("derivation.through", expectedGot(MessageId::WantedOrderedPair, *t));
            }
        }
        if (const Json* p = section(v, "pick", {"entry", "link"})) {
            if (const Json* e = member(*p, "entry")) {
                if (e->is_string() && !e->get<std::string>().empty()) view_.pick.entry = e->get<std::string>();
                else error("pick.entry", expectedGot(MessageId::WantedName, *e));
            }
            view_.pick.link = whole(*p, "pick.link", 1, 1000);
        }
        if (const Json* p = section(v, "playback", {"time", "playing", "speed", "loop", "play"})) {
            view_.playback.time = number(*p, "playback.time", 0, 1e6);
            view_.playback.playing = flag(*p, "playback.playing");
            view_.playback.speed = number(*p, "playback.speed", 0.1, 10);
            view_.playback.loop = flag(*p, "playback.loop");
            if (const Json* t = member(*p, "play")) {
                const auto a = t->is_array() && t->size() == 2 ? numberIn((*t)[0], 0, 1e6) : std::nullopt;
                const auto b = t->is_array() && t->size() == 2 ? numberIn((*t)[1], 0, 1e6) : std::nullopt;
                if (a && b && *a <= *b) view_.playback.play = std::array<double, 2>{*a, *b};
                else error("playback.play", expectedGot(MessageId::WantedOrderedPair, *t));
            }
        }
        if (const Json* c = section(v, "camera", {"eye", "target", "up", "fov"})) {
            WindowView::Camera camera;
            const bool eye = vector3(*c, "camera.eye", camera.eye), target = vector3(*c, "camera.target", camera.target);
            const bool up = vector3(*c, "camera.up", camera.up);
            if (const auto fov = number(*c, "camera.fov", 1, 170)) camera.fov = *fov;
            for (const char* key : {"eye", "target"})
                if (!member(*c, key)) error(std::string("camera.") + key, message(MessageId::RequiredFieldMissing, "m"));
            if (up && camera.up.norm() < 1e-9) error("camera.up", message(MessageId::MustBeFiniteDirection));
            if (eye && target && (camera.eye - camera.target).norm() < 1e-9)
                error("camera.eye", message(MessageId::MustBeFiniteDirection));
            view_.camera = camera;
        }
        if (const Json* s = section(v, "show", {"frames", "labels", "coms", "trail", "look"})) {
            view_.show.frames = flag(*s, "show.frames");
            view_.show.labels = flag(*s, "show.labels");
            view_.show.coms = flag(*s, "show.coms");
            view_.show.trail = flag(*s, "show.trail");
            view_.show.look = flag(*s, "show.look");
        }
        if (const Json* p = section(v, "plots", {"tab", "joint", "tracking"})) {
            view_.plots.tab = choice(*p, "plots.tab", kPlotTabs);
            view_.plots.joint = whole(*p, "plots.joint", 1, 1000);
            view_.plots.tracking = choice(*p, "plots.tracking", kTrackings);
        }
        if (const Json* d = section(v, "dh", {"mode", "joint", "frame", "done", "dimensions"})) {
            WindowView::DhSteps dh;
            if (const auto mode = choice(*d, "dh.mode", kDhModes)) dh.mode = *mode;
            const bool rows = dh.mode == "rows";
            if (const auto i = whole(*d, rows ? "dh.joint" : "dh.frame", rows ? 1 : 0, 1000)) dh.index = *i;
            if (const auto k = whole(*d, "dh.done", 0, 4)) dh.done = *k;
            if (const auto on = flag(*d, "dh.dimensions")) dh.dimensions = *on;
            view_.dh = dh;
        }
        if (const Json* q = member(v, "teach")) {
            std::vector<double> pose;
            for (std::size_t i = 0; q->is_array() && i < q->size(); ++i)
                if (const auto x = numberIn((*q)[i], -1e6, 1e6)) pose.push_back(*x);
            if (q->is_array() && !q->empty() && pose.size() == q->size()) view_.teach = pose;
            else error("teach", expectedGot(MessageId::WantedNumberArray, *q));
        }
        if (!errors_.empty()) throw InputError(errors_);
        return view_;
    }

private:
    std::string field(const std::string& path) const { return root_.empty() ? path : path.empty() ? root_ : root_ + "." + path; }
    void error(const std::string& path, Message m) { errors_.push_back({Severity::Error, field(path), std::move(m)}); }
    [[noreturn]] void fail(const std::string& path, Message m) {
        error(path, std::move(m));
        throw InputError(errors_);
    }

    static const Json* member(const Json& object, const std::string& path) {
        const std::string key = path.substr(path.rfind('.') == std::string::npos ? 0 : path.rfind('.') + 1);
        const auto found = object.find(key);
        return found == object.end() ? nullptr : &*found;
    }

    // The keys of `object` at `path` not in `known`, kept for the writer.
    void keep(const Json& object, const std::string& path, const Keys& known) {
        for (const auto& [key, value] : object.items())
            if (std::find(known.begin(), known.end(), key) == known.end()) {
                if (path.empty()) view_.kept[key] = value;
                else view_.kept[path][key] = value;
            }
    }

    const Json* section(const Json& v, const std::string& key, const Keys& known) {
        const Json* s = member(v, key);
        if (!s) return nullptr;
        if (!s->is_object()) {
            error(key, expectedGot(MessageId::WantedObject, *s));
            return nullptr;
        }
        keep(*s, key, known);
        return s;
    }

    void text(const Json& v, const std::string& key, std::string& out) {
        if (const Json* t = member(v, key)) {
            if (t->is_string()) out = t->get<std::string>();
            else error(key, expectedGot(MessageId::WantedString, *t));
        }
    }

    std::optional<std::string> choice(const Json& v, const std::string& path, const Keys& choices) {
        const Json* c = member(v, path);
        if (!c) return std::nullopt;
        if (c->is_string() && std::find(choices.begin(), choices.end(), c->get<std::string>()) != choices.end()) return c->get<std::string>();
        error(path, expectedGot(alternatives(choices), *c));
        return std::nullopt;
    }

    std::optional<bool> flag(const Json& v, const std::string& path) {
        const Json* b = member(v, path);
        if (!b) return std::nullopt;
        if (b->is_boolean()) return b->get<bool>();
        error(path, expectedGot(MessageId::WantedBoolean, *b));
        return std::nullopt;
    }

    static std::optional<int> wholeIn(const Json& value, int low, int high) {
        if (!value.is_number_integer()) return std::nullopt;
        const long long k = value.get<long long>();
        if (k < low || k > high) return std::nullopt;
        return static_cast<int>(k);
    }

    static std::optional<double> numberIn(const Json& value, double low, double high) {
        if (!value.is_number()) return std::nullopt;
        const double x = value.get<double>();
        if (unusableNumber(x) || x < low || x > high) return std::nullopt;
        return x;
    }

    std::optional<int> whole(const Json& v, const std::string& path, int low, int high) {
        const Json* w = member(v, path);
        if (!w) return std::nullopt;
        if (const auto k = wholeIn(*w, low, high)) return k;
        error(path, high >= 1000 ? expectedGot(message(MessageId::WantedWholeNumberFrom, low), *w)
                                 : expectedGot(message(MessageId::WantedWholeNumberFromTo, low, high), *w));
        return std::nullopt;
    }

    std::optional<double> number(const Json& v, const std::string& path, double low, double high) {
        const Json* x = member(v, path);
        if (!x) return std::nullopt;
        if (const auto y = numberIn(*x, low, high)) return y;
        error(path, expectedGot(message(MessageId::WantedNumberFromTo, low, high), *x));
        return std::nullopt;
    }

    bool vector3(const Json& v, const std::string& path, Eigen::Vector3d& out) {
        const Json* x = member(v, path);
        if (!x) return false;
        Eigen::Vector3d read;
        bool ok = x->is_array() && x->size() == 3;
        for (std::size_t i = 0; ok && i < 3; ++i)
            if (const auto y = numberIn((*x)[i], -1e6, 1e6)) read[static_cast<int>(i)] = *y;
            else ok = false;
        if (ok) out = read;
        else error(path, expectedGot(MessageId::WantedVector3, *x));
        return ok;
    }

    std::string root_;
    WindowView view_;
    std::vector<Diagnostic> errors_;
};

Json array3(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

template <class T>
void put(Json& object, const char* key, const std::optional<T>& value) {
    if (value) object[key] = *value;
}

// `kept` merged into `out`: a key out already has stays (the known field wins).
void merge(Json& out, const Json& kept) {
    for (const auto& [key, value] : kept.items()) {
        if (!out.contains(key)) out[key] = value;
        else if (out[key].is_object() && value.is_object()) merge(out[key], value);
    }
}

void collectPaths(const Json& kept, const std::string& prefix, std::vector<std::string>& paths, bool top) {
    for (const auto& [key, value] : kept.items()) {
        // At the top, an object under a known section's name holds that section's kept keys.
        static const Keys sections{"derivation", "pick", "playback", "camera", "show", "plots", "dh"};
        if (top && value.is_object() && std::find(sections.begin(), sections.end(), key) != sections.end())
            collectPaths(value, key + ".", paths, false);
        else paths.push_back(prefix + key);
    }
}

}  // namespace

std::vector<std::string> WindowView::keptPaths() const {
    std::vector<std::string> paths;
    collectPaths(kept, "", paths, true);
    return paths;
}

WindowView readWindowView(const Json& value, const std::string& path) { return ViewReader(path).read(value); }

Json windowViewJson(const WindowView& view, bool withFormat) {
    Json out = Json::object();
    if (withFormat) out["format"] = kViewFormat;
    if (!view.name.empty()) out["name"] = view.name;
    if (!view.note.empty()) out["note"] = view.note;
    if (view.sceneEmbedded) out["scene"] = *view.sceneEmbedded;
    else if (!view.scenePath.empty()) out["scene"] = view.scenePath;
    put(out, "language", view.language);
    put(out, "notation", view.notation);
    put(out, "present", view.present);
    if (view.size) out["size"] = Json::array({(*view.size)[0], (*view.size)[1]});
    Json d = Json::object();
    put(d, "tab", view.derivation.tab);
    put(d, "step", view.derivation.step);
    put(d, "scroll", view.derivation.scroll);
    put(d, "zoom", view.derivation.zoom);
    if (view.derivation.through) d["through"] = Json::array({(*view.derivation.through)[0], (*view.derivation.through)[1]});
    if (!d.empty()) out["derivation"] = d;
    Json pick = Json::object();
    put(pick, "entry", view.pick.entry);
    put(pick, "link", view.pick.link);
    if (!pick.empty()) out["pick"] = pick;
    Json p = Json::object();
    put(p, "time", view.playback.time);
    put(p, "playing", view.playback.playing);
    put(p, "speed", view.playback.speed);
    put(p, "loop", view.playback.loop);
    if (view.playback.play) p["play"] = Json::array({(*view.playback.play)[0], (*view.playback.play)[1]});
    if (!p.empty()) out["playback"] = p;
    if (view.camera)
        out["camera"] = Json{{"eye", array3(view.camera->eye)}, {"target", array3(view.camera->target)}, {"up", array3(view.camera->up)},
                             {"fov", view.camera->fov}};
    Json show = Json::object();
    put(show, "frames", view.show.frames);
    put(show, "labels", view.show.labels);
    put(show, "coms", view.show.coms);
    put(show, "trail", view.show.trail);
    put(show, "look", view.show.look);
    if (!show.empty()) out["show"] = show;
    Json plots = Json::object();
    put(plots, "tab", view.plots.tab);
    put(plots, "joint", view.plots.joint);
    put(plots, "tracking", view.plots.tracking);
    if (!plots.empty()) out["plots"] = plots;
    if (view.dh) {
        const bool rows = view.dh->mode == "rows";
        Json dh{{"mode", view.dh->mode}, {rows ? "joint" : "frame", view.dh->index}, {"done", view.dh->done}};
        if (rows && view.dh->dimensions) dh["dimensions"] = true;
        out["dh"] = dh;
    }
    if (view.teach) out["teach"] = *view.teach;
    // A camera or dh the view no longer has: its kept fields alone would not read again
    // (a camera needs its eye and target) or would bring back a default one.
    Json kept = view.kept;
    if (!view.camera) kept.erase("camera");
    if (!view.dh) kept.erase("dh");
    merge(out, kept);
    return out;
}

std::string serializeWindowView(const WindowView& view) {
    std::string text;
    writePretty(text, windowViewJson(view), 0);
    return text + "\n";
}

std::string relativePath(const std::string& path, const std::string& folder) {
    namespace fs = std::filesystem;
    const fs::path absolute = fs::absolute(path).lexically_normal();
    const fs::path base = fs::absolute(folder.empty() ? "." : folder).lexically_normal();
    // Sharing nothing but the root ("/usr/share/…" seen from "/home/…"): absolute.
    const auto second = [](const fs::path& p) { return std::next(p.begin()) == p.end() ? fs::path() : *std::next(p.begin()); };
    if (second(absolute) != second(base)) return absolute.string();
    const fs::path relative = absolute.lexically_relative(base);
    return relative.empty() ? absolute.string() : relative.string();
}

std::string resolvedPath(const std::string& path, const std::string& folder) {
    namespace fs = std::filesystem;
    if (path.empty() || fs::path(path).is_absolute() || path.rfind(":/", 0) == 0) return path;
    return relativePath((fs::path(folder.empty() ? "." : folder) / path).string(), ".");
}

WindowView loadWindowView(const std::string& spec) {
    // PATH#NAME; a file whose own name holds '#' ("Lecture #2.lesson") is that file.
    const auto hash = std::filesystem::exists(spec) ? std::string::npos : spec.rfind('#');
    const std::string path = hash == std::string::npos ? spec : spec.substr(0, hash);
    const std::string name = hash == std::string::npos ? std::string() : spec.substr(hash + 1);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    const Json root = readJsonFile(path);
    const Json* format = root.contains("format") ? &root["format"] : nullptr;
    const std::string kind = format && format->is_string() ? format->get<std::string>() : std::string();
    WindowView view;
    try {
        if (kind == kLessonFormat) {
            view = viewOfLesson(loadLesson(path), name, path);
            return view;  // a lesson's views have their scene paths made relative to here already
        } else if (kind == kFormat) {  // a scene: its named view, or the scene as it opens
            if (name.empty()) {
                view.scenePath = path;
                return view;
            }
            const Json* views = root.contains("views") ? &root["views"] : nullptr;
            if (!views || !views->is_object() || views->empty()) throw InputError(path, message(MessageId::HoldsNoViews, path));
            if (!views->contains(name)) {
                Keys names;
                for (const auto& [key, value] : views->items()) names.push_back(key);
                throw InputError(path, message(MessageId::NoSuchView, path, name, joined(names)));
            }
            view = readWindowView((*views)[name], "views." + name);
            if (view.name.empty()) view.name = name;
            if (view.scenePath.empty() && !view.sceneEmbedded) view.scenePath = path;
            else view.scenePath = resolvedPath(view.scenePath, folder);
            return view;
        }
        view = readWindowView(root);
    } catch (const InputError& e) {
        std::vector<Diagnostic> named = e.diagnostics();
        for (Diagnostic& d : named)
            if (d.field.rfind(path, 0) != 0) d.field = path + ": " + d.field;
        throw InputError(named);
    }
    view.scenePath = resolvedPath(view.scenePath, folder);
    return view;
}

void saveWindowView(const WindowView& view, const std::string& path) {
    WindowView written = view;
    if (!written.scenePath.empty() && written.scenePath.rfind(":/", 0) != 0)
        written.scenePath = relativePath(written.scenePath, std::filesystem::path(path).parent_path().string());
    saveFileAtomically(path, serializeWindowView(written), Backup::None);
}

}  // namespace ll
