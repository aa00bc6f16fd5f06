#pragma once
// The SI units of the quantities a derivation shows, by the types of the joints they
// belong to: b_jk is kg·m² between two revolute joints, kg·m between a revolute and a
// prismatic one, kg between two prismatic ones; g_j and Q_j are N·m or N; c_ij is b_ij's
// unit per second (c_ij q̇_j is a torque or force). One spelling for the window's
// readouts, the teach panel, `simulate --out`'s header and `check`.
#include <string>

namespace ll {

std::string massMatrixUnit(bool revoluteJ, bool revoluteK);
std::string coriolisUnit(bool revoluteI, bool revoluteJ);
std::string forceUnit(bool revolute);         // N·m or N
std::string coordinateUnit(bool revolute);    // rad or m
std::string velocityUnit(bool revolute);      // rad/s or m/s
std::string accelerationUnit(bool revolute);  // rad/s² or m/s²

}  // namespace ll
