#include "core/visual/frame_labels.hpp"

#include <cmath>

namespace ll {

std::vector<LabelBox> frameLabelBoxes(const VisualScene& scene, const CameraView& view, int width, int height, double pixels) {
    const Eigen::Vector3d forward = (view.centre - view.eye).normalized();
    const Eigen::Vector3d right = forward.cross(view.up).normalized();
    const Eigen::Vector3d up = right.cross(forward);
    const double tanY = std::tan(view.fovy * 3.14159265358979323846 / 360.0), aspect = double(width) / height;
    std::vector<LabelBox> boxes;
    for (int k = 0; k < static_cast<int>(scene.frames.size()); ++k) {
        const VisualFrame& frame = scene.frames[static_cast<std::size_t>(k)];
        if (frame.label.empty()) continue;
        const Eigen::Vector3d anchor = frame.pose * Eigen::Vector3d::Constant(-kLabelBack * frame.axisLength);
        const Eigen::Vector3d v = anchor - view.eye;
        const double depth = v.dot(forward);
        if (depth <= 0) continue;
        const double x = (v.dot(right) / (depth * tanY * aspect) + 1) / 2 * width;
        const double y = (1 - v.dot(up) / (depth * tanY)) / 2 * height;
        double textWidth = 0;
        for (char c : frame.label) textWidth += (c == ',' ? 0.38 : 0.70) * pixels;
        boxes.push_back({k, frame.label, x - textWidth, y, x, y + pixels});
    }
    return boxes;
}

}  // namespace ll
