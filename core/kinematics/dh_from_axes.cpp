#include "core/kinematics/dh_from_axes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ll {
namespace {

using Eigen::Vector3d;

struct Line {
    Vector3d point, direction;  // direction of unit length
};

Vector3d footOn(const Line& line, const Vector3d& p) { return ll::footOn(line.point, line.direction, p); }

// x ⊥ z, of unit length: `preferred` with its z part taken out, else `fallback`'s.
Vector3d perpendicular(const Vector3d& preferred, const Vector3d& fallback, const Vector3d& z) {
    for (const Vector3d& v : {preferred, fallback, Vector3d(Vector3d::UnitX()), Vector3d(Vector3d::UnitY())}) {
        const Vector3d w = v - v.dot(z) * z;
        if (w.norm() > 1e-6) return w.normalized();
    }
    return z.unitOrthogonal();
}

// Where the common normal of `from` and `to` meets each line, and which case the pair is.
// Lines closer than `tolerance` meet; directions within 1e-9 rad are parallel.
struct CommonNormal {
    AxisPair pair = AxisPair::Skew;
    Vector3d onFrom, onTo;  // its feet (for parallel lines: the caller chooses)
    Vector3d x;             // unit, from `from` towards `to` (skew); z_from × z_to (intersecting)
};

CommonNormal commonNormal(const Line& from, const Line& to, double tolerance) {
    CommonNormal n;
    const Vector3d cross = from.direction.cross(to.direction);
    if (cross.norm() < 1e-9) {
        n.pair = AxisPair::Parallel;
        return n;
    }
    // Closest points: minimise |from.point + s u − to.point − t v|.
    const Vector3d w = from.point - to.point;
    const double b = from.direction.dot(to.direction), d = from.direction.dot(w), e = to.direction.dot(w);
    const double denominator = 1.0 - b * b;
    const double s = (b * e - d) / denominator, t = (e - b * d) / denominator;
    n.onFrom = from.point + s * from.direction;
    n.onTo = to.point + t * to.direction;
    const Vector3d between = n.onTo - n.onFrom;
    if (between.norm() > tolerance) {
        n.x = between.normalized();
    } else {
        n.pair = AxisPair::Intersecting;
        n.x = cross.normalized();
        n.onTo = n.onFrom;
    }
    return n;
}

double angleAbout(const Vector3d& from, const Vector3d& to, const Vector3d& axis) {
    return std::atan2(from.cross(to).dot(axis), from.dot(to));
}

// Frame 0, in both conventions: the world's frame as far as joint 1's line allows: z_0
// along it, the origin at the foot of the world's origin, x_0 the world's x (else y) made
// perpendicular. A robot standing on the world's origin with joint 1 along its z has no
// base transform.
DhFrameRule frameZero(const Line& first) {
    DhFrameRule f;
    f.z = first.direction;
    f.origin = footOn(first, Vector3d::Zero());
    f.x = perpendicular(Vector3d::UnitX(), Vector3d::UnitY(), f.z);
    return f;
}

// Of the two directions of z_a × z_b, the one not opposite to x_{i-1}: θ_i = 0 at home
// where the choice allows (the PUMA's α5 = −π/2 with θ5 = 0, not +π/2 with θ5 = π).
Vector3d intersectingX(const Vector3d& x, const Vector3d& previousX) { return x.dot(previousX) < -1e-12 ? Vector3d(-x) : x; }

// The standard frames: z_{i-1} on joint i's line; frame n at the tool's origin with z_n = z_{n-1}.
void standardFrames(const std::vector<Line>& lines, const Eigen::Isometry3d& tool, double tolerance, std::vector<DhFrameRule>& frames) {
    const std::size_t n = lines.size();
    frames[0] = frameZero(lines[0]);
    for (std::size_t i = 1; i < n; ++i) {  // frame i from the lines of joints i and i + 1
        const Line &from = lines[i - 1], &to = lines[i];
        DhFrameRule& f = frames[i];
        const DhFrameRule& prev = frames[i - 1];
        f.z = to.direction;
        const CommonNormal normal = commonNormal(from, to, tolerance);
        f.pair = normal.pair;
        if (normal.pair != AxisPair::Parallel) {
            f.origin = normal.onTo;
            f.x = normal.pair == AxisPair::Intersecting ? intersectingX(normal.x, prev.x) : normal.x;
        } else {
            f.antiparallel = from.direction.dot(to.direction) < 0;
            f.origin = footOn(to, prev.origin);  // the normal through o_{i-1}: d_i = 0
            const Vector3d between = f.origin - prev.origin;
            if (between.norm() > tolerance) {
                f.x = between.normalized();
            } else {
                f.pair = AxisPair::Coincident;
                f.origin = prev.origin;
                f.x = prev.x;
            }
        }
    }
    // Frame n: on the tool's origin, z_n along the last joint's line; x_n from that line to
    // the tool's origin (a_n), or x_{n-1} when the tool's origin is on it (θ_n = 0 at home).
    DhFrameRule& last = frames[n];
    last.pair = AxisPair::Last;
    last.z = lines[n - 1].direction;
    last.origin = tool.translation();
    const Vector3d offset = last.origin - footOn(lines[n - 1], last.origin);
    last.x = offset.norm() > tolerance ? Vector3d(offset.normalized()) : frames[n - 1].x;
}

// The modified frames: z_i on joint i's line, the origin at the foot of the common normal
// to the next line; frame n's origin where x_{n-1} meets the last line, x_n = x_{n-1}
// (d_n = 0 and θ_n = 0 at home, as Craig chooses).
void modifiedFrames(const std::vector<Line>& lines, double tolerance, std::vector<DhFrameRule>& frames) {
    const std::size_t n = lines.size();
    frames[0] = frameZero(lines[0]);
    Vector3d previousOrigin = frames[0].origin;  // o_{i-1}
    Vector3d previousX = frames[0].x;
    for (std::size_t i = 1; i <= n; ++i) {
        const Line& line = lines[i - 1];
        DhFrameRule& f = frames[i];
        f.z = line.direction;
        const Vector3d met = footOn(line, previousOrigin);  // where x_{i-1} meets this line
        if (i == n) {
            f.pair = AxisPair::Last;
            f.origin = met;
            f.x = perpendicular(previousX, Vector3d::UnitX(), f.z);
            break;
        }
        const Line& next = lines[i];
        const CommonNormal normal = commonNormal(line, next, tolerance);
        f.pair = normal.pair;
        if (normal.pair != AxisPair::Parallel) {
            f.origin = normal.onFrom;
            f.x = normal.pair == AxisPair::Intersecting ? intersectingX(normal.x, previousX) : normal.x;
        } else {
            f.antiparallel = line.direction.dot(next.direction) < 0;
            f.origin = met;  // d_i = 0
            const Vector3d between = footOn(next, met) - met;
            if (between.norm() > tolerance) {
                f.x = between.normalized();
            } else {
                f.pair = AxisPair::Coincident;
                f.x = perpendicular(previousX, Vector3d::UnitX(), f.z);
            }
        }
        previousOrigin = f.origin;
        previousX = f.x;
    }
}

}  // namespace

