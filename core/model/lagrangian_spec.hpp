#pragma once
// A mechanical system typed by hand as a Lagrangian, instead of a robot's DH table:
// the scene's "lagrangian" block. Plain text and numbers; the expressions are parsed
// by core/symbolic/lagrangian_fields.hpp and derived by core/symbolic/lagrangian_derivation.
//
//   coordinates  generalized coordinates q_1..q_n by name ("theta1", "x"): identifiers,
//                unique, not reserved, not a parameter; the velocity of x is x_dot
//                (and its acceleration x_ddot, in the printed equations)
//   kinetic      E_kin(q, q̇): must be ½ q̇ᵀ B(q) q̇ with B positive definite
//   potential    E_pot(q): gravity, springs, every conservative force; no velocities
//   forces       the generalized forces Q_i(q, q̇, t), one per coordinate, or none:
//                only non-conservative ones (inputs, friction); a force that is the
//                gradient of a potential belongs in `potential`
//   bodies       what the 3D view draws: shapes whose pose is an expression of q and t
//
// Expressions may use the parameters, the coordinates, (kinetic, forces) their
// velocities <name>_dot, (forces, bodies) the time t, pi, and the functions sin cos
// tan exp log sqrt tanh abs step sinh cosh asin acos atan.
// The scene's effects name coordinates by number ("joint": 2 is the second
// coordinate): torques, viscous and Coulomb friction add to Q; gravity and springs are
// not allowed (write them in the potential).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace ll {

enum class BodyShape { Box, Sphere, Cylinder, Rod };

// One rigid shape of the 3D view, posed by expressions of the coordinates and t:
//   box       size [lx, ly, lz], centred on `position`
//   sphere    size [radius], centred on `position`
//   cylinder  size [radius, length], axis along the body's z, centred on `position`
//   rod       size [radius], a cylinder from `position` to `end` (a pendulum's arm,
//             a spring); `angle`/`axis` are ignored
// The body is turned by `angle` [rad] about the unit `axis` (world frame), about its
// centre. Sizes and the axis are numbers or parameter expressions (constants).
struct VisualBody {
    std::string name;
    BodyShape shape = BodyShape::Sphere;
    std::vector<double> size;                            // as the shape says
    std::array<std::string, 3> position{"0", "0", "0"};  // expressions of q, t
    std::array<std::string, 3> end{"0", "0", "0"};       // rod only
    std::string angle = "0";                             // expression of q, t
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    std::string color;  // "#rrggbb", empty: the view's default
};

struct LagrangianSpec {
    std::vector<std::string> coordinates;
    std::string kinetic;
    std::string potential = "0";
    std::vector<std::string> forces;  // empty (no Q from here) or one per coordinate
    std::vector<VisualBody> bodies;

    int dof() const { return static_cast<int>(coordinates.size()); }
};

const char* toString(BodyShape shape);
// How many numbers `size` holds for the shape (box 3, sphere 1, cylinder 2, rod 1).
int sizeCount(BodyShape shape);

}  // namespace ll
