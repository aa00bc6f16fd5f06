#include "core/io/lesson_file.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "core/io/atomic_file.hpp"
#include "core/io/json_file.hpp"

namespace ll {

namespace {

using namespace scene_json;
namespace fs = std::filesystem;

// The diagnostics with their field prefixed by `file` (once).
std::vector<Diagnostic> prefixedByFile(std::vector<Diagnostic> diagnostics, const std::string& file) {
    for (Diagnostic& d : diagnostics)
        if (d.field.rfind(file, 0) != 0) d.field = file + (d.field.empty() || d.field == kDocument ? "" : ": " + d.field);
    return diagnostics;
}

// The lessons being opened, so an include of itself is refused instead of recursing.
thread_local std::set<std::string> opening;

}  // namespace

Lesson loadLesson(const std::string& path) {
    const std::string canonical = fs::weakly_canonical(fs::absolute(path)).string();
    if (opening.count(canonical)) throw InputError(path, message(MessageId::IncludesItself, path));
    opening.insert(canonical);
    struct Leave {
        std::string key;
        ~Leave() { opening.erase(key); }
    } leave{canonical};

    const Json root = readJsonFile(path);
    const std::string folder = fs::path(path).parent_path().string();
    const Json* format = root.contains("format") ? &root["format"] : nullptr;
    if (!format || !format->is_string() || format->get<std::string>() != kLessonFormat)
        throw InputError(path + ": format", format ? expectedGot(alternatives({kLessonFormat}), *format)
                                                   : message(MessageId::RequiredFieldMissing, alternatives({kLessonFormat})));
    Lesson lesson;
    lesson.folder = folder;
    for (const auto& [key, value] : root.items())
        if (key != "format" && key != "title" && key != "views") lesson.kept[key] = value;
    if (root.contains("title")) {
        if (root["title"].is_string()) lesson.title = root["title"].get<std::string>();
        else throw InputError(path + ": title", expectedGot(MessageId::WantedString, root["title"]));
    }
    const Json* views = root.contains("views") ? &root["views"] : nullptr;
    if (!views || !views->is_array()) throw InputError(path + ": views", views ? expectedGot(MessageId::WantedViewArray, *views)
                                                                                : message(MessageId::RequiredFieldMissing, Message(MessageId::WantedViewArray)));
    for (std::size_t i = 0; i < views->size(); ++i) {
        const Json& entry = (*views)[i];
        const std::string field = item("views", i + 1);
        LessonView lv;
        lv.written = entry;
        try {
            if (!entry.is_object()) throw InputError(field, expectedGot(MessageId::WantedViewOrInclude, entry));
            if (entry.contains("include")) {
                const Json& include = entry["include"];
                if (!include.is_string() || include.get<std::string>().empty())
                    throw InputError(field + ".include", expectedGot(MessageId::WantedString, include));
                lv.include = include.get<std::string>();
                lv.view = loadWindowView(resolvedPath(lv.include, folder));
                // Its own name and note (and nothing else) beside the include.
                for (const auto& [key, value] : entry.items()) {
                    if (key == "include") continue;
                    if ((key != "name" && key != "note") || !value.is_string())
                        throw InputError(field + "." + key, key == "name" || key == "note" ? expectedGot(MessageId::WantedString, value)
                                                                                           : message(MessageId::UnknownKey, "include, name, note"));
                    (key == "name" ? lv.view.name : lv.view.note) = value.get<std::string>();
                }
            } else {
                lv.view = readWindowView(entry, field);
                lv.view.scenePath = resolvedPath(lv.view.scenePath, folder);
            }
        } catch (const InputError& e) {
            lv.problems = prefixedByFile(e.diagnostics(), path);
            if (entry.is_object() && entry.contains("name") && entry["name"].is_string()) lv.view.name = entry["name"].get<std::string>();
            if (entry.is_object() && entry.contains("note") && entry["note"].is_string()) lv.view.note = entry["note"].get<std::string>();
        }
        lesson.views.push_back(std::move(lv));
    }
    return lesson;
}

namespace {

// `spec` (PATH or PATH#NAME, relative to `from`) relative to `to`; a resource or absolute path stays.
std::string rebased(const std::string& spec, const std::string& from, const std::string& to) {
    const auto hash = spec.rfind('#');
    const std::string file = hash == std::string::npos ? spec : spec.substr(0, hash);
    const std::string name = hash == std::string::npos ? std::string() : spec.substr(hash);
    if (file.empty() || file.rfind(":/", 0) == 0 || fs::path(file).is_absolute()) return spec;
    return relativePath(resolvedPath(file, from), to) + name;
}

}  // namespace

void saveLesson(const Lesson& lesson, const std::string& path, bool embed) {
    const std::string folder = fs::path(path).parent_path().string();
    Json root = Json::object();
    root["format"] = kLessonFormat;
    if (!lesson.title.empty()) root["title"] = lesson.title;
    Json views = Json::array();
    for (const LessonView& lv : lesson.views) {
        if (!lv.problems.empty()) {  // as it was written (its paths from here): nothing of it is lost
            Json written = lv.written;
            for (const char* key : {"include", "scene"})
                if (written.is_object() && written.contains(key) && written[key].is_string())
                    written[key] = rebased(written[key].get<std::string>(), lesson.folder, folder);
            views.push_back(written);
            continue;
        }
        if (!lv.include.empty() && !embed) {
            Json entry{{"include", rebased(lv.include, lesson.folder, folder)}};
            if (!lv.view.name.empty()) entry["name"] = lv.view.name;
            if (!lv.view.note.empty()) entry["note"] = lv.view.note;
            views.push_back(entry);
            continue;
        }
        WindowView view = lv.view;
        if (embed && !view.sceneEmbedded && !view.scenePath.empty() && view.scenePath.rfind(":/", 0) != 0) {
            view.sceneEmbedded = readJsonFile(view.scenePath);
            view.sceneEmbedded->erase("views");  // the scene's own views are not this lesson's
        }
        if (!view.scenePath.empty() && view.scenePath.rfind(":/", 0) != 0) view.scenePath = relativePath(view.scenePath, folder);
        views.push_back(windowViewJson(view, false));
    }
    root["views"] = views;
    for (const auto& [key, value] : lesson.kept.items()) root[key] = value;
    std::string text;
    writePretty(text, root, 0);
    saveFileAtomically(path, text + "\n", Backup::Keep);
}

WindowView viewOfLesson(const Lesson& lesson, const std::string& name, const std::string& path) {
    const LessonView* found = nullptr;
    for (const LessonView& lv : lesson.views)
        if (!name.empty() && lv.view.name == name) found = found ? found : &lv;  // no name: the first, not the first unnamed
    if (!found && !name.empty() && std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        const std::size_t k = std::stoul(name.substr(0, 6));
        if (k >= 1 && k <= lesson.views.size()) found = &lesson.views[k - 1];
    }
    if (!found && name.empty() && !lesson.views.empty()) found = &lesson.views.front();
    if (!found) {
        Keys names;
        for (std::size_t i = 0; i < lesson.views.size(); ++i)
            names.push_back(lesson.views[i].view.name.empty() ? std::to_string(i + 1) : lesson.views[i].view.name);
        throw InputError(path, lesson.views.empty() ? message(MessageId::HoldsNoViews, path) : message(MessageId::NoSuchView, path, name, joined(names)));
    }
    if (!found->problems.empty()) throw InputError(found->problems);
    return found->view;
}

}  // namespace ll
