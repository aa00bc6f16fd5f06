#pragma once
// An Eigen vector as a std::vector<double>: what JSON writers and Qt's variant lists take.
#include <vector>

#include <Eigen/Core>

namespace ll {

inline std::vector<double> listOf(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

}  // namespace ll
