#include "ui/window/scene_view.hpp"

#include <QVariantAnimation>

#include <algorithm>
#include <cmath>

#include <QMouseEvent>
#include <QOpenGLWindow>
#include <QSurfaceFormat>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Material>
#include <osg/NodeVisitor>
#include <osgUtil/LineSegmentIntersector>
#include <osgViewer/Viewer>

namespace ll::ui {

namespace {

// What Debian's OSG needs: a compatibility context. Requesting no version gives one
// on Mesa (a versioned request without DeprecatedFunctions silently gives core 4.5).
QSurfaceFormat viewFormat() {
    QSurfaceFormat format;
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(0);
    return format;
}

osg::Vec3d toOsg(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

// The native window the view draws in. It takes no keyboard focus, so the window's keys
// (Space, F, arrows) keep working after a click in the view.
class SceneView::GlWindow : public QOpenGLWindow {
public:
    explicit GlWindow(SceneView* view) : QOpenGLWindow(QOpenGLWindow::NoPartialUpdate), view_(view) {
        setFormat(viewFormat());
        setFlag(Qt::WindowDoesNotAcceptFocus);
        connect(this, &QOpenGLWindow::frameSwapped, view, &SceneView::frameSwapped);
    }

protected:
    void resizeGL(int w, int h) override { view_->resizeGL(w, h); }
    void paintGL() override { view_->paintGL(); }
    void mousePressEvent(QMouseEvent* e) override { view_->press(e); }
    void mouseMoveEvent(QMouseEvent* e) override { view_->move(e); }
    void mouseReleaseEvent(QMouseEvent*) override { view_->release(); }
    void wheelEvent(QWheelEvent* e) override { view_->wheel(e); }

private:
    SceneView* view_;
};

SceneView::SceneView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(200, 150);
    gl_ = new GlWindow(this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(QWidget::createWindowContainer(gl_, this));
    viewer_ = new osgViewer::Viewer;
    viewer_->setThreadingModel(osgViewer::Viewer::SingleThreaded);
    window_ = viewer_->setUpViewerAsEmbeddedInWindow(0, 0, 640, 480);
    viewer_->getCamera()->setClearColor(osg::Vec4(0.93f, 0.94f, 0.96f, 1.0f));
    viewer_->setKeyEventSetsDone(0);
    root_ = new osg::Group;
    viewer_->setSceneData(root_);
}

SceneView::~SceneView() {
    // OSG releases its GL objects in the context that made them.
    const bool current = gl_->isValid();
    if (current) gl_->makeCurrent();
    viewer_ = nullptr;
    window_ = nullptr;
    if (current) gl_->doneCurrent();
}

void SceneView::requestFrame() { gl_->update(); }

QWindow* SceneView::surface() const { return gl_; }

QImage SceneView::grabView() {
    if (!gl_->isValid()) return {};
    gl_->makeCurrent();
    paintGL();  // into the back buffer, read before any swap
    return gl_->grabFramebuffer();
}

void SceneView::setVisualScene(std::shared_ptr<VisualScene> scene, bool fitCamera) {
    visual_ = std::move(scene);
    trail_.clear();
    rebuild();
    if (fitCamera) {
        const CameraSpec::Preset preset = visual_ && looksPlanar(*visual_) ? CameraSpec::Preset::Front : CameraSpec::Preset::Iso;
        azimuth_ = preset == CameraSpec::Preset::Front ? 0 : 45;
        elevation_ = preset == CameraSpec::Preset::Front ? 0 : 30;
        distance_ = 0;
        pan_.setZero();
        userMoved_ = false;
    } else if (visual_ && !userMoved_ && fittedRadius_ > 0 &&
               std::abs(visual_->bounds.radius() / fittedRadius_ - 1) > 0.05) {  // an edit resized the robot
        // Refit, the distance gliding there over 0.3 s rather than jumping: the student
        // sees the arm grow, not a cut.
        const double from = distance_;
        distance_ = 0;
        pan_.setZero();
        applyCamera();  // fits: distance_ is the target now
        const double to = distance_;
        if (from > 0 && std::abs(to / from - 1) > 1e-3) {
            distance_ = from;
            auto* glide = new QVariantAnimation(this);
            glide->setDuration(300);
            glide->setStartValue(from);
            glide->setEndValue(to);
            glide->setEasingCurve(QEasingCurve::InOutQuad);
            connect(glide, &QVariantAnimation::valueChanged, this, [this, glide](const QVariant& value) {
                if (userMoved_) {  // the user took the camera: it is theirs
                    glide->stop();
                    return;
                }
                distance_ = value.toDouble();
                applyCamera();
                requestFrame();
            });
            glide->start(QAbstractAnimation::DeleteWhenStopped);
        }
    }
    applyCamera();
    requestFrame();
}

void SceneView::rebuild() {
    root_->removeChildren(0, root_->getNumChildren());
    osg_.reset();
    ghost_.reset();
    if (visual_) {
        osg_ = std::make_unique<OsgScene>(*visual_, options_);
        root_->addChild(osg_->root());
        drawComs();
        if (options_.trail) osg_->setTrail(trail_);
        if (emphasis_.strength.size() == visual_->parts.size()) osg_->setEmphasis(emphasis_);
        updateMovingFrame();
        if (!construction_.empty()) osg_->setConstruction(&construction_);
        emit lookAvailable(osg_->hasLook());
        QStringList failures;
        for (const std::string& failure : osg_->meshFailures()) failures << QString::fromStdString(failure);
        if (failures != meshFailures_) {
            meshFailures_ = failures;
            if (!failures.isEmpty()) emit meshesNotRead(failures);
        }
    }
    if (ghostVisual_) {
        OsgSceneOptions ghostOptions;
        ghostOptions.frames = ghostOptions.frameLabels = ghostOptions.grid = ghostOptions.trail = false;
        ghostOptions.meshDirectory = options_.meshDirectory;
        ghost_ = std::make_unique<OsgScene>(*ghostVisual_, ghostOptions);
        // Translucent: blended, drawn after the opaque robot, not writing depth.
        osg::StateSet* ss = ghost_->root()->getOrCreateStateSet();
        ss->setMode(GL_BLEND, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
        ss->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA),
                                 osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
        auto* material = new osg::Material;
        material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0.2f, 0.45f, 0.95f, 0.35f));
        material->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0.1f, 0.2f, 0.5f, 0.35f));
        ss->setAttributeAndModes(material, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
        ss->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0, 1, false), osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
        ss->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
        root_->addChild(ghost_->root());
    }
    applyHighlight();
}

