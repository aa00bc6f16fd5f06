#include "core/visual/trajectory_sampler.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace ll {

TrajectorySampler::TrajectorySampler(const Trajectory& trajectory) : trajectory_(trajectory) { assert(trajectory.size() > 0); }

double TrajectorySampler::startTime() const { return trajectory_.t.front(); }
double TrajectorySampler::endTime() const { return trajectory_.t.back(); }

int TrajectorySampler::locate(double t, double& s) const {
    const std::vector<double>& times = trajectory_.t;
    const int last = static_cast<int>(times.size()) - 1;
    if (last == 0 || t <= times.front()) {
        s = 0.0;
        return 0;
    }
    if (t >= times.back()) {
        s = 1.0;
        return last - 1;
    }
    const int k = static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    s = (t - times[k]) / (times[k + 1] - times[k]);
    return k;
}

void TrajectorySampler::sample(double t, Eigen::VectorXd& q, Eigen::VectorXd& qd) const {
    double s = 0.0;
    const int k = locate(t, s);
    if (trajectory_.size() == 1) {
        q = trajectory_.q[0];
        qd = trajectory_.qd[0];
        return;
    }
    const double h = trajectory_.t[k + 1] - trajectory_.t[k];
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    // Derivatives with respect to s; d/dt = (1/h) d/ds.
    const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
    const Eigen::VectorXd &q0 = trajectory_.q[k], &q1 = trajectory_.q[k + 1];
    const Eigen::VectorXd &v0 = trajectory_.qd[k], &v1 = trajectory_.qd[k + 1];
    q.noalias() = h00 * q0 + (h * h10) * v0 + h01 * q1 + (h * h11) * v1;
    qd.noalias() = (d00 / h) * q0 + d10 * v0 + (d01 / h) * q1 + d11 * v1;
}

double TrajectorySampler::scalar(const std::vector<double>& series, double t) const {
    if (series.empty()) return 0.0;
    double s = 0.0;
    const int k = locate(t, s);
    if (series.size() == 1) return series[0];
    return (1 - s) * series[k] + s * series[k + 1];
}

std::vector<double> frameTimes(double start, double duration, double fps, double speed) {
    const long count = std::max(1L, static_cast<long>(std::floor(duration * fps / speed + 1e-9)));
    std::vector<double> times(count);
    for (long k = 0; k < count; ++k) times[k] = start + static_cast<double>(k) * speed / fps;
    return times;
}

}  // namespace ll
