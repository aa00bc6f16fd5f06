#pragma once
// Work–precision analysis: what accuracy costs in time, for each integrator and
// tolerance (or fixed step), against a reference solution. Shaped like simulate()
// for a GUI worker thread as much as for the CLI: inputs copied in, progress through
// a callback, a flag cancels, results are plain data (partial when cancelled).
//
// "Error" is the final-state error in the units the tolerances use (abs = rel = tol):
//   max over q_i and q̇_i at t = T of |x_i − x_ref,i| / (1 + |x_ref,i|),
// so an adaptive method asked for tolerance tol should land within a small factor of
// tol. "Energy drift" is max over the run of |E − E0 − W| relative to the energy scale
// of the motion (SimulationStats::maxRelEnergyError).
#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/message.hpp"
#include "core/model/scene.hpp"
#include "core/simulation/simulate.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

struct WorkPrecisionSettings {
    std::vector<std::string> integrators;  // empty: every integrator of the catalogue
    std::vector<double> tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
    std::vector<double> steps = {1e-2, 3e-3, 1e-3, 3e-4, 1e-4};  // fixed-step methods' dt [s]
    double duration = 0.0;                                       // [s]; 0: the scene's
    int repeats = 3;                                             // CPU time is the median over repeats
    double outputRate = 10.0;                                    // energy is sampled at this rate [Hz]
    std::string referenceIntegrator = "fehlberg78";
    double referenceTolerance = 0.0;  // 0: min(tolerances) / 100, at least 1e-14
};

struct WorkPrecisionPoint {
    std::string integrator;
    bool adaptive = false;
    double setting = 0.0;    // tolerance (adaptive) or dt [s] (fixed step)
    bool completed = false;  // false: the run stopped (message says why)
    Message message;
    double finalError = 0.0;        // see the header comment
    bool atReferenceFloor = false;  // finalError is not above the reference's own error estimate
    double maxRelEnergyDrift = 0.0;
    double cpuSeconds = 0.0;  // median over repeats
    long rhsEvaluations = 0;
    long steps = 0;
    long rejectedSteps = 0;
    // The step actually taken [s]: dt for a fixed-step method (on t_k = k·dt whatever the
    // output rate), the mean accepted step duration / steps for an adaptive one.
    double step = 0.0;
    double lastStep = 0.0;  // fixed step: a last shorter step when the duration is not a multiple of dt
};

struct WorkPrecisionReference {
    std::string integrator;
    double tolerance = 0.0;
    // Estimate of the reference's own final-state error: its distance to the same
    // method at 10x the tolerance (an upper estimate, since the error falls with tol).
    double estimatedError = 0.0;
    double maxRelEnergyDrift = 0.0;
    double cpuSeconds = 0.0;
    Eigen::VectorXd finalState;  // [q; q̇] at t = duration
};

struct WorkPrecisionResult {
    std::string scene;
    double duration = 0.0;
    WorkPrecisionReference reference;
    std::vector<WorkPrecisionPoint> points;                 // by integrator, then setting, as requested
    SimulationStatus status = SimulationStatus::Completed;  // Cancelled, or Failed (reference failed)
    Message message;                                        // why it stopped; empty when it completed
    double cpuSeconds = 0.0;                                // the whole analysis, this thread
};

// fraction 0..1 and what is being run ("dopri5 tol 1e-06", "reference fehlberg78 tol 1e-12"),
// from the worker thread.
using WorkPrecisionProgress = std::function<void(double fraction, const Message& what)>;

// The scene must be valid (requireValidScene). Throws std::invalid_argument for an
// unknown integrator name or an empty/non-positive setting list before anything runs.
WorkPrecisionResult runWorkPrecision(const SimulationInput& input, const WorkPrecisionSettings& settings,
                                     const WorkPrecisionProgress& progress = {}, const std::atomic<bool>* cancel = nullptr);

// The error measure above, between the final states of two trajectories ([q; q̇]).
double finalStateError(const Eigen::VectorXd& x, const Eigen::VectorXd& reference);
Eigen::VectorXd finalState(const Trajectory& trajectory);

// One paragraph saying what "error" and "energy drift" mean, for every output.
const char* workPrecisionDefinitions();

}  // namespace ll
