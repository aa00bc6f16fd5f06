#pragma once
// The 3D view of the window: the shared OSG scene builder (ui/paint/osg_scene.hpp) drawn in a
// native QOpenGLWindow inside a window container (compatibility context,
// GraphicsWindowEmbedded, single-threaded viewer, frame() only in paintGL, the window's
// framebuffer set before every frame; see shared/notes/platform-facts.md).
// Not a QOpenGLWidget: with one in it, every repaint of the main window, a table cell
// or the status line, is composed through OpenGL (13 ms for a label under llvmpipe at
// 1280×800, 0.7 ms with the GL view in its own native window, measured side by side),
// which doubled the time from an edit to its frame. Left drag orbits, right or middle drag
// pans, the wheel zooms; fit and the standard views of core/visual/camera_view. Hovering
// or clicking a joint reports it; highlightJoint lights one up.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <QImage>
#include <QStringList>
#include <QWidget>
#include <osg/ref_ptr>

#include "core/visual/camera_view.hpp"
#include "core/visual/visual_scene.hpp"
#include "ui/paint/osg_scene.hpp"

class QWindow;

namespace osgViewer {
class Viewer;
class GraphicsWindowEmbedded;
}  // namespace osgViewer

namespace ll::ui {

class SceneView : public QWidget {
    Q_OBJECT
public:
    explicit SceneView(QWidget* parent = nullptr);
    ~SceneView() override;

    // Shows `scene` (shared with the caller, posed by this view only). `fit`: the camera
    // fits the scene's bounds; otherwise it keeps its angles and distance, and refits its
    // distance when the scene's size changed by more than 5 % and the user has not moved it.
    void setVisualScene(std::shared_ptr<VisualScene> scene, bool fit);
    // The camera's distance from what it looks at [m], and whether the user moved it since
    // it was last fitted (tests, the presentation mode).
    double cameraDistance() const { return distance_; }
    bool cameraMovedByUser() const { return userMoved_; }
    // Moves the camera towards what it looks at (factor < 1) or away, as the wheel does.
    void zoomBy(double factor);
    // The camera as last applied (its eye moved by any pan), and the share of the view's
    // height the scene takes at its current pose (core/visual/camera_view.hpp).
    const CameraView& camera() const { return camera_; }
    // Puts the camera exactly at `view` (a saved view): its eye, target and field of view;
    // its up is the scene's, as orbiting keeps it. The camera is then the user's (an edit
    // does not refit it); F fits again.
    void setCamera(const CameraView& view);
    double sceneHeightInView() const;
    // Presentation framing: the camera fits the robot as it stands (not its whole motion,
    // which would leave a falling Panda half the height), then backs away as far as the
    // motion needs to stay in view, never closer again until the next fit. Off: the camera
    // stays where it is (the caller refits it once the view has its docked size).
    void setFramePose(bool on);
    bool framesPose() const { return framePose_; }
    const VisualScene* visualScene() const { return visual_.get(); }
    // Poses the scene at q, t; `trail` (optional) the end effector's path up to t.
    void setPose(const Eigen::VectorXd& q, double t, const std::vector<Eigen::Vector3d>* trail = nullptr);
    // A second, translucent copy of the robot (a ghost run); null removes it.
    void setGhost(std::shared_ptr<VisualScene> ghost);
    void setGhostPose(const Eigen::VectorXd& q, double t);
    const VisualScene* ghost() const { return ghostVisual_.get(); }  // null: none

    void setShowFrames(bool on);
    void setShowLabels(bool on);  // the frames' numbers
    bool showLabels() const { return options_.frameLabels; }
    void setShowComs(bool on);
    void setShowTrail(bool on);
    // The robot's own look (a URDF's meshes and shapes) instead of the DH drawing, where the
    // scene has one and every mesh was read (else meshesNotRead says which were not);
    // relative mesh paths start at `folder` (the scene file's).
    void setShowLook(bool on);
    bool showsLook() const;
    bool lookWanted() const { return options_.look; }  // the meshes toggle (shown where the scene has them)
    void setMeshDirectory(const QString& folder);
    bool showFrames() const { return options_.frames; }
    bool showComs() const { return coms_; }
    bool showTrail() const { return options_.trail; }
    std::size_t trailPoints() const { return trail_.size(); }  // of the trail drawn now

