#pragma once
// The result of a simulation as plain immutable data: a GUI worker hands it back
// whole, the CLI writes it out, tests read it.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/message.hpp"

namespace ll {

struct Trajectory {
    int n = 0;                        // coordinates
    std::vector<std::string> names;   // (n) coordinate names: q1..qn, or a Lagrangian's own
    std::vector<double> t;            // sample times [s]
    std::vector<Eigen::VectorXd> q;   // (n) per sample
    std::vector<Eigen::VectorXd> qd;  // (n) per sample
    std::vector<double> Ekin, Epot;   // [J]
    std::vector<double> E;            // Ekin + Epot
    std::vector<double> work;         // ∫ Qᵀ q̇ dt: work done by non-conservative forces since t0

    size_t size() const { return t.size(); }
    // names[i], or q<i+1> when names does not have it.
    std::string coordinateName(int i) const {
        if (i < static_cast<int>(names.size())) return names[i];
        std::string name = "q";  // (appended: GCC 12 warns falsely about "q" + to_string at -O3)
        return name.append(std::to_string(i + 1));
    }
};

struct SimulationStats {
    std::string integrator;
    long steps = 0;           // accepted steps
    long rejectedSteps = 0;   // adaptive methods only
    long rhsEvaluations = 0;  // forward-dynamics evaluations
    double cpuSeconds = 0.0;  // CPU time of this thread spent integrating
    // Steps that ended early at a located event (included in steps), or for adaptive
    // methods also at a corner (OdeSystem::cornerFraction). Fixed-step methods (0 for
    // adaptive ones): the step dt [s] they took on the grid
    // t_k = t0 + k·dt, a last shorter step when the duration is not a multiple of dt, and the samples
    // that lie between step ends (cubic Hermite interpolation of q, q̇ and W from q, q̇,
    // q̈ at the step ends; energies evaluated at the interpolated state).
    double dt = 0.0;
    double lastStep = 0.0;
    long eventSteps = 0;
    long interpolatedSamples = 0;
    double simulatedSeconds = 0.0;
    // Energy balance: E(t) − E(0) − W(t) is zero for the exact solution (W = work of
    // Q). Max absolute value, and relative to the energy scale of the motion
    // (max of |E(0)|, max E_kin, max |E_pot − E_pot(0)|).
    double maxEnergyError = 0.0;
    double maxRelEnergyError = 0.0;
};

enum class SimulationStatus { Completed, Cancelled, Failed };

struct SimulationResult {
    Trajectory trajectory;
    SimulationStats stats;
    SimulationStatus status = SimulationStatus::Completed;
    Message message;  // why it stopped early: time, state and what to try; for a completed run,
                      // a warning when the energy balance is off by more than 1 %; empty: none
};

}  // namespace ll
