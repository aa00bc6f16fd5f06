#include "core/visual/camera_view.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/model/message_error.hpp"

namespace ll {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

struct Basis {
    Eigen::Vector3d up, right, back;
};

Basis sceneBasis(const Eigen::Vector3d& up) {
    Basis basis;
    basis.up = up.normalized();
    Eigen::Vector3d r = std::abs(basis.up.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    r -= r.dot(basis.up) * basis.up;
    basis.right = r.normalized();
    basis.back = basis.up.cross(basis.right);
    return basis;
}

std::vector<Eigen::Vector3d> corners(const VisualBounds& b) {
    std::vector<Eigen::Vector3d> out;
    for (int c = 0; c < 8; ++c)
        out.emplace_back((c & 1) ? b.max.x() : b.min.x(), (c & 2) ? b.max.y() : b.min.y(), (c & 4) ? b.max.z() : b.min.z());
    return out;
}

}  // namespace

CameraSpec parseCameraSpec(const std::string& text) {
    CameraSpec spec;
    if (text == "auto") return spec;
    if (text == "front") spec.preset = CameraSpec::Preset::Front;
    else if (text == "side") spec.preset = CameraSpec::Preset::Side;
    else if (text == "top") spec.preset = CameraSpec::Preset::Top;
    else if (text == "iso") spec.preset = CameraSpec::Preset::Iso;
    if (spec.preset != CameraSpec::Preset::Auto) return spec;

    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    bool ok = !text.empty();
    while (ok && std::getline(in, item, ',')) {
        std::istringstream number(item);
        double v = 0;
        number >> v;
        ok = !number.fail() && number.eof() && std::isfinite(v);
        values.push_back(v);
    }
    ok = ok && (values.size() == 2 || values.size() == 3) && std::abs(values[1]) <= 90 && (values.size() == 2 || values[2] > 0);
    if (!ok) throw MessageError(MessageId::UnknownCamera);
    spec.preset = CameraSpec::Preset::Angles;
    spec.azimuth = values[0];
    spec.elevation = values[1];
    spec.distance = values.size() == 3 ? values[2] : 0.0;
    return spec;
}

PictureAxes pictureAxes(const CameraView& view) {
    PictureAxes axes;
    axes.forward = (view.centre - view.eye).normalized();
    axes.right = axes.forward.cross(view.up).normalized();
    axes.up = axes.right.cross(axes.forward);
    axes.tanHalfFovy = std::tan(view.fovy * kDegree / 2);
    return axes;
}

double projectedHeight(const CameraView& view, const std::vector<Eigen::Vector4d>& spheres) {
    const PictureAxes axes = pictureAxes(view);
    const double tanY = axes.tanHalfFovy;
    double low = 1e300, high = -1e300;
    for (const Eigen::Vector4d& s : spheres) {
        const Eigen::Vector3d v = s.head<3>() - view.eye;
        const double depth = std::max(v.dot(axes.forward), 1e-9);
        // -1 at the picture's bottom edge, +1 at its top
        const double y = v.dot(axes.up) / (depth * tanY), r = s[3] / (depth * tanY);
        low = std::min(low, y - r), high = std::max(high, y + r);
    }
    return spheres.empty() ? 0.0 : (high - low) / 2;
}

bool looksPlanar(const VisualScene& scene) {
    if (scene.bounds.empty()) return false;
    const Basis basis = sceneBasis(scene.up);
    double lowB = 1e300, highB = -1e300, lowR = 1e300, highR = -1e300, lowU = 1e300, highU = -1e300;
    for (const Eigen::Vector3d& p : corners(scene.bounds)) {
        lowB = std::min(lowB, p.dot(basis.back)), highB = std::max(highB, p.dot(basis.back));
        lowR = std::min(lowR, p.dot(basis.right)), highR = std::max(highR, p.dot(basis.right));
        lowU = std::min(lowU, p.dot(basis.up)), highU = std::max(highU, p.dot(basis.up));
    }
    return highB - lowB < 0.35 * std::max(highR - lowR, highU - lowU);
}

double distanceToHold(const CameraView& view, const std::vector<Eigen::Vector4d>& spheres, double aspect) {
    const PictureAxes axes = pictureAxes(view);
    const Eigen::Vector3d toEye = -axes.forward;
    // Every sphere inside the frustum, with 5 % to spare on each side: a sphere of
    // radius r at depth z stays inside when its centre's offset plus r·(1 + tan²)^½
    // is within z·tan; checking offset + r against (z − r)·tan is a little stricter.
    const double tanY = axes.tanHalfFovy * 0.95, tanX = tanY * aspect;
    double distance = 0.0;
    for (const Eigen::Vector4d& s : spheres) {
        const Eigen::Vector3d v = s.head<3>() - view.centre;
        const double towardEye = v.dot(toEye) + s[3];
        distance = std::max(
            {distance, towardEye + (std::abs(v.dot(axes.right)) + s[3]) / tanX, towardEye + (std::abs(v.dot(axes.up)) + s[3]) / tanY});
    }
    return distance;
}

std::pair<double, double> viewAngles(const VisualScene& scene, const Eigen::Vector3d& toEye) {
    const Basis basis = sceneBasis(scene.up);
    const Eigen::Vector3d d = toEye.normalized();
    const double elevation = std::asin(std::clamp(d.dot(basis.up), -1.0, 1.0)) / kDegree;
    return {std::atan2(d.dot(basis.right), -d.dot(basis.back)) / kDegree, elevation};
}

CameraView cameraView(const VisualScene& scene, const CameraSpec& spec, double aspect, const std::vector<Eigen::Vector4d>* hold) {
    double azimuth = spec.azimuth, elevation = spec.elevation;
    CameraSpec::Preset preset = spec.preset;
    if (preset == CameraSpec::Preset::Auto) preset = looksPlanar(scene) ? CameraSpec::Preset::Front : CameraSpec::Preset::Iso;
    switch (preset) {
        case CameraSpec::Preset::Front: azimuth = 0, elevation = 0; break;
        case CameraSpec::Preset::Side: azimuth = 90, elevation = 0; break;
        case CameraSpec::Preset::Top: azimuth = 0, elevation = 90; break;
        case CameraSpec::Preset::Iso: azimuth = 45, elevation = 30; break;
        case CameraSpec::Preset::Auto:
        case CameraSpec::Preset::Angles: break;
    }
    const Basis basis = sceneBasis(scene.up);
    const double az = azimuth * kDegree, el = elevation * kDegree;
    const Eigen::Vector3d toEye =
        (std::cos(el) * (-std::cos(az) * basis.back + std::sin(az) * basis.right) + std::sin(el) * basis.up).normalized();

    // What must stay in view: the spheres the scene collected, or the corners of its bounds.
    std::vector<Eigen::Vector4d> keep = hold ? *hold : scene.keepInView;
    if (keep.empty() && !scene.bounds.empty())
        for (const Eigen::Vector3d& p : corners(scene.bounds)) keep.emplace_back(p.x(), p.y(), p.z(), 0.0);

    CameraView view;
    view.centre = scene.bounds.empty() ? Eigen::Vector3d::Zero() : scene.bounds.centre();
    // The picture's up: the scene's up, or (looking straight down or up) the back direction.
    view.up = std::abs(toEye.dot(basis.up)) > 0.999 ? Eigen::Vector3d(basis.back * (toEye.dot(basis.up) > 0 ? 1 : -1)) : basis.up;
    const Eigen::Vector3d right = (-toEye).cross(view.up).normalized();
    const Eigen::Vector3d upInPicture = right.cross(-toEye);
    // Centre the picture on the middle of what it shows (not on the middle of the box,
    // whose corners a slanted view sees far outside the robot).
    if (!keep.empty()) {
        double lowR = 1e300, highR = -1e300, lowU = 1e300, highU = -1e300;
        for (const Eigen::Vector4d& s : keep) {
            const Eigen::Vector3d v = s.head<3>() - view.centre;
            lowR = std::min(lowR, v.dot(right) - s[3]), highR = std::max(highR, v.dot(right) + s[3]);
            lowU = std::min(lowU, v.dot(upInPicture) - s[3]), highU = std::max(highU, v.dot(upInPicture) + s[3]);
        }
        view.centre += right * (lowR + highR) / 2 + upInPicture * (lowU + highU) / 2;
    }

    double distance = spec.distance;
    const double radius = std::max(scene.bounds.radius(), 1e-6);
    view.eye = view.centre + toEye;
    if (distance <= 0) distance = distanceToHold(view, keep, aspect);
    view.eye = view.centre + distance * toEye;
    view.zNear = std::max(1e-3 * distance, distance - 2 * radius);
    view.zFar = distance + 4 * radius;
    return view;
}

}  // namespace ll
