#pragma once
// Numbers that look typed in the wrong unit. Data copied from datasheets and CAD
// comes in mm, g and g·mm²; the scene format is SI (m, kg, kg·m²). Each check gives a
// warning naming the field, the value and the likely slip; the model is loaded as
// given (a warning, not a refusal: the number may be right).
//
//  - a, d: longer than 10 m, beyond any arm ("431.8 m: in mm? 431.8 mm = 0.4318 m");
//  - a COM far outside the robot's reach: more than 3 × max(reach, 0.5 m) from its
//    frame's origin, where the reach is Σ|a_i| + |d_i| of the plausible lengths;
//  - a radius of gyration √(I_max/m) over 3 × max(reach, 0.5 m): no link of this robot
//    is that large, so the tensor is probably in g·mm² or kg·mm²;
//  - a link heavier than 1000 kg: probably in g.
// Angles in degrees where radians are expected are found where the file is read
// (core/io/scene_file.cpp), since only there is it known that a number was bare.
#include <string>
#include <vector>

#include "core/model/diagnostics.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

std::vector<Diagnostic> unitSlipWarnings(const RobotModel& model);

}  // namespace ll
