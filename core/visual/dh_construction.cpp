#include "core/visual/dh_construction.hpp"

#include <algorithm>
#include <cmath>

#include "core/kinematics/axes_at_home.hpp"

namespace ll {
namespace {

using Eigen::Vector3d;

// "z" and k as the textbook writes it: z₀, o₁₂.
std::string subscripted(const std::string& symbol, int k) {
    std::string text = symbol;
    for (const char digit : std::to_string(k)) {
        const unsigned code = 0x2080u + static_cast<unsigned>(digit - '0');  // ₀..₉, three bytes in UTF-8
        text += static_cast<char>(0xE0 | (code >> 12));
        text += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        text += static_cast<char>(0x80 | (code & 0x3F));
    }
    return text;
}

// An arrow from `from` along unit `direction`, `length` long, its head two strokes.
ConstructionMark arrow(ConstructionMarkKind kind, const Vector3d& from, const Vector3d& direction, double length, std::string label) {
    const Vector3d tip = from + length * direction, side = direction.unitOrthogonal();
    const Vector3d back = tip - 0.22 * length * direction;
    ConstructionMark m;
    m.kind = kind;
    m.points = {from, tip, back + 0.1 * length * side, tip, back - 0.1 * length * side};
    m.label = std::move(label);
    m.labelAt = from + 1.12 * length * direction;
    return m;
}

double wrapped(double angle) { return std::remainder(angle, 2 * M_PI); }

}  // namespace

DhConstruction::DhConstruction(const RobotModel& robot, std::vector<std::pair<std::string, Eigen::Isometry3d>> overlay)
    : robot_(robot), axes_(axesAtHome(robot)), found_(dhFromAxes(axes_, robot.convention)), overlay_(std::move(overlay)) {
    double reach = axes_.tool.translation().norm();
    for (const DhFrameRule& f : found_.frames) reach = std::max(reach, (f.origin - found_.frames[0].origin).norm());
    scale_ = std::max(reach, 0.05);
}

DhConstructionStep DhConstruction::step(int index) {
    if (index <= 0) return {};
    static constexpr DhRule rules[] = {DhRule::Z, DhRule::Origin, DhRule::X, DhRule::Y};
    return {(index - 1) / 4, rules[(index - 1) % 4]};
}

int DhConstruction::rowsFound(int index) const { return std::clamp((index - 3) / 4, 0, joints()); }

std::vector<int> DhConstruction::rowsDiffering() const {
    std::vector<int> rows;
    for (int i = 0; i < joints(); ++i) {
        const DhRow &own = robot_.joints[static_cast<std::size_t>(i)].dh, &rule = found_.rows[static_cast<std::size_t>(i)];
        const double length = 1e-9 * std::max(1.0, scale_);
        if (std::abs(own.a - rule.a) > length || std::abs(own.d - rule.d) > length || std::abs(wrapped(own.alpha - rule.alpha)) > 1e-9 ||
            std::abs(wrapped(own.theta - rule.theta)) > 1e-9)
            rows.push_back(i + 1);
    }
    return rows;
}

std::vector<int> DhConstruction::linesInUse(int index) const {
    const DhConstructionStep s = step(index);
    std::vector<int> lines;
    if (s.rule == DhRule::Axes) return lines;
    for (const int line : {s.frame, s.frame + 1})  // frame k sits between joints k and k + 1, in both conventions
        if (line >= 1 && line <= joints()) lines.push_back(line);
    return lines;
}

std::vector<ConstructionMark> DhConstruction::marks(int index) const {
    index = std::clamp(index, 0, steps() - 1);
    const int n = joints();
    const DhConstructionStep now = step(index);
    const std::vector<int> inUse = linesInUse(index);
    std::vector<ConstructionMark> out;
    const double half = 0.45 * scale_, length = 0.16 * scale_;
    for (int i = 1; i <= n; ++i) {
        const JointAxis& axis = axes_.axes[static_cast<std::size_t>(i - 1)];
        const Vector3d u = axis.direction.normalized();
        ConstructionMark line;
        line.kind = std::count(inUse.begin(), inUse.end(), i) ? ConstructionMarkKind::AxisInUse : ConstructionMarkKind::Axis;
        line.points = {axis.point - half * u, axis.point + half * u};
        line.label = subscripted("q", i);
        line.labelAt = axis.point + 1.05 * half * u;
        out.push_back(std::move(line));
    }
    for (const auto& [name, frame] : overlay_) {
        static constexpr ConstructionMarkKind kind = ConstructionMarkKind::OverlayFrame;
        for (int c = 0; c < 3; ++c) {
            ConstructionMark axis;
            axis.kind = kind;
            axis.points = {frame.translation(), frame.translation() + 0.6 * length * frame.linear().col(c)};
            if (c == 0) axis.label = name, axis.labelAt = frame.translation() - 0.15 * length * frame.linear().col(2);
            out.push_back(std::move(axis));
        }
    }
    for (int k = 0; k <= n; ++k) {
        const int done = std::clamp(index - 4 * k, 0, 4);
        if (done == 0) continue;
        const bool current = now.rule != DhRule::Axes && now.frame == k;
        const DhFrameRule& f = found_.frames[static_cast<std::size_t>(k)];
        const auto named = [&](const char* symbol) { return current ? subscripted(symbol, k) : std::string(); };
        out.push_back(arrow(ConstructionMarkKind::FrameZ, f.origin, f.z, length, named("z")));
        if (done < 2) continue;
        if (current) {  // the normal the origin came from
            const auto axis = [&](int joint) -> const JointAxis& { return axes_.axes[static_cast<std::size_t>(joint)]; };
            Vector3d from = f.origin, to = f.origin;
            const bool standard = found_.convention == DhConvention::Standard;
            if (k == 0) from = Vector3d::Zero();  // the world's origin, nearest point on z₀
            else if (standard) from = footOn(axis(k - 1).point, axis(k - 1).direction, f.origin);
            else if (k < n) to = footOn(axis(k).point, axis(k).direction, f.origin);
            else from = found_.frames[static_cast<std::size_t>(k - 1)].origin;
            if ((to - from).norm() > 1e-9 * scale_) {
                ConstructionMark normal;
                normal.kind = ConstructionMarkKind::Normal;
                normal.points = {from, to};
                out.push_back(std::move(normal));
            }
        }
        ConstructionMark origin;
        origin.kind = ConstructionMarkKind::Origin;
        origin.points = {f.origin};
        origin.label = current ? subscripted("o", k) : std::to_string(k);
        origin.labelAt = f.origin - 0.12 * length * (f.x + f.z.cross(f.x));
        out.push_back(std::move(origin));
        if (done >= 3) out.push_back(arrow(ConstructionMarkKind::FrameX, f.origin, f.x, length, named("x")));
        if (done >= 4) out.push_back(arrow(ConstructionMarkKind::FrameY, f.origin, f.z.cross(f.x), length, named("y")));
    }
    return out;
}

}  // namespace ll
