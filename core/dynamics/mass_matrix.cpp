#include "core/dynamics/mass_matrix.hpp"

#include "core/kinematics/jacobians.hpp"
#include "core/model/argument_checks.hpp"

namespace ll {

void computeMassMatrix(const RobotModel& model, RobotData& data) {
    requireDataFor("computeMassMatrix", model, data);
    const int n = data.n;
    // Composite inertias: in one frame they are plain sums, tip to base.
    for (int i = n - 1; i >= 0; --i) {
        data.I_composite[i] = data.I[i];
        if (i + 1 < n) data.I_composite[i] += data.I_composite[i + 1];
    }
    for (int j = 0; j < n; ++j) {
        const Vector6d F = data.I_composite[j] * data.S[j];  // force to accelerate links j..n with joint j
        for (int i = 0; i <= j; ++i) {
            data.B(i, j) = data.S[i].dot(F);
            data.B(j, i) = data.B(i, j);
        }
        data.B(j, j) += model.joints[j].motor.armature();
    }
}

Eigen::MatrixXd massMatrixFromJacobians(const RobotModel& model, const RobotData& data) {
    requireDataFor("massMatrixFromJacobians", model, data);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(data.n, data.n);
    Jacobian J;
    for (int i = 0; i < data.n; ++i) {
        comJacobian(data, i, J);
        const auto Jv = J.topRows<3>();
        const auto Jw = J.bottomRows<3>();
        B += model.joints[i].link.mass * Jv.transpose() * Jv + Jw.transpose() * data.I_li0[i] * Jw;
        B(i, i) += model.joints[i].motor.armature();
    }
    return B;
}

}  // namespace ll
