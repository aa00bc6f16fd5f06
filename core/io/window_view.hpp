#pragma once
// A view: everything that decides what the window shows, as plain data, and its JSON
// ("format": "lagrangelab-view/1", documented in docs/user/scene-format.md "Views").
// The window captures and restores one (ui/window/view_state.hpp); a lesson strings
// them together (core/io/lesson_file.hpp); a scene file may hold named ones ("views").
//
// Every field is optional: what a view leaves out, the window leaves as it is. Units as
// everywhere in a scene file: seconds, metres, radians (a teach pose), and degrees for the
// camera's field of view. Fields a newer version wrote are kept as they are (`kept`) and
// written back on save, so opening and saving never loses them; their paths are listed
// for a warning.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/io/scene_json.hpp"
#include "core/model/diagnostics.hpp"

namespace ll {

struct WindowView {
    struct Derivation {
        std::optional<std::string> tab;       // typeset, text, entries, exercise
        std::optional<int> step;              // 0..9, 10: the results at the teach pose
        std::optional<double> scroll;         // 0..1 of the step's page, top to bottom
        std::optional<double> zoom;           // 1 = 15 px per em
        std::optional<std::array<int, 2>> through;  // a lesson steps from the first to the last of these
    };
    struct Pick {
        std::optional<std::string> entry;  // as the Entries tab names it: b11, g2, p_c2
        std::optional<int> link;           // from 1
    };
    struct Playback {
        std::optional<double> time;  // [s]
        std::optional<bool> playing;
        std::optional<double> speed;  // × real time
        std::optional<bool> loop;
        std::optional<std::array<double, 2>> play;  // a lesson plays from t₀ to t₁ [s]
    };
    struct Camera {
        Eigen::Vector3d eye = Eigen::Vector3d::Zero();     // [m]
        Eigen::Vector3d target = Eigen::Vector3d::Zero();  // looked at [m]
        Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
        double fov = 30.0;  // vertical [deg]
    };
    struct Show {
        std::optional<bool> frames, labels, coms, trail, look;
    };
    struct Plots {
        std::optional<std::string> tab;       // energy, joints, teach, torques, properties, work-precision, dh-steps, tracking
        std::optional<int> joint;             // from 1 (Torques, Tracking)
        std::optional<std::string> tracking;  // error, torque, lyapunov, rate
    };
    struct DhSteps {
        std::string mode = "rows";  // rows: joint i's four motions; axes: step 0, frame by frame
        int index = 1;              // rows: the joint from 1; axes: the frame from 0
        int done = 0;               // motions (0..4) or rules (0..4) done
        bool dimensions = false;    // rows: every DH parameter drawn on the robot
    };

    std::string name;  // in a lesson or a scene's "views"
    std::string note;  // the speaker's note (a lesson)
    // The scene: a path (relative to the file the view is in) or the scene itself.
    std::string scenePath;
    std::optional<scene_json::Json> sceneEmbedded;
    std::optional<std::string> language;  // en, da
    std::optional<std::string> notation;  // notes, spong, craig, siciliano
    std::optional<bool> present;
    std::optional<std::array<int, 2>> size;  // the window's [width, height] in pixels
    Derivation derivation;
    Pick pick;
    Playback playback;
    std::optional<Camera> camera;
    Show show;
    Plots plots;
    std::optional<DhSteps> dh;
    std::optional<std::vector<double>> teach;  // the teach pose q [rad, m]

    scene_json::Json kept = scene_json::Json::object();  // fields unknown to this version, as read
    std::vector<std::string> keptPaths() const;        // their paths: "camera.roll", "effects"
};

inline constexpr const char* kViewFormat = "lagrangelab-view/1";

// The view `value` describes; `path` prefixes the fields of its errors ("views[2]"). Throws
// InputError with every error found. A missing "format" is accepted (a view inside a
// lesson or a scene has none).
WindowView readWindowView(const scene_json::Json& value, const std::string& path = {});
// The view's JSON: its fields in a fixed order, then the kept ones.
scene_json::Json windowViewJson(const WindowView& view, bool withFormat = true);
// The file's text (pretty, as scene files are written).
std::string serializeWindowView(const WindowView& view);

// A file's view: `spec` is PATH or PATH#NAME. PATH may be a view file, a lesson (its view
// named NAME, or numbered NAME from 1) or a scene with "views" (NAME; a scene without NAME
// is a view of that scene as it opens). The view's scene path is made relative to the
// current directory. Throws InputError naming the file.
WindowView loadWindowView(const std::string& spec);
// Writes the view to `path` (atomically, no backup), its scene path made relative to the
// file's folder. Throws MessageError when it cannot be written.
void saveWindowView(const WindowView& view, const std::string& path);

// `path` as seen from `folder` (both as given: absolute or relative to the current
// directory); an absolute path stays absolute when the two share nothing but the root.
std::string relativePath(const std::string& path, const std::string& folder);
// `path` written relative to `folder`, as seen from the current directory.
std::string resolvedPath(const std::string& path, const std::string& folder);

}  // namespace ll
