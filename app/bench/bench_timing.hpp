#pragma once
// What lagrangelab-bench and the KDL comparison (tests/oracle/bench_kdl.cpp) time the
// same way: seeded random states, the median time per call over batches, and our five
// dynamics quantities on those states.
#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/kinematics/forward_kinematics.hpp"

namespace ll::cli {

struct States {
    std::vector<Eigen::VectorXd> q, qd, tau;
};

inline States randomStates(const RobotModel& robot, int count) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    States s;
    const int n = robot.dof();
    for (int k = 0; k < count; ++k) {
        Eigen::VectorXd q(n), qd(n), tau(n);
        for (int i = 0; i < n; ++i) {
            q[i] = robot.joints[i].dh.type == JointType::Revolute ? 3.0 * u(rng) : 0.2 * u(rng);
            qd[i] = 2.0 * u(rng);
            tau[i] = 5.0 * u(rng);
        }
        s.q.push_back(q);
        s.qd.push_back(qd);
        s.tau.push_back(tau);
    }
    return s;
}

// --batches N read as `n` from `typed`: a whole number from 1 to 1000 (a median needs a
// batch), else std::invalid_argument naming the option and the value as typed.
inline int checkedBatches(double n, const std::string& typed) {
    if (!(n >= 1 && n <= 1000) || n != std::floor(n))
        throw std::invalid_argument("--batches: expected a whole number from 1 to 1000, got '" + typed + "'");
    return static_cast<int>(n);
}

// The median of a list of timings (the upper one of an even count); 0 for none.
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// Milliseconds from a to b.
inline double ms(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

// Median over batches of the time per call [µs]; each batch cycles through the states.
template <class F>
double medianMicros(int batches, int statesCount, F&& call) {
    using clock = std::chrono::steady_clock;
    int perBatch = 64;
    for (;;) {  // calibrate: a batch should take about 2 ms
        const auto start = clock::now();
        for (int r = 0; r < perBatch; ++r) call(r % statesCount);
        if (std::chrono::duration<double>(clock::now() - start).count() > 2e-3 || perBatch > (1 << 22)) break;
        perBatch *= 2;
    }
    std::vector<double> times;
    for (int b = 0; b < batches; ++b) {  // batches ≥ 1: checkedBatches
        const auto start = clock::now();
        for (int r = 0; r < perBatch; ++r) call(r % statesCount);
        times.push_back(std::chrono::duration<double, std::micro>(clock::now() - start).count() / perBatch);
    }
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    return times[times.size() / 2];
}

// Medians [µs] of B (kinematics + CRBA), C (+ the Christoffel matrix), g, forward
// dynamics q̈ = B⁻¹(Q − C q̇ − g) and inverse dynamics (RNEA) over the states.
struct DynamicsTimes {
    double B = 0, C = 0, g = 0, FD = 0, RNEA = 0;
};

inline DynamicsTimes dynamicsTimes(const RobotModel& robot, const Effects& effects, const States& s, int batches) {
    RobotData data(robot);
    const int count = static_cast<int>(s.q.size());
    DynamicsTimes t;
    t.B = medianMicros(batches, count, [&](int k) {
        forwardKinematics(robot, data, s.q[k]);
        computeMassMatrix(robot, data);
    });
    t.C = medianMicros(batches, count, [&](int k) {
        forwardKinematics(robot, data, s.q[k]);
        computeMassMatrix(robot, data);
        computeCoriolisMatrix(robot, data, s.qd[k]);
    });
    t.g = medianMicros(batches, count, [&](int k) {
        forwardKinematics(robot, data, s.q[k]);
        computePotentialGradient(robot, data, effects, s.q[k]);
    });
    t.FD = medianMicros(batches, count, [&](int k) { forwardDynamics(robot, data, effects, s.q[k], s.qd[k], s.tau[k]); });
    t.RNEA = medianMicros(batches, count, [&](int k) { inverseDynamics(robot, data, effects, s.q[k], s.qd[k], s.tau[k]); });
    return t;
}

}  // namespace ll::cli
