#pragma once
// A recorded trajectory read at any time t, so animation frames fall at exactly
// t = t0 + k·speed/fps whatever steps the integrator took.
//
// Between samples k and k+1 (h = t_{k+1} − t_k, s = (t − t_k)/h ∈ [0, 1]) q is the cubic
// Hermite interpolant of the recorded q and q̇:
//   q(t) = h00(s) q_k + h h10(s) q̇_k + h01(s) q_{k+1} + h h11(s) q̇_{k+1},
//   h00 = 2s³ − 3s² + 1, h10 = s³ − 2s² + s, h01 = −2s³ + 3s², h11 = s³ − s²,
// exact at the samples and for cubic motions, error O(h⁴) (third-order accurate); q̇ is
// its derivative (error O(h³)). Energies and work are interpolated linearly.
// Outside [t_0, t_N] the first or last sample is returned.
#include <vector>

#include <Eigen/Core>

#include "core/simulation/trajectory.hpp"

namespace ll {

class TrajectorySampler {
public:
    // Keeps a reference: `trajectory` must outlive the sampler. It needs at least one
    // sample and increasing times.
    explicit TrajectorySampler(const Trajectory& trajectory);

    double startTime() const;
    double endTime() const;
    int dof() const { return trajectory_.n; }
    const Trajectory& trajectory() const { return trajectory_; }

    // q(t) and q̇(t); q and qd must have dof() entries (no allocation then).
    void sample(double t, Eigen::VectorXd& q, Eigen::VectorXd& qd) const;
    // A recorded scalar series (Ekin, Epot, E, work) at t, linear between samples.
    double scalar(const std::vector<double>& series, double t) const;

private:
    const Trajectory& trajectory_;
    // Index k of the interval [t_k, t_{k+1}] holding t (clamped), and s in [0, 1].
    int locate(double t, double& s) const;
};

// Times of the frames of an animation of `duration` simulated seconds from `start`,
// played `speed` times as fast as real time (speed < 1: slow motion) at `fps` frames
// per second: t_k = start + k·speed/fps for k = 0 .. N−1, N = the whole frames in
// duration·fps/speed (at least 1). So 1 s at 10 fps gives 10 frames, t = 0 .. 0.9.
std::vector<double> frameTimes(double start, double duration, double fps, double speed);

}  // namespace ll
