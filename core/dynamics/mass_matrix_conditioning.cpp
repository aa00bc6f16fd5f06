#include "core/dynamics/mass_matrix_conditioning.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "core/math/cholesky.hpp"
#include "core/dynamics/forward_dynamics.hpp"

namespace ll {

namespace {

// A joint "moves nothing" when its b_jj is below this share of what the links it
// carries could give it, or its pivot below this share of b_jj.
constexpr double kNothing = 1e-9;

// The inertia the links j..n carry, in b_jj's unit: their rotational inertia about the
// world origin (revolute) or their mass (prismatic). Zero only when they are massless.
double carriedInertia(const RobotData& data, int j) {
    const SpatialInertia& composite = data.I_composite[j];
    const bool prismatic = data.S[j].head<3>().isZero();
    return prismatic ? composite.m : composite.I.trace();
}

}  // namespace

MassMatrixDefect diagnoseMassMatrix(const RobotData& data, double relTol) {
    MassMatrixDefect defect;
    const Eigen::MatrixXd& B = data.B;
    const int j = firstSingularJoint(B, relTol);
    if (j < 0) return defect;
    defect.joint = j;
    defect.diagonal = B(j, j);
    defect.largest = B.diagonal().maxCoeff();
    defect.pivot = B(j, j);
    if (j > 0) {  // the joints before j passed: their block is positive definite
        const Eigen::VectorXd coupling = B.col(j).head(j);
        defect.pivot -= coupling.dot(Cholesky(j).compute(B.topLeftCorner(j, j)).solve(coupling));
    }
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(B, Eigen::EigenvaluesOnly).eigenvalues();
    defect.condition = eigenvalues[0] > 0 ? eigenvalues[eigenvalues.size() - 1] / eigenvalues[0] : std::numeric_limits<double>::infinity();
    const bool nothingOfItsOwn = !(defect.diagonal > kNothing * carriedInertia(data, j));
    const bool nothingNew = !(defect.pivot > kNothing * defect.diagonal);
    defect.kind = nothingOfItsOwn || nothingNew ? MassMatrixDefect::Kind::MovesNothing : MassMatrixDefect::Kind::IllConditioned;
    return defect;
}

}  // namespace ll
