#pragma once
// A scene: everything one scene file holds. One Scene feeds the CLI, the GUI and
// the headless renderer alike.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/lagrangian_spec.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

struct SimulationSettings {
    double duration = 5.0;            // [s]
    std::string integrator = "dopri5";
    double absTol = 1e-8;
    double relTol = 1e-8;
    double dt = 1e-3;                 // fixed step, or first trial step of adaptive methods [s]
    double outputRate = 100.0;        // samples per second in the recorded trajectory
    // Not a scene-file field: explicit adaptive methods stop on a stiff scene unless this is
    // off (the work–precision reference turns it off: it must resolve every mode).
    bool detectStiffness = true;
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

    // Number of generalized coordinates: the Lagrangian's, or the robot's joints.
    int dof() const { return lagrangian ? lagrangian->dof() : robot.dof(); }
};

}  // namespace ll