Eigen::Isometry3d DhFrameRule::transform() const {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear().col(0) = x;
    T.linear().col(1) = z.cross(x);
    T.linear().col(2) = z;
    T.translation() = origin;
    return T;
}

Vector3d footOn(const Vector3d& point, const Vector3d& direction, const Vector3d& p) {
    const Vector3d u = direction.normalized();
    return point + (p - point).dot(u) * u;
}

DhFromAxes dhFromAxes(const AxesDescription& robot, DhConvention convention) {
    const std::size_t n = robot.axes.size();
    if (n == 0) throw std::invalid_argument("dhFromAxes: no joints");
    std::vector<Line> lines;
    double scale = robot.tool.translation().norm();
    for (std::size_t i = 0; i < n; ++i) {
        const JointAxis& axis = robot.axes[i];
        const double length = axis.direction.norm();
        if (!std::isfinite(length) || length == 0.0 || !axis.point.allFinite())
            throw std::invalid_argument("dhFromAxes: joint " + std::to_string(i + 1) + " has no axis direction");
        lines.push_back({axis.point, axis.direction / length});
        scale = std::max(scale, axis.point.norm());
    }
    const double tolerance = 1e-9 * std::max(1.0, scale);

    DhFromAxes out;
    out.convention = convention;
    out.frames.resize(n + 1);
    if (convention == DhConvention::Standard) standardFrames(lines, robot.tool, tolerance, out.frames);
    else modifiedFrames(lines, tolerance, out.frames);

    const bool standard = convention == DhConvention::Standard;
    for (std::size_t i = 1; i <= n; ++i) {
        const DhFrameRule &prev = out.frames[i - 1], &cur = out.frames[i];
        const Vector3d step = cur.origin - prev.origin;
        DhRow row;
        row.type = robot.axes[i - 1].type;
        if (standard) {  // A_i = Rot_z(θ_i) Trans_z(d_i) Trans_x(a_i) Rot_x(α_i)
            row.theta = angleAbout(prev.x, cur.x, prev.z);
            row.d = step.dot(prev.z);
            row.a = step.dot(cur.x);
            row.alpha = angleAbout(prev.z, cur.z, cur.x);
        } else {  // A_i = Rot_x(α_{i-1}) Trans_x(a_{i-1}) Rot_z(θ_i) Trans_z(d_i)
            row.alpha = angleAbout(prev.z, cur.z, prev.x);
            row.a = step.dot(prev.x);
            row.theta = angleAbout(prev.x, cur.x, cur.z);
            row.d = step.dot(cur.z);
        }
        out.rows.push_back(row);
    }
    out.base = out.frames[0].transform();
    out.tool = out.frames[n].transform().inverse() * robot.tool;
    return out;
}

Eigen::Isometry3d toolPoseFromAxes(const AxesDescription& robot, const Eigen::VectorXd& q) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    for (std::size_t i = 0; i < robot.axes.size(); ++i) {
        const JointAxis& axis = robot.axes[i];
        const Vector3d u = axis.direction.normalized();
        Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
        if (axis.type == JointType::Revolute) {
            M.linear() = Eigen::AngleAxisd(q[static_cast<Eigen::Index>(i)], u).toRotationMatrix();
            M.translation() = axis.point - M.linear() * axis.point;  // about the line through `point`
        } else {
            M.translation() = q[static_cast<Eigen::Index>(i)] * u;
        }
        T = T * M;
    }
    return T * robot.tool;
}

}  // namespace ll
