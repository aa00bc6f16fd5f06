#include "core/simulation/simulate.hpp"

#include <cmath>
#include <ctime>
#include <optional>
#include <stdexcept>

#include "core/dynamics/energy.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/argument_checks.hpp"
#include "core/simulation/integrators.hpp"
#include "core/simulation/lagrangian_ode.hpp"
#include "core/simulation/robot_ode.hpp"

namespace ll {

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::vector<double> outputTimes(double duration, double rate) {
    const long intervals = std::max(1L, static_cast<long>(std::ceil(duration * rate - 1e-9)));
    std::vector<double> times(intervals + 1);
    for (long k = 0; k < intervals; ++k) times[k] = static_cast<double>(k) / rate;
    times[intervals] = duration;
    return times;
}

namespace {

// Records one sample: state, energies, work of Q. A Lagrangian system's energies come
// from its compiled derivation, a robot's from the numeric dynamics.
class Recorder {
public:
    Recorder(const Scene& scene, Trajectory& trajectory, const LagrangianOde* lagrangian)
        : scene_(scene), traj_(trajectory), lagrangian_(lagrangian), data_(scene.robot) {
        traj_.n = scene.dof();
        for (int i = 0; i < traj_.n; ++i) {
            if (scene.lagrangian) {
                traj_.names.push_back(scene.lagrangian->coordinates[i]);
            } else {
                traj_.names.emplace_back("q");
                traj_.names.back().append(std::to_string(i + 1));
            }
        }
    }

    // False (and nothing recorded) when an energy is not finite: no sample shows inf.
    bool record(double t, const OdeState& x) {
        const int n = traj_.n;
        Eigen::VectorXd q(n), qd(n);
        for (int i = 0; i < n; ++i) {
            q[i] = x[i];
            qd[i] = x[n + i];
        }
        double Ekin = 0.0, Epot = 0.0;
        if (lagrangian_) {
            lagrangian_->model().energies(x.data(), Ekin, Epot);
        } else {
            forwardKinematics(scene_.robot, data_, q);
            computeMassMatrix(scene_.robot, data_);
            Ekin = kineticEnergy(data_, qd);
            Epot = potentialEnergy(scene_.robot, data_, scene_.effects, q);
        }
        if (!std::isfinite(Ekin) || !std::isfinite(Epot)) {
            problem_ = message(MessageId::EnergyBecameNonFinite, std::isfinite(Ekin) ? "E_pot" : "E_kin",
                               std::to_string(std::isfinite(Ekin) ? Epot : Ekin), std::to_string(t));
            return false;
        }
        traj_.t.push_back(t);
        traj_.q.push_back(q);
        traj_.qd.push_back(qd);
        traj_.Ekin.push_back(Ekin);
        traj_.Epot.push_back(Epot);
        traj_.E.push_back(Ekin + Epot);
        traj_.work.push_back(x[2 * n]);
        return true;
    }
    const Message& problem() const { return problem_; }

private:
    const Scene& scene_;
    Trajectory& traj_;
    const LagrangianOde* lagrangian_;
    RobotData data_;
    Message problem_;
};

void energyBalance(const Trajectory& traj, SimulationStats& stats) {
    if (traj.size() == 0) return;
    double scale = std::abs(traj.E[0]), maxError = 0.0;
    for (size_t k = 0; k < traj.size(); ++k) {
        scale = std::max({scale, traj.Ekin[k], std::abs(traj.Epot[k] - traj.Epot[0])});
        maxError = std::max(maxError, std::abs(traj.E[k] - traj.E[0] - traj.work[k]));
    }
    stats.maxEnergyError = maxError;
    stats.maxRelEnergyError = scale > 0 ? maxError / scale : 0.0;
}

}  // namespace

SimulationResult simulate(SimulationInput input, const SimulationSettings& settings, const ProgressCallback& progress,
                          const std::atomic<bool>* cancel) {
    const Scene& scene = input.scene;
    requireSize("simulate", "initial.q", scene.initial.q.size(), scene.dof(), "the scene", "coordinates");
    requireSize("simulate", "initial.qd", scene.initial.qd.size(), scene.dof(), "the scene", "coordinates");
    if (!scene.lagrangian) requireEffectsFit("simulate", scene.effects, scene.dof());
    const IntegrationSettings& integration = settings;  // the scene's settings extend the integrator's
    if (!findIntegrator(integration.integrator))
        throw std::invalid_argument("unknown integrator '" + settings.integrator + "' (known: " + integratorNames() + ")");

    SimulationResult result;
    result.stats.integrator = settings.integrator;
    const int n = scene.dof();
    std::optional<LagrangianOde> lagrangian;
    std::optional<RobotOde> robot;
    if (scene.lagrangian) {
        if (!input.lagrangian || input.lagrangian->dof() != n)
            throw std::invalid_argument("a Lagrangian scene is simulated from its compiled system "
                                        "(prepareSimulation), which is missing or has the wrong size");
        lagrangian.emplace(std::move(*input.lagrangian));
    } else {
        robot.emplace(scene.robot, scene.effects);
    }
    OdeSystem& ode = lagrangian ? static_cast<OdeSystem&>(*lagrangian) : *robot;
    OdeState x =
        lagrangian ? lagrangian->initialState(scene.initial.q, scene.initial.qd) : robot->initialState(scene.initial.q, scene.initial.qd);
    const std::vector<double> times = outputTimes(settings.duration, settings.outputRate);
    Recorder recorder(scene, result.trajectory, lagrangian ? &*lagrangian : nullptr);

    const auto observe = [&](double t, const OdeState& state) {
        if (!recorder.record(t, state)) {
            result.status = SimulationStatus::Failed;
            const bool adaptive = findIntegrator(settings.integrator)->adaptive;
            result.message = message(MessageId::MotionBlewUp, recorder.problem(), settings.integrator,
                                     Message(adaptive ? MessageId::TightenTolerances : MessageId::StepTooLargeReduceDt));
            return false;
        }
        if (progress) progress(t / settings.duration);
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            result.status = SimulationStatus::Cancelled;
            result.message = message(MessageId::CancelledAtTime, std::to_string(t));
            return false;
        }
        return true;
    };

    const auto book = [&](const IntegrationCounts& counts) {
        SimulationStats& stats = result.stats;
        stats.steps = counts.steps;
        stats.rejectedSteps = counts.rejectedSteps;
        stats.dt = findIntegrator(settings.integrator)->adaptive ? 0.0 : settings.dt;
        stats.lastStep = counts.lastStep;
        stats.eventSteps = counts.eventSteps;
        stats.interpolatedSamples = counts.interpolatedOutputs;
    };
    const double cpuStart = threadCpuSeconds();
    try {
        book(integrate(ode, x, times, integration, observe));
    } catch (const IntegrationError& e) {
        result.status = SimulationStatus::Failed;
        result.message = e.message();
        book(e.counts());
    }
    result.stats.cpuSeconds = threadCpuSeconds() - cpuStart;
    result.stats.rhsEvaluations = lagrangian ? lagrangian->evaluations() : robot->evaluations();
    result.stats.simulatedSeconds = result.trajectory.t.empty() ? 0.0 : result.trajectory.t.back();
    energyBalance(result.trajectory, result.stats);
    // A run that completed but lost its energy balance is not silently right.
    if (result.status == SimulationStatus::Completed && !(result.stats.maxRelEnergyError <= 1e-2))
        result.message = message(MessageId::EnergyBalanceOff, std::to_string(100 * result.stats.maxRelEnergyError));
    return result;
}

}  // namespace ll
