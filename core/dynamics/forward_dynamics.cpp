#include "core/dynamics/forward_dynamics.hpp"

#include <cmath>

#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/argument_checks.hpp"
#include "core/model/message.hpp"

namespace ll {

int firstSingularJoint(const Eigen::MatrixXd& B, double relTol) {
    const int n = static_cast<int>(B.rows());
    const double scale = B.diagonal().cwiseAbs().maxCoeff();
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd D = Eigen::VectorXd::Zero(n);
    for (int j = 0; j < n; ++j) {
        double dj = B(j, j);
        for (int k = 0; k < j; ++k) dj -= L(j, k) * L(j, k) * D[k];
        if (!(dj > relTol * scale)) return j;
        D[j] = dj;
        for (int i = j + 1; i < n; ++i) {
            double lij = B(i, j);
            for (int k = 0; k < j; ++k) lij -= L(i, k) * L(j, k) * D[k];
            L(i, j) = lij / dj;
        }
    }
    return -1;
}

void factorMassMatrix(RobotData& data) {
    data.B_llt.compute(data.B);
    if (data.B_llt.info() == Eigen::Success) return;
    const int joint = firstSingularJoint(data.B);
    // core/pipeline/scene_evaluation.cpp says the same in the reader's language
    throw SingularMassMatrix(joint, message(MessageId::MassMatrixSingularAtJoint, joint + 1).english());
}

const Eigen::VectorXd& forwardDynamics(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q,
                                       const Eigen::VectorXd& qd, const Eigen::VectorXd& Q) {
    requireSize("forwardDynamics", "qd", qd.size(), model.dof());
    requireSize("forwardDynamics", "Q", Q.size(), model.dof());
    forwardKinematics(model, data, q);
    computeMassMatrix(model, data);
    data.qdd.setZero();
    data.h = rnea(model, data, effects, q, qd, data.qdd);  // C q̇ + g
    data.rhs = Q - data.h;
    factorMassMatrix(data);
    data.qdd = data.rhs;
    data.B_llt.solveInPlace(data.qdd);
    return data.qdd;
}

}  // namespace ll
