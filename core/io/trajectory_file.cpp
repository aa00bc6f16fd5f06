#include "core/io/trajectory_file.hpp"

#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/io/atomic_file.hpp"
#include "core/model/message.hpp"
#include "core/model/message_error.hpp"
#include "core/model/quantity_units.hpp"

namespace ll {

namespace {

// Column names: q1.., qd1.. for robots; a Lagrangian system's own names, x and x_dot.
// (Appending, not "q" + to_string: GCC 12 warns falsely about the latter at -O3.)
std::string indexed(const char* stem, int i) {
    std::string name(stem);
    name.append(std::to_string(i + 1));
    return name;
}

std::string velocityName(const Trajectory& tr, int i) {
    const std::string q = tr.coordinateName(i);
    return q == indexed("q", i) ? indexed("qd", i) : q + "_dot";
}

// The torque columns' stems and values, in the order written.
struct TorquePart {
    const char* stem;
    Eigen::VectorXd (*value)(const TorqueParts&);
};
const TorquePart kTorqueParts[] = {
    {"tau_inertial_", [](const TorqueParts& p) { return p.inertial; }},
    {"tau_coriolis_", [](const TorqueParts& p) { return p.coriolis; }},
    {"tau_potential_", [](const TorqueParts& p) { return p.potential; }},
    {"Q_", [](const TorqueParts& p) { return p.Q(); }},
    {"Q_actuation_", [](const TorqueParts& p) { return p.actuation; }},
    {"Q_viscous_", [](const TorqueParts& p) { return p.viscous; }},
    {"Q_coulomb_", [](const TorqueParts& p) { return p.coulomb; }},
};

// The controller's columns, per joint: stem, value, in the coordinate's unit (else the torque's).
struct ControlPart {
    const char* stem;
    bool coordinate;
    const Eigen::VectorXd ControlParts::*value;
};
const ControlPart kControlParts[] = {
    {"q_ref_", true, &ControlParts::qRef},
    {"e_", true, &ControlParts::error},
    {"tau_ctrl_", false, &ControlParts::tau},
    {"tau_ctrl_inertial_", false, &ControlParts::inertial},
    {"tau_ctrl_coriolis_", false, &ControlParts::coriolis},
    {"tau_ctrl_gravity_", false, &ControlParts::gravity},
    {"tau_ctrl_kp_", false, &ControlParts::proportional},
    {"tau_ctrl_kd_", false, &ControlParts::derivative},
};
// The Lyapunov function's columns (one each), with their units.
struct LyapunovPart {
    const char* name;
    const char* unit;
    const std::vector<double> LyapunovHistory::*value;
};
const LyapunovPart kLyapunovParts[] = {
    {"V", "J", &LyapunovHistory::V},
    {"Vdot", "W", &LyapunovHistory::Vdot},
    {"minus_qdT_Kd_qd", "W", &LyapunovHistory::dissipation},
};

std::string withUnit(const std::string& name, const std::string& unit) { return unit.empty() ? name : name + " [" + unit + "]"; }

}  // namespace

TorqueColumns torqueColumns(const Scene& scene, const TorqueHistory& history) {
    TorqueColumns columns;
    columns.history = &history;
    for (int j = 0; j < scene.dof(); ++j)
        columns.units.push_back(scene.lagrangian ? "" : forceUnit(scene.robot.joints[j].dh.type == JointType::Revolute));
    columns.coordinateUnits = coordinateUnits(scene);
    return columns;
}

std::vector<std::string> coordinateUnits(const Scene& scene) {
    std::vector<std::string> units(static_cast<std::size_t>(scene.dof()));
    if (!scene.lagrangian)
        for (int i = 0; i < scene.dof(); ++i)
            units[static_cast<std::size_t>(i)] =
                coordinateUnit(scene.robot.joints[static_cast<std::size_t>(i)].dh.type == JointType::Revolute);
    return units;
}

void writeTrajectoryCsv(const Trajectory& tr, std::ostream& out, const TorqueColumns& torques, const std::vector<std::string>* units) {
    const auto unitOf = [&](int i) {
        return units && i < static_cast<int>(units->size()) ? (*units)[static_cast<std::size_t>(i)] : std::string();
    };
    out << (units ? "t [s]" : "t");
    for (int i = 0; i < tr.n; ++i) out << ',' << withUnit(tr.coordinateName(i), unitOf(i));
    for (int i = 0; i < tr.n; ++i) out << ',' << withUnit(velocityName(tr, i), unitOf(i).empty() ? "" : unitOf(i) + "/s");
    out << (units ? ",Ekin [J],Epot [J],E [J],W [J]" : ",Ekin,Epot,E,W");
    if (torques.history)
        for (const TorquePart& part : kTorqueParts)
            for (int i = 0; i < tr.n; ++i) out << ',' << withUnit(indexed(part.stem, i), torques.units.at(i));
    if (torques.control) {
        for (const ControlPart& part : kControlParts)
            for (int i = 0; i < tr.n; ++i)
                out << ',' << withUnit(indexed(part.stem, i), part.coordinate ? torques.coordinateUnits.at(i) : torques.units.at(i));
        if (torques.control->lyapunov)
            for (const LyapunovPart& part : kLyapunovParts) out << ',' << withUnit(part.name, part.unit);
    }
    out << '\n';
    char buffer[32];
    const auto put = [&](double v) {
        std::snprintf(buffer, sizeof buffer, "%.17g", v);
        out << buffer;
    };
    for (size_t k = 0; k < tr.size(); ++k) {
        put(tr.t[k]);
        for (int i = 0; i < tr.n; ++i) out << ',', put(tr.q[k][i]);
        for (int i = 0; i < tr.n; ++i) out << ',', put(tr.qd[k][i]);
        out << ',', put(tr.Ekin[k]);
        out << ',', put(tr.Epot[k]);
        out << ',', put(tr.E[k]);
        out << ',', put(tr.work[k]);
        if (torques.history)
            for (const TorquePart& part : kTorqueParts) {
                const Eigen::VectorXd v = part.value(torques.history->parts.at(k));
                for (int i = 0; i < tr.n; ++i) out << ',', put(v[i]);
            }
        if (torques.control) {
            const ControlParts& p = torques.control->parts.at(k);
            for (const ControlPart& part : kControlParts)
                for (int i = 0; i < tr.n; ++i) out << ',', put((p.*part.value)[i]);
            if (const auto& l = torques.control->lyapunov)
                for (const LyapunovPart& part : kLyapunovParts) out << ',', put(((*l).*part.value).at(k));
        }
        out << '\n';
    }
}

void writeTrajectoryJson(const SimulationResult& result, std::ostream& out, const TorqueColumns& torques) {
    const Trajectory& tr = result.trajectory;
    nlohmann::ordered_json j;
    j["t"] = tr.t;
    for (int i = 0; i < tr.n; ++i) {
        std::vector<double> column(tr.size());
        for (size_t k = 0; k < tr.size(); ++k) column[k] = tr.q[k][i];
        j[tr.coordinateName(i)] = column;
    }
    for (int i = 0; i < tr.n; ++i) {
        std::vector<double> column(tr.size());
        for (size_t k = 0; k < tr.size(); ++k) column[k] = tr.qd[k][i];
        j[velocityName(tr, i)] = column;
    }
    j["Ekin"] = tr.Ekin;
    j["Epot"] = tr.Epot;
    j["E"] = tr.E;
    j["W"] = tr.work;
    if (torques.history) {
        nlohmann::ordered_json units;
        for (const TorquePart& part : kTorqueParts)
            for (int i = 0; i < tr.n; ++i) {
                std::vector<double> column(tr.size());
                for (size_t k = 0; k < tr.size(); ++k) column[k] = part.value(torques.history->parts.at(k))[i];
                j[indexed(part.stem, i)] = column;
                units[indexed(part.stem, i)] = torques.units.at(i);
            }
        if (torques.control) {
            for (const ControlPart& part : kControlParts)
                for (int i = 0; i < tr.n; ++i) {
                    std::vector<double> column(tr.size());
                    for (size_t k = 0; k < tr.size(); ++k) column[k] = (torques.control->parts.at(k).*part.value)[i];
                    j[indexed(part.stem, i)] = column;
                    units[indexed(part.stem, i)] = part.coordinate ? torques.coordinateUnits.at(i) : torques.units.at(i);
                }
            if (const auto& l = torques.control->lyapunov)
                for (const LyapunovPart& part : kLyapunovParts) {
                    j[part.name] = (*l).*part.value;
                    units[part.name] = part.unit;
                }
        }
        j["units"] = units;
        j["largest_residual"] = torques.history->largestResidual;
    }
    const SimulationStats& s = result.stats;
    j["stats"] = {{"integrator", s.integrator},           {"steps", s.steps},
                  {"rejected_steps", s.rejectedSteps},    {"rhs_evaluations", s.rhsEvaluations},
                  {"cpu_seconds", s.cpuSeconds},          {"simulated_seconds", s.simulatedSeconds},
                  {"max_energy_error", s.maxEnergyError}, {"max_rel_energy_error", s.maxRelEnergyError}};
    if (s.dt > 0)  // a fixed-step method: its grid, and which samples lie between step ends
        j["stats"]["fixed_step"] = {{"dt", s.dt},
                                    {"last_step", s.lastStep},
                                    {"event_steps", s.eventSteps},
                                    {"interpolated_samples", s.interpolatedSamples},
                                    {"interpolation",
                                     "cubic Hermite from q, qd, qdd at the step ends; energies at the interpolated state"}};
    j["status"] = result.status == SimulationStatus::Completed   ? "completed"
                  : result.status == SimulationStatus::Cancelled ? "cancelled"
                                                                 : "failed";
    if (!result.message.empty()) j["message"] = result.message.english();
    out << j.dump(1) << '\n';
}

void saveTrajectory(const SimulationResult& result, const std::string& path, const TorqueColumns& torques) {
    const bool json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
    const bool csv = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
    if (!json && !csv) throw MessageError(message(MessageId::TrajectoryFileExtension, path));
    saveFileAtomically(
        path,
        [&](std::ostream& out) {
            if (json) writeTrajectoryJson(result, out, torques);
            else writeTrajectoryCsv(result.trajectory, out, torques);
        },
        Backup::None);
}

}  // namespace ll
