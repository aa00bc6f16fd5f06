#include "core/model/robot_data.hpp"

#include <cmath>

namespace ll {

RobotData::RobotData(const RobotModel& model)
    : n(model.dof()),
      cosAlpha(n),
      sinAlpha(n),
      T_0i(n + 1, Eigen::Isometry3d::Identity()),
      p_ci(n, Eigen::Vector3d::Zero()),
      I_li0(n, Eigen::Matrix3d::Zero()),
      axis(n, Eigen::Vector3d::UnitZ()),
      axisPoint(n, Eigen::Vector3d::Zero()),
      S(n, Vector6d::Zero()),
      I(n),
      I_composite(n),
      B(Eigen::MatrixXd::Zero(n, n)),
      dB_dq(n, Eigen::MatrixXd::Zero(n, n)),
      crossS(n * n, Vector6d::Zero()),
      I_compositeS(n * n, Vector6d::Zero()),
      C(Eigen::MatrixXd::Zero(n, n)),
      g(Eigen::VectorXd::Zero(n)),
      V(n, Vector6d::Zero()),
      A(n, Vector6d::Zero()),
      F(n, Vector6d::Zero()),
      tau(Eigen::VectorXd::Zero(n)),
      h(Eigen::VectorXd::Zero(n)),
      rhs(Eigen::VectorXd::Zero(n)),
      qdd(Eigen::VectorXd::Zero(n)),
      B_llt(n) {
    for (int i = 0; i < n; ++i) {
        cosAlpha[i] = std::cos(model.joints[i].dh.alpha);
        sinAlpha[i] = std::sin(model.joints[i].dh.alpha);
    }
}

}  // namespace ll
