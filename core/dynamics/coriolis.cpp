#include "core/dynamics/coriolis.hpp"

#include <algorithm>

#include "core/model/argument_checks.hpp"

namespace ll {

void computeMassMatrixDerivatives(const RobotModel& model, RobotData& data) {
    requireDataFor("computeMassMatrixDerivatives", model, data);
    const int n = data.n;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i) data.crossS[k * n + i] = crossMotion(data.S[k], data.S[i]);
    for (int b = 0; b < n; ++b)
        for (int j = 0; j < n; ++j) data.I_compositeS[b * n + j] = data.I_composite[b] * data.S[j];

    for (int k = 0; k < n; ++k) {
        Eigen::MatrixXd& dB = data.dB_dq[k];
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i <= j; ++i) {
                const int a = j;  // max(i, j)
                const int b = std::max(a, k);
                const Vector6d& X_ki = data.crossS[k * n + i];
                const Vector6d& X_kj = data.crossS[k * n + j];
                // Moving the axes S_i, S_j ...
                double value = 0.0;
                if (k < i) value += X_ki.dot(data.I_compositeS[a * n + j]);
                if (k < j) value += data.I_compositeS[a * n + i].dot(X_kj);
                // ... and the links b..n that joint k carries.
                value -= X_ki.dot(data.I_compositeS[b * n + j]) + data.I_compositeS[b * n + i].dot(X_kj);
                dB(i, j) = value;
                dB(j, i) = value;
            }
        }
    }
}

void computeCoriolisMatrix(const RobotModel& model, RobotData& data, const Eigen::VectorXd& qd) {
    requireSize("computeCoriolisMatrix", "qd", qd.size(), data.n);
    computeMassMatrixDerivatives(model, data);
    christoffelMatrix<double>(data.n, data.dB_dq, qd, data.C);
}

}  // namespace ll
