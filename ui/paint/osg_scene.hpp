#pragma once
// The OpenSceneGraph nodes of a VisualScene, built once: lit solids, x/y/z triads in
// red/green/blue with optional frame labels, a ground grid and an end-effector trail.
// Per frame only the part transforms and the trail change (update, setTrail). Knows no
// GL context: the headless renderer (ui/paint/headless_renderer.hpp) and the desktop
// window's 3D view (a native QOpenGLWindow) draw the same root.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <osg/Camera>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Group>
#include <osg/MatrixTransform>
#include <osg/Switch>
#include <osgText/Text>

#include "core/visual/camera_view.hpp"
#include "core/visual/dh_construction.hpp"
#include "core/visual/visual_emphasis.hpp"
#include "core/visual/visual_scene.hpp"

namespace ll::ui {

struct OsgSceneOptions {
    bool frames = true;       // DH triads
    bool frameLabels = true;  // their numbers beside them
    bool trail = true;        // the end effector's recent path
    bool grid = true;         // the ground grid
    bool dropLines = true;    // a line from each centre of mass down to the ground, a dot at its foot
    double labelPixels = 18;  // label height on screen [px]
    bool look = true;         // the robot's own look (its meshes and shapes) instead of the DH drawing, where it has one
    std::string meshDirectory;  // where a relative mesh path starts: the scene file's folder
};

class OsgScene {
public:
    explicit OsgScene(const VisualScene& scene, const OsgSceneOptions& options = {});

    osg::Group* root() const { return root_.get(); }
    // Copies the poses of `scene` (the one built from, posed anew) into the transforms.
    void update(const VisualScene& scene);
    // Lays the ground grid anew (after VisualScene::fitToMotion moved it).
    void updateGround(const VisualScene& scene);
    // The trail through `points`, oldest first, fading towards the oldest. At most
    // `maxTrailPoints` are drawn (the newest).
    void setTrail(const std::vector<Eigen::Vector3d>& points);
    static constexpr int maxTrailPoints = 2048;

    // The transform of part i (what a test reads back as "drawn").
    const osg::MatrixTransform* partTransform(int i) const { return parts_[i].get(); }
    // The robot's own look (PartRole::Look: a URDF's meshes and shapes) instead of the DH
    // links, joints and pedestal, or the DH drawing back. Shown only when every mesh was
    // read: one that was not (meshFailures) leaves the DH drawing.
    void setShowLook(bool on);
    bool hasLook() const;
    bool showsLook() const { return showsLook_; }
    const std::vector<std::string>& meshFailures() const { return meshFailures_; }
    // Shows or hides part i (the window's centre-of-mass toggle).
    void setPartVisible(int i, bool on);
    // Draws part i in the highlight colour (a joint selected or hovered in the window).
    void setPartHighlighted(int i, bool on);
    // The DH step-through's moving frame: a triad 1.8× the frames' size drawn over the
    // solids at `pose`; null hides it.
    void setMovingFrame(const Eigen::Isometry3d* pose);
    // The DH table drawn on the robot (core/visual/dh_dimensions.hpp): arrows and arcs
    // with their labels, over the solids, a colour per kind of parameter; null removes them.
    void setDimensions(const std::vector<DhDimension>* dimensions);
    // Step 0 rule by rule (core/visual/dh_construction.hpp): the joints' lines, the normals
    // and the frames placed so far, over the solids; null removes them.
    void setConstruction(const std::vector<ConstructionMark>* marks);
    // Shows or hides the drop lines (with the centres of mass they hang from).
    void setDropLinesVisible(bool on);
    // Places the frame labels for a picture of width × height seen through `view`
    // (core/visual/frame_labels.hpp): each at its frame, or, where it would overlap an
    // earlier one, moved to the nearest free place with a leader line back to its frame.
    // Called before every frame is drawn (the camera or the pose may have changed).
    void placeLabels(const VisualScene& scene, const CameraView& view, int width, int height);
    // Shows or hides DH frame k's triad and label (the step-through keeps frames i−1 and i).
    void setFrameVisible(int k, bool on);
    // A picked entry's links in their colour by share, the others faded, the axes of the
    // joints it depends on (core/visual/visual_emphasis.hpp); an inactive one undoes it.
    void setEmphasis(const VisualEmphasis& emphasis);

private:
    OsgSceneOptions options_;
    osg::ref_ptr<osg::Group> root_;
    osg::ref_ptr<osg::Group> groundGroup_;
    std::vector<osg::ref_ptr<osg::MatrixTransform>> parts_, frames_;
    std::vector<bool> stretch_;
    std::vector<PartRole> roles_;
    std::vector<std::string> meshFailures_;  // "path: why", one per mesh not read
    bool showsLook_ = false;
    std::vector<Rgba> built_;                               // each part's colour as built
    std::vector<Rgba> colours_;                             // and when its link is emphasised
    std::vector<osg::ref_ptr<osg::MatrixTransform>> axes_;  // per part: a joint's axis line (null elsewhere)
    std::vector<osg::ref_ptr<osg::Geode>> axisGeodes_;
    osg::ref_ptr<osg::Geometry> trail_;
    osg::ref_ptr<osg::MatrixTransform> moving_;
    osg::ref_ptr<osg::Geometry> drops_;
    osg::ref_ptr<osg::Group> dimensions_, construction_;
    std::vector<osg::ref_ptr<osgText::Text>> labels_;     // per frame (null: no label)
    std::vector<osg::ref_ptr<osg::Geode>> leaderGeodes_;  // per frame: the line anchor → moved label
    osg::ref_ptr<osg::Geode> dropGeode_;
    double frameLength_ = 0.1;
};

// Sets `camera`'s view and projection to `view` for a picture of width/height `aspect`.
void applyCameraView(osg::Camera& camera, const CameraView& view, double aspect);

}  // namespace ll::ui