void SceneView::setPose(const Eigen::VectorXd& q, double t, const std::vector<Eigen::Vector3d>* trail) {
    if (!visual_ || !osg_ || q.size() != visual_->dof()) return;
    visual_->pose(q, t);
    shownQ_ = q;
    osg_->update(*visual_);
    updateMovingFrame();
    keepPoseInView();
    if (trail && options_.trail) {
        trail_ = *trail;
        osg_->setTrail(trail_);
    }
    requestFrame();
}

void SceneView::setGhost(std::shared_ptr<VisualScene> ghost) {
    ghostVisual_ = std::move(ghost);
    rebuild();
    requestFrame();
}

void SceneView::setGhostPose(const Eigen::VectorXd& q, double t) {
    if (!ghostVisual_ || !ghost_ || q.size() != ghostVisual_->dof()) return;
    ghostVisual_->pose(q, t);
    ghost_->update(*ghostVisual_);
    requestFrame();
}

void SceneView::setShowFrames(bool on) {
    if (options_.frames == on) return;
    options_.frames = on;
    emit partsShownChanged();
    rebuild();
    requestFrame();
}

void SceneView::setShowLabels(bool on) {
    if (options_.frameLabels == on) return;
    options_.frameLabels = on;
    emit partsShownChanged();
    rebuild();
    requestFrame();
}

void SceneView::setShowComs(bool on) {
    if (coms_ == on) return;
    coms_ = on;
    emit partsShownChanged();
    rebuild();
    requestFrame();
}

void SceneView::setShowLook(bool on) {
    if (options_.look == on) return;
    options_.look = on;
    emit partsShownChanged();
    rebuild();
    requestFrame();
}

void SceneView::setMeshDirectory(const QString& folder) { options_.meshDirectory = folder.toStdString(); }

bool SceneView::showsLook() const { return osg_ && osg_->showsLook(); }

void SceneView::setShowTrail(bool on) {
    if (options_.trail == on) return;
    options_.trail = on;
    emit partsShownChanged();
    if (!on) trail_.clear();
    rebuild();
    requestFrame();
}

void SceneView::highlightJoint(int joint) {
    if (joint == highlighted_) return;
    highlighted_ = joint;
    applyHighlight();
    requestFrame();
}

void SceneView::setEmphasis(VisualEmphasis emphasis) {
    emphasis_ = std::move(emphasis);
    if (!visual_ || !osg_) return;
    if (emphasis_.active() && emphasis_.strength.size() != visual_->parts.size()) emphasis_ = {};  // of another scene
    osg_->setEmphasis(emphasis_);
    requestFrame();
}

void SceneView::applyHighlight() {
    if (!visual_ || !osg_) return;
    for (std::size_t i = 0; i < visual_->parts.size(); ++i) {
        const VisualPart& part = visual_->parts[i];
        osg_->setPartHighlighted(static_cast<int>(i), highlighted_ >= 0 && part.coordinate == highlighted_ &&
                                                          (part.role == PartRole::Joint || part.role == PartRole::Link));
    }
}