    // The DH step-through (core/kinematics/dh_step_through.hpp): the moving frame of row
    // joint+1 after `done` motions and `fraction` of the next, drawn at every pose;
    // joint −1 hides it.
    void setDhStep(int joint, int done, double fraction);
    // The step-through's static view: every DH parameter drawn on the robot as an arrow or
    // an arc with its value, kept up with the pose.
    void setShowDimensions(bool on);
    bool showDimensions() const { return dimensionsShown_; }
    // Step 0 rule by rule (core/visual/dh_construction.hpp): these marks over the robot and
    // none of its own DH frames; empty removes them and shows the frames again.
    void setConstruction(std::vector<ConstructionMark> marks);
    const std::vector<ConstructionMark>& construction() const { return construction_; }
    // The moving frame as drawn now (false when none is).
    bool dhStepFrame(Eigen::Isometry3d& frame) const;
    // The pose shown (q of the last setPose).
    const Eigen::VectorXd& shownPose() const { return shownQ_; }

    // The joint (0-based) drawn highlighted; -1: none.
    void highlightJoint(int joint);
    // A picked entry's or link's emphasis (core/visual/visual_emphasis.hpp), kept across
    // rebuilds; an inactive one shows every part as built.
    void setEmphasis(VisualEmphasis emphasis);
    const VisualEmphasis& emphasis() const { return emphasis_; }
    // The joint whose part is under widget point `p`, or -1.
    int jointAt(const QPoint& p);

    // Frames drawn so far (a test or benchmark waits for the next one).
    long framesDrawn() const { return frames_; }
    // Nodes and drawables in the scene graph (each drawable owns its GL buffer objects):
    // what a soak test watches for leaks.
    std::size_t graphObjects() const;
    // The native window that draws and takes the mouse (tests send it input events).
    QWindow* surface() const;
    // Asks for a new frame (drawn at the GL window's next update).
    void requestFrame();
    // The rendered picture: a frame drawn now and read back (null before the view is shown).
    QImage grabView();

public slots:
    void fit();
    void setStandardView(const QString& name);  // "front", "side", "top", "iso"

signals:
    void frameDrawn();
    void frameSwapped();  // the frame drawn is on screen
    void jointHovered(int joint);
    void jointClicked(int joint);
    void meshesNotRead(const QStringList& failures);
    void partsShownChanged();  // a toggle of frames, labels, COMs, trail or meshes changed
    void lookAvailable(bool available);  // whether the scene shown has a look of its own (meshes)  // "path: why" each; the DH drawing is shown

private:
    class GlWindow;  // the native GL window; forwards its paint, resize and mouse events here
    void resizeGL(int w, int h);
    void paintGL();
    void press(QMouseEvent* e);
    void move(QMouseEvent* e);
    void release();
    void wheel(QWheelEvent* e);
    void rebuild();
    void applyCamera();
    CameraView unpannedView() const;  // cameraView at the angles and distance (0: fitted), before the pan
    void applyHighlight();
    void drawComs();  // the COM markers, as coms_ says

    GlWindow* gl_ = nullptr;  // owned by its container, a child of this widget
    osg::ref_ptr<osgViewer::Viewer> viewer_;
    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> window_;
    osg::ref_ptr<osg::Group> root_;
    std::shared_ptr<VisualScene> visual_, ghostVisual_;
    std::unique_ptr<OsgScene> osg_, ghost_;
    OsgSceneOptions options_;
    VisualEmphasis emphasis_;
    bool coms_ = true;
    std::vector<Eigen::Vector3d> trail_;
    // Camera: angles [deg] in the scene's basis, distance [m], pan offset of the centre.
    double azimuth_ = 45, elevation_ = 30, distance_ = 0, fovy_ = 30;
    // Whether the user turned, panned or zoomed since the last fit (then an edit keeps the
    // camera), and the scene radius the camera was last fitted to (an edit that changes it
    // by more than 5 % refits an untouched camera: a1 = 1.5 on the 2R stays in view).
    bool userMoved_ = false;
    double fittedRadius_ = 0;
    Eigen::Vector3d pan_ = Eigen::Vector3d::Zero();
    CameraView camera_;
    bool framePose_ = false;
    int stepJoint_ = -1, stepDone_ = 0;
    bool dimensionsShown_ = false;
    std::vector<ConstructionMark> construction_;
    QStringList meshFailures_;
    double stepFraction_ = 0;
    Eigen::VectorXd shownQ_;
    void updateMovingFrame();
    std::vector<Eigen::Vector4d> framed_, extent_;  // the spheres fitted to; the current pose's (scratch)
    void keepPoseInView();
    QPoint last_;
    Qt::MouseButton dragging_ = Qt::NoButton;
    int highlighted_ = -1, hovered_ = -1;
    long frames_ = 0;
};

}  // namespace ll::ui
