#pragma once
// A scene: everything one scene file holds. One Scene feeds the CLI, the GUI and
// the headless renderer alike.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/exercise.hpp"
#include "core/model/integration_settings.hpp"
#include "core/model/lagrangian_spec.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// The scene's "simulation" block: how to integrate (IntegrationSettings) and what to run.
struct SimulationSettings : IntegrationSettings {
    double duration = 5.0;      // [s]
    double outputRate = 100.0;  // samples per second in the recorded trajectory
};

struct InitialState {
    Eigen::VectorXd q;
    Eigen::VectorXd qd;
};

struct Scene {
    std::string format = "lagrangelab-scene/1";
    std::string name;
    std::string description;
    std::string source;  // where the numbers come from (citation)
    // Named parameters in file order, with their numeric values.
    std::vector<std::pair<std::string, double>> parameters;
    // Fields written as expressions, by field path (e.g. "robot.joints[2].a" ->
    // "l1/2"), so a symbolic derivation can keep the symbols and saving keeps the text.
    std::map<std::string, std::string> expressions;
    RobotModel robot;  // no joints when `lagrangian` is set
    // A system typed by hand as E_kin, E_pot and Q instead of a robot (the file's
    // "lagrangian" block); then effects name its coordinates by number.
    std::optional<LagrangianSpec> lagrangian;
    Effects effects;
    InitialState initial;
    SimulationSettings simulation;
    Exercise exercise;  // the entries a student answers and their answers (may be empty)

    // Number of generalized coordinates: the Lagrangian's, or the robot's joints.
    int dof() const { return lagrangian ? lagrangian->dof() : robot.dof(); }
};

}  // namespace ll
