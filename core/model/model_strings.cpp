#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/model/dh_row.hpp"
#include "core/model/effects.hpp"

namespace ll {

const char* toString(DhConvention convention) { return convention == DhConvention::Standard ? "standard" : "modified"; }

const char* toString(JointType type) { return type == JointType::Revolute ? "revolute" : "prismatic"; }

const char* toString(TorqueKind kind) {
    switch (kind) {
        case TorqueKind::Constant: return "constant";
        case TorqueKind::Step: return "step";
        case TorqueKind::Sine: return "sine";
        case TorqueKind::Ramp: return "ramp";
    }
    return "?";
}

const char* toString(CoulombModel model) { return model == CoulombModel::Tanh ? "tanh" : "stick"; }

double JointTorque::operator()(double t) const {
    switch (kind) {
        case TorqueKind::Constant: return value;
        case TorqueKind::Step: return t >= at ? value : 0.0;
        case TorqueKind::Sine: return amplitude * std::sin(2.0 * std::numbers::pi * frequency * t + phase);
        case TorqueKind::Ramp: return t >= start ? slope * (t - start) : 0.0;
    }
    return 0.0;
}

std::vector<int> actuatedJoints(const Effects& effects, int dof) {
    std::vector<int> joints;
    for (const JointTorque& torque : effects.torques)
        if (torque.joint >= 0 && torque.joint < dof) joints.push_back(torque.joint);
    if (effects.control)  // a controller drives its joints (all unless it names them)
        for (int i = 0; i < dof; ++i)
            if (effects.control->drives(i)) joints.push_back(i);
    std::sort(joints.begin(), joints.end());
    joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
    return joints;
}

}  // namespace ll
