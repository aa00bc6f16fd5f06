#pragma once
// Where the camera stands to see a VisualScene, renderer-neutral.
//
// Directions are taken in the scene's own basis: up u (−gravity), right r (the world x
// axis, or y when x is nearly vertical, made perpendicular to u) and back b = u × r.
// Azimuth φ turns from the front towards the right, elevation ε lifts towards up; the
// camera looks at the centre of the scene's bounds from the direction
//   d = cos ε (−cos φ b + sin φ r) + sin ε u.
// Presets: front (φ 0°, ε 0°), side (90°, 0°), top (0°, 90°), iso (45°, 30°). For the
// x–y plane scenes with y up, front looks along −z, so the plane is seen face on.
// `auto` is front for a scene whose bounds are flat along b (a planar mechanism seen
// face on), iso otherwise. Distance 0 fits the bounds: every corner of the bounds box
// lies inside the view, so the scene never leaves the frame.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/visual/visual_scene.hpp"

namespace ll {

struct CameraSpec {
    enum class Preset { Auto, Front, Side, Top, Iso, Angles };
    Preset preset = Preset::Auto;
    double azimuth = 0.0;    // [deg], Angles only
    double elevation = 0.0;  // [deg], Angles only
    double distance = 0.0;   // [m] from the centre; 0: fit the bounds
};

// "auto", "front", "side", "top", "iso" or "azimuth,elevation[,distance]" (degrees,
// metres). Throws MessageError (core/model/message_error.hpp) saying what is accepted.
CameraSpec parseCameraSpec(const std::string& text);

struct CameraView {
    Eigen::Vector3d eye = Eigen::Vector3d::Zero();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // looked at
    Eigen::Vector3d up = Eigen::Vector3d::UnitZ();     // the picture's up direction
    double fovy = 30.0;                                // vertical field of view [deg]
    double zNear = 0.01, zFar = 100.0;                 // [m]
};

// The view of `scene` (its `bounds`) for a picture of width/height `aspect`; it holds the
// scene's keepInView spheres, or `hold` when given (the robot at one pose).
CameraView cameraView(const VisualScene& scene, const CameraSpec& spec, double aspect, const std::vector<Eigen::Vector4d>* hold = nullptr);

// The azimuth and elevation [deg] (CameraSpec's) of the direction `toEye` from the centre
// towards the eye: the inverse of cameraView's direction d (a saved camera restored).
std::pair<double, double> viewAngles(const VisualScene& scene, const Eigen::Vector3d& toEye);

// How far from `view.centre`, looking along the view's direction, the eye must stand for
// every sphere (centre x, y, z, radius [m]) to lie inside the picture with 5 % to spare.
double distanceToHold(const CameraView& view, const std::vector<Eigen::Vector4d>& spheres, double aspect);

// The picture's directions seen through `view`, unit: forward (eye → centre), right and
// up in the picture; and tan of half the vertical field of view.
struct PictureAxes {
    Eigen::Vector3d forward, right, up;
    double tanHalfFovy = 0.0;
};
PictureAxes pictureAxes(const CameraView& view);

// The share (0..1 and beyond) of the picture's height that `spheres` (centre x, y, z,
// radius [m]) cover seen through `view`: from the lowest to the highest point of their
// perspective projection, over the height of the view at each sphere's depth.
double projectedHeight(const CameraView& view, const std::vector<Eigen::Vector4d>& spheres);

// Whether the bounds of `scene` are flat along its back direction b (less than 35 %
// of their largest extent across it): `auto` then looks from the front.
bool looksPlanar(const VisualScene& scene);

}  // namespace ll
