#pragma once
// Each link's share of B, C, g, E_kin and E_pot at a state. The dynamics are linear in
// the links' inertial parameters (mass, centre of mass, inertia tensor), so link i's
// share of any of them is that quantity of the robot with link i's inertials alone: the
// textbook's per-link sums b_jk = Σ_i β_jk⁽ⁱ⁾ and g_j = −Σ_i m_i g₀ᵀ J_P,j⁽ⁱ⁾, evaluated
// numerically (tests/test_link_contributions checks them against the structured form's
// β and γ). What the links leave over belongs to the joints: the motors' armature on
// b_jj and the springs' part of g and E_pot.
//
// Built once per model: n one-link models and their scratch data, so evaluate()
// allocates nothing. Not thread-safe (scratch): one object per thread.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

class LinkContributions {
public:
    // Gravity from `effects` (springs and forces are the joints', not the links').
    LinkContributions(const RobotModel& robot, const Effects& effects);

    int links() const { return static_cast<int>(models_.size()); }
    // Every link's share at (q, q̇); throws std::invalid_argument for wrong sizes.
    void evaluate(const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

    // Link i's share of B(q), C(q, q̇), g(q) (gravity), E_kin and E_pot (gravity), as
    // evaluated last.
    const Eigen::MatrixXd& B(int link) const { return data_[link].B; }
    const Eigen::MatrixXd& C(int link) const { return data_[link].C; }
    const Eigen::VectorXd& g(int link) const { return data_[link].g; }
    double Ekin(int link) const { return Ekin_[link]; }
    double Epot(int link) const { return Epot_[link]; }

    // The links whose share of what `at(*this, i)` picks is not zero at some of `states`
    // seeded random states: the links whose inertial parameters occur in the quantity. A
    // share below 1e-9 of the largest magnitude `family(*this, i)` of its kind seen (the
    // largest entry of B for an entry of B) is rounding: a term that cancels.
    template <class At, class Family>
    std::vector<int> linksIn(At at, Family family, int states = 3);

private:
    std::vector<RobotModel> models_;
    std::vector<RobotData> data_;
    Effects gravity_;
    std::vector<double> Ekin_, Epot_;
};

template <class At, class Family>
std::vector<int> LinkContributions::linksIn(At at, Family family, int states) {
    // at(*this, i): link i's share of the quantity, after evaluate().
    const int n = links();
    std::vector<double> largest(n, 0.0);
    double scale = 0.0;
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd q(n), qd(n);
    for (int s = 0; s < states; ++s) {
        for (int j = 0; j < n; ++j) {
            q[j] = models_[j].joints[j].dh.type == JointType::Revolute ? 3.0 * u(rng) : 0.3 * u(rng);
            qd[j] = u(rng);
        }
        evaluate(q, qd);
        for (int i = 0; i < n; ++i) {
            largest[i] = std::max(largest[i], std::abs(at(*this, i)));
            scale = std::max(scale, std::abs(family(*this, i)));
        }
    }
    std::vector<int> out;
    for (int i = 0; i < n; ++i)
        if (largest[i] > 1e-9 * scale) out.push_back(i);
    return out;
}

}  // namespace ll
