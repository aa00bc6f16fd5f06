#pragma once
// A lesson: an ordered list of views (core/io/window_view.hpp) across scenes, each with its
// title (the view's name) and the speaker's note. The file:
//   {"format": "lagrangelab-lesson/1", "title": "…", "views": [ VIEW, {"include": "PATH#NAME", "note": "…"}, … ]}
// A view's scene path and an include's path are relative to the lesson's file. An include
// names a view file, a scene's named view (scene.json#NAME) or another lesson's view
// (lesson.json#NAME or #3); its own "name" and "note" override the included view's.
//
// Opening never fails for one view: a view that cannot be read (a file gone, a field
// broken) keeps its JSON as written, so saving loses nothing, and says why (`problems`).
#include <string>
#include <vector>

#include "core/io/scene_json.hpp"
#include "core/io/window_view.hpp"
#include "core/model/diagnostics.hpp"

namespace ll {

inline constexpr const char* kLessonFormat = "lagrangelab-lesson/1";

struct LessonView {
    WindowView view;                   // scene path relative to the current directory
    std::string include;               // as written ("views.json#intro"); empty: the view is inline
    scene_json::Json written;          // the entry as read (written back when `problems` is not empty)
    std::vector<Diagnostic> problems;  // why the view could not be read
};

struct Lesson {
    std::string title;
    std::string folder;  // the folder its file was read from: includes are relative to it
    std::vector<LessonView> views;
    scene_json::Json kept = scene_json::Json::object();  // top-level fields unknown to this version
};

// The lesson in `path`. Throws InputError naming the file when the file itself is not a
// lesson (unreadable, not JSON, wrong format, no "views" array); a broken view does not throw.
Lesson loadLesson(const std::string& path);
// Writes the lesson to `path` (atomically, PATH.bak kept): inline views with their scene
// paths relative to the file's folder, includes (and the paths in views kept as written)
// made relative to it from the folder the lesson was read from. `embed`: every view inline
// with its scene inside, so the file is all a student needs.
void saveLesson(const Lesson& lesson, const std::string& path, bool embed = false);

// The lesson's view named `name`, or numbered `name` (from 1). Throws InputError naming
// `path` when there is none, or the view's first problem.
WindowView viewOfLesson(const Lesson& lesson, const std::string& name, const std::string& path);

}  // namespace ll
