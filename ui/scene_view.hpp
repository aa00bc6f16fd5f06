#pragma once
// The 3D view of the window: the shared OSG scene builder (ui/osg_scene.hpp) drawn in a
// QOpenGLWidget (compatibility context, GraphicsWindowEmbedded, single-threaded
// viewer, frame() only in paintGL, the widget's own framebuffer object set before every
// frame; see shared/notes/platform-facts.md). Left drag orbits, right or middle drag
// pans, the wheel zooms; fit and the standard views of core/scene/camera_view. Hovering
// or clicking a joint reports it; highlightJoint lights one up.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <QOpenGLWidget>
#include <osg/ref_ptr>

#include "core/scene/camera_view.hpp"
#include "core/scene/visual_scene.hpp"
#include "ui/osg_scene.hpp"

namespace osgViewer {
class Viewer;
class GraphicsWindowEmbedded;
}  // namespace osgViewer

namespace ll::ui {

class SceneView : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit SceneView(QWidget* parent = nullptr);
    ~SceneView() override;

    // Shows `scene` (shared with the caller, posed by this view only). `fit`: the camera
    // fits the scene's bounds; otherwise it keeps its angles and distance.
    void setVisualScene(std::shared_ptr<VisualScene> scene, bool fit);
    const VisualScene* visualScene() const { return visual_.get(); }
    // Poses the scene at q, t; `trail` (optional) the end effector's path up to t.
    void setPose(const Eigen::VectorXd& q, double t, const std::vector<Eigen::Vector3d>* trail = nullptr);
    // A second, translucent copy of the robot (a ghost run); null removes it.
    void setGhost(std::shared_ptr<VisualScene> ghost);
    void setGhostPose(const Eigen::VectorXd& q, double t);

    void setShowFrames(bool on);
    void setShowComs(bool on);
    void setShowTrail(bool on);
    bool showFrames() const { return options_.frames; }
    bool showComs() const { return coms_; }
    bool showTrail() const { return options_.trail; }
    std::size_t trailPoints() const { return trail_.size(); }  // of the trail drawn now

    // The joint (0-based) drawn highlighted; -1: none.
    void highlightJoint(int joint);
    // The joint whose part is under widget point `p`, or -1.
    int jointAt(const QPoint& p);

    // Frames drawn so far (a test or benchmark waits for the next one).
    long framesDrawn() const { return frames_; }
    // The rendered picture (the GL framebuffer).
    QImage grabView() { return grabFramebuffer(); }

public slots:
    void fit();
    void setStandardView(const QString& name);  // "front", "side", "top", "iso"

signals:
    void frameDrawn();
    void jointHovered(int joint);
    void jointClicked(int joint);

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;

private:
    void rebuild();
    void applyCamera();
    void applyHighlight();

    osg::ref_ptr<osgViewer::Viewer> viewer_;
    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> window_;
    osg::ref_ptr<osg::Group> root_;
    std::shared_ptr<VisualScene> visual_, ghostVisual_;
    std::unique_ptr<OsgScene> osg_, ghost_;
    OsgSceneOptions options_;
    bool coms_ = true;
    std::vector<Eigen::Vector3d> trail_;
    // Camera: angles [deg] in the scene's basis, distance [m], pan offset of the centre.
    double azimuth_ = 45, elevation_ = 30, distance_ = 0;
    Eigen::Vector3d pan_ = Eigen::Vector3d::Zero();
    QPoint last_;
    Qt::MouseButton dragging_ = Qt::NoButton;
    int highlighted_ = -1, hovered_ = -1;
    long frames_ = 0;
};

}  // namespace ll::ui
