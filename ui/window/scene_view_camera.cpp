// SceneView's camera (scene_view.hpp): fitted to the scene or to the pose shown, the
// standard views, and orbit, pan and zoom with the mouse.
#include "ui/window/scene_view.hpp"

#include <QMouseEvent>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <osgViewer/Viewer>

namespace ll::ui {

void SceneView::fit() {
    distance_ = 0;
    fovy_ = 30;
    pan_.setZero();
    userMoved_ = false;
    applyCamera();
    requestFrame();
}

void SceneView::setStandardView(const QString& name) {
    const CameraSpec spec = parseCameraSpec(name.toStdString());
    switch (spec.preset) {
        case CameraSpec::Preset::Front: azimuth_ = 0, elevation_ = 0; break;
        case CameraSpec::Preset::Side: azimuth_ = 90, elevation_ = 0; break;
        case CameraSpec::Preset::Top: azimuth_ = 0, elevation_ = 89.9; break;
        default: azimuth_ = 45, elevation_ = 30; break;
    }
    fit();
}

CameraView SceneView::unpannedView() const {
    CameraSpec spec;
    spec.preset = CameraSpec::Preset::Angles;
    spec.azimuth = azimuth_;
    spec.elevation = elevation_;
    spec.distance = distance_;
    const double aspect = double(std::max(width(), 1)) / std::max(height(), 1);
    return cameraView(*visual_, spec, aspect, framePose_ ? &framed_ : nullptr);
}

void SceneView::applyCamera() {
    if (!visual_ || !viewer_) return;
    const double aspect = double(std::max(width(), 1)) / std::max(height(), 1);
    if (framePose_ && distance_ <= 0) visual_->currentExtent(framed_);  // fitting now: to the pose shown
    CameraView view = unpannedView();
    if (distance_ <= 0) {  // fitted now
        distance_ = (view.eye - view.centre).norm();
        fittedRadius_ = visual_->bounds.radius();
    }
    view.eye += pan_;
    view.centre += pan_;
    view.fovy = fovy_;
    const double radius = std::max(visual_->bounds.radius(), 1e-6);
    view.zNear = std::max(1e-3 * distance_, distance_ - 3 * radius);
    view.zFar = distance_ + 4 * radius + pan_.norm();
    applyCameraView(*viewer_->getCamera(), view, aspect);
    camera_ = view;
}

void SceneView::setCamera(const CameraView& wanted) {
    if (!visual_) return;
    // The angles and distance of the eye from the target, and the pan that moves the
    // centre cameraView picks for those angles onto the target.
    const Eigen::Vector3d toEye = wanted.eye - wanted.centre;
    const auto [azimuth, elevation] = viewAngles(*visual_, toEye);
    azimuth_ = azimuth;
    elevation_ = std::clamp(elevation, -89.9, 89.9);
    distance_ = toEye.norm();
    fovy_ = wanted.fovy;
    pan_ = wanted.centre - unpannedView().centre;
    userMoved_ = true;
    applyCamera();
    requestFrame();
}

double SceneView::sceneHeightInView() const {
    if (!visual_) return 0.0;
    std::vector<Eigen::Vector4d> spheres;
    visual_->currentExtent(spheres);
    return projectedHeight(camera_, spheres);
}

void SceneView::setFramePose(bool on) {
    framePose_ = on;
    if (on) fit();
}

void SceneView::keepPoseInView() {
    if (!framePose_ || userMoved_ || !visual_ || distance_ <= 0) return;
    visual_->currentExtent(extent_);
    CameraView unpanned = camera_;
    unpanned.eye -= pan_;
    unpanned.centre -= pan_;
    const double aspect = double(std::max(width(), 1)) / std::max(height(), 1);
    const double needed = distanceToHold(unpanned, extent_, aspect);
    if (needed > distance_ * 1.0001) {
        distance_ = needed;
        applyCamera();
    }
}

void SceneView::move(QMouseEvent* e) {
    const QPoint delta = e->pos() - last_;
    last_ = e->pos();
    if (!visual_) return;
    if (e->buttons() & (Qt::LeftButton | Qt::RightButton | Qt::MiddleButton)) userMoved_ = true;
    if (e->buttons() & Qt::LeftButton) {
        azimuth_ -= delta.x() * 0.4;
        elevation_ = std::clamp(elevation_ + delta.y() * 0.4, -89.9, 89.9);
        applyCamera();
        requestFrame();
    } else if (e->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
        // Move the looked-at point in the picture plane, a pixel's worth of the view.
        osg::Vec3d eye, centre, up;
        viewer_->getCamera()->getViewMatrixAsLookAt(eye, centre, up);
        osg::Vec3d forward = centre - eye;
        forward.normalize();
        osg::Vec3d right = forward ^ up;
        right.normalize();
        const osg::Vec3d pictureUp = right ^ forward;
        const double perPixel = 2 * distance_ * std::tan(fovy_ / 2 * M_PI / 180) / std::max(height(), 1);
        const osg::Vec3d shift = (right * -delta.x() + pictureUp * delta.y()) * perPixel;
        pan_ += Eigen::Vector3d(shift.x(), shift.y(), shift.z());
        applyCamera();
        requestFrame();
    } else {
        const int joint = jointAt(e->pos());
        if (joint != hovered_) {
            hovered_ = joint;
            emit jointHovered(joint);
        }
    }
}

void SceneView::release() { dragging_ = Qt::NoButton; }

void SceneView::wheel(QWheelEvent* e) { zoomBy(std::pow(0.9, e->angleDelta().y() / 120.0)); }

void SceneView::zoomBy(double factor) {
    distance_ *= factor;
    userMoved_ = true;
    applyCamera();
    requestFrame();
}

}  // namespace ll::ui
