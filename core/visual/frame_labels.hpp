#pragma once
// Where the DH frames' labels ("0", "1,2", "4,5,6") stand in a picture, renderer-neutral:
// each is drawn at a point behind its frame's origin (kLabelBack of the triad's length
// along −x, −y and −z of the frame) with its top-right corner there, at a fixed height in
// pixels. What a test checks for overlaps and the renderers place by (ui/osg_scene).
#include <cmath>
#include <string>
#include <vector>

#include "core/visual/camera_view.hpp"
#include "core/visual/visual_scene.hpp"

namespace ll {

constexpr double kLabelBack = 0.12;  // of the frame's axis length

struct LabelBox {
    int frame = -1;
    std::string text;
    double left = 0, top = 0, right = 0, bottom = 0;  // [px], y down, in a width × height picture
    double anchorX = 0, anchorY = 0;                  // [px] where the label belongs (its box's top-right before moving)
    bool offBodies = false;                           // kept clear of the bodies' boxes (VisualFrame::labelOffBodies)
    bool moved() const { return std::abs(right - anchorX) > 0.5 || std::abs(top - anchorY) > 0.5; }
    bool overlaps(const LabelBox& other) const {
        return left < other.right && other.left < right && top < other.bottom && other.top < bottom;
    }
};

// The boxes of the labelled frames at the scene's current pose seen through `view` in a
// picture of width × height pixels, labels `pixels` high (bold sans: a digit 0.70 of the
// height wide, a comma 0.38). Labels behind the eye are left out.
std::vector<LabelBox> frameLabelBoxes(const VisualScene& scene, const CameraView& view, int width, int height, double pixels);

// The boxes the bodies of a typed system (PartRole::Body) cover in the same picture: the
// square around each one's bounding sphere. Empty for a robot.
std::vector<LabelBox> bodyBoxes(const VisualScene& scene, const CameraView& view, int width, int height);

// Moves labels that would overlap an earlier one (in frame order), or for a label kept off
// the bodies one of `bodies`, to the nearest free place, trying rings of positions around
// its anchor a label height apart; a moved label is drawn with a leader line from its
// anchor (ui/osg_scene). Boxes stay inside the width × height picture where they can.
void separateLabels(std::vector<LabelBox>& boxes, int width, int height, const std::vector<LabelBox>& bodies = {});

}  // namespace ll
