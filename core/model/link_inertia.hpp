#pragma once
// Mass properties of one link, expressed in its own DH frame (frame i for link i).
#include <Eigen/Core>

namespace ll {

struct LinkInertia {
    double mass = 0.0;                              // m_i [kg], >= 0
    Eigen::Vector3d com = Eigen::Vector3d::Zero();  // centre of mass in frame i [m]
    // Inertia tensor about the COM with the axes of frame i [kg m^2]. Off-diagonal
    // entries are the tensor's own entries (I_xy = -∫xy dm), not the positive
    // "products of inertia" some tables list.
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

}  // namespace ll