int SceneView::jointAt(const QPoint& p) {
    if (!visual_ || !osg_ || !viewer_) return -1;
    const double r = devicePixelRatioF();
    auto picker = osg::ref_ptr<osgUtil::LineSegmentIntersector>(
        new osgUtil::LineSegmentIntersector(osgUtil::Intersector::WINDOW, p.x() * r, (height() - p.y()) * r));
    osgUtil::IntersectionVisitor visitor(picker.get());
    viewer_->getCamera()->accept(visitor);
    if (!picker->containsIntersections()) return -1;
    for (const auto& hit : picker->getIntersections()) {
        for (osg::Node* node : hit.nodePath)
            for (std::size_t i = 0; i < visual_->parts.size(); ++i)
                if (node == osg_->partTransform(static_cast<int>(i))) {
                    const VisualPart& part = visual_->parts[i];
                    if (part.coordinate >= 0 &&
                        (part.role == PartRole::Joint || part.role == PartRole::Link || part.role == PartRole::CentreOfMass))
                        return part.coordinate;
                }
    }
    return -1;
}

void SceneView::setDhStep(int joint, int done, double fraction) {
    stepJoint_ = joint, stepDone_ = done, stepFraction_ = fraction;
    updateMovingFrame();
    requestFrame();
}

void SceneView::setShowDimensions(bool on) {
    dimensionsShown_ = on;
    updateMovingFrame();
    requestFrame();
}

bool SceneView::dhStepFrame(Eigen::Isometry3d& frame) const {
    return visual_ && stepJoint_ >= 0 && visual_->steppedFrame(stepJoint_, stepDone_, stepFraction_, frame);
}

void SceneView::updateMovingFrame() {
    if (!osg_) return;
    Eigen::Isometry3d frame;
    const bool stepping = dhStepFrame(frame);
    osg_->setMovingFrame(stepping ? &frame : nullptr);
    if (dimensionsShown_ && visual_) {
        // Rebuilt at each pose while shown (a teaching view, not the playback's hot path).
        const std::vector<DhDimension> dimensions = visual_->dhDimensions();
        osg_->setDimensions(&dimensions);
    } else {
        osg_->setDimensions(nullptr);
    }
    // Stepping through row i: only frames i−1 and i beside the moving one; finding the
    // frames by the rules: none of the robot's own (the marks place them one by one).
    if (visual_)
        for (int k = 0; k < static_cast<int>(visual_->frames.size()); ++k)
            osg_->setFrameVisible(k, construction_.empty() && (!stepping || k == stepJoint_ || k == stepJoint_ + 1));
}

// The centres of mass as the toggle says, but not while the frames are being found (the
// construction's lines would hide behind them).
void SceneView::drawComs() {
    const bool on = coms_ && construction_.empty();
    for (std::size_t i = 0; i < visual_->parts.size(); ++i)
        if (visual_->parts[i].role == PartRole::CentreOfMass) osg_->setPartVisible(static_cast<int>(i), on);
    osg_->setDropLinesVisible(on);
}

void SceneView::setConstruction(std::vector<ConstructionMark> marks) {
    construction_ = std::move(marks);
    if (osg_) osg_->setConstruction(construction_.empty() ? nullptr : &construction_);
    if (osg_ && visual_) drawComs();
    updateMovingFrame();
    requestFrame();
}

void SceneView::resizeGL(int w, int h) {
    const double r = devicePixelRatioF();
    const int pw = static_cast<int>(w * r), ph = static_cast<int>(h * r);
    window_->resized(0, 0, pw, ph);
    window_->getEventQueue()->windowResize(0, 0, pw, ph);
    viewer_->getCamera()->setViewport(0, 0, pw, ph);
    // A camera nobody moved stays fitted to the view's new shape (a dock laid out again
    // after the fit would otherwise leave it fitted to a shape the view no longer has).
    if (!userMoved_ && framePose_) distance_ = 0;
    applyCamera();
}

std::size_t SceneView::graphObjects() const {
    struct Count : osg::NodeVisitor {
        Count() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
        void apply(osg::Node& node) override {
            ++objects;
            traverse(node);
        }
        std::size_t objects = 0;
    } count;
    if (root_) root_->accept(count);
    return count.objects;
}

void SceneView::paintGL() {
    window_->setDefaultFboId(gl_->defaultFramebufferObject());
    if (osg_ && visual_) {  // labels apart for this camera and pose
        const double r = devicePixelRatioF();
        osg_->placeLabels(*visual_, camera_, static_cast<int>(width() * r), static_cast<int>(height() * r));
    }
    viewer_->frame();
    ++frames_;
    emit frameDrawn();
}

void SceneView::press(QMouseEvent* e) {
    last_ = e->pos();
    dragging_ = e->button();
    if (e->button() == Qt::LeftButton) {
        const int joint = jointAt(e->pos());
        if (joint >= 0) emit jointClicked(joint);
    }
}

}  // namespace ll::ui
