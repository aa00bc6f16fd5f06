#include "core/visual/frame_labels.hpp"

#include <cmath>

namespace ll {

std::vector<LabelBox> frameLabelBoxes(const VisualScene& scene, const CameraView& view, int width, int height, double pixels) {
    const PictureAxes axes = pictureAxes(view);
    const double tanY = axes.tanHalfFovy, aspect = double(width) / height;
    std::vector<LabelBox> boxes;
    for (int k = 0; k < static_cast<int>(scene.frames.size()); ++k) {
        const VisualFrame& frame = scene.frames[static_cast<std::size_t>(k)];
        if (frame.label.empty()) continue;
        const Eigen::Vector3d anchor = frame.pose * Eigen::Vector3d::Constant(-kLabelBack * frame.axisLength);
        const Eigen::Vector3d v = anchor - view.eye;
        const double depth = v.dot(axes.forward);
        if (depth <= 0) continue;
        const double x = (v.dot(axes.right) / (depth * tanY * aspect) + 1) / 2 * width;
        const double y = (1 - v.dot(axes.up) / (depth * tanY)) / 2 * height;
        double textWidth = 0;
        for (char c : frame.label) textWidth += (c == ',' ? 0.38 : 0.70) * pixels;
        boxes.push_back({k, frame.label, x - textWidth, y, x, y + pixels, x, y, frame.labelOffBodies});
    }
    return boxes;
}

std::vector<LabelBox> bodyBoxes(const VisualScene& scene, const CameraView& view, int width, int height) {
    const PictureAxes axes = pictureAxes(view);
    const double tanY = axes.tanHalfFovy, aspect = double(width) / height;
    std::vector<LabelBox> boxes;
    for (const VisualPart& part : scene.parts) {
        if (part.role != PartRole::Body) continue;
        double radius = part.radius;  // of a sphere around the part
        if (part.shape == PartShape::Box) radius = part.box.norm() / 2;
        if (part.shape == PartShape::Cylinder || part.shape == PartShape::Rod) radius = std::hypot(part.radius, part.length / 2);
        const Eigen::Vector3d v = part.pose.translation() - view.eye;
        const double depth = v.dot(axes.forward);
        if (depth <= radius) continue;  // around or behind the eye
        const double x = (v.dot(axes.right) / (depth * tanY * aspect) + 1) / 2 * width;
        const double y = (1 - v.dot(axes.up) / (depth * tanY)) / 2 * height;
        const double r = radius / (depth * tanY) / 2 * height;  // [px]
        boxes.push_back({-1, part.name, x - r, y - r, x + r, y + r, x, y});
    }
    return boxes;
}

void separateLabels(std::vector<LabelBox>& boxes, int width, int height, const std::vector<LabelBox>& bodies) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto free = [&](const LabelBox& b) {
            for (std::size_t j = 0; j < i; ++j)
                if (b.overlaps(boxes[j])) return false;
            if (b.offBodies)
                for (const LabelBox& body : bodies)
                    if (b.overlaps(body)) return false;
            return true;
        };
        if (free(boxes[i])) continue;
        const LabelBox start = boxes[i];
        const double step = 0.6 * (start.bottom - start.top);
        bool placed = false;
        // Rings of 16 directions around the anchor, farther each time.
        const int rings = start.offBodies ? 40 : 12;  // a body may be much larger than a label
        for (int ring = 1; ring <= rings && !placed; ++ring)
            for (int k = 0; k < 16 && !placed; ++k) {
                const double phi = 3.14159265358979323846 * (0.5 + k / 8.0);  // below first, then round
                LabelBox b = start;
                const double dx = ring * step * 1.6 * std::cos(phi), dy = ring * step * std::sin(phi);
                b.left += dx, b.right += dx, b.top += dy, b.bottom += dy;
                const bool inside = b.left >= 0 && b.top >= 0 && b.right <= width && b.bottom <= height;
                if (inside && free(b)) boxes[i] = b, placed = true;
            }
    }
}

}  // namespace ll
