#pragma once
// The expressions of a scene's "lagrangian" block (core/model/lagrangian_spec.hpp) as
// GiNaC expressions: the coordinates, their velocities <name>_dot and the time t are
// symbols beside the parameters. The scene parser uses this to check every field when
// the file is read, the derivation to build the model; both name the field and the
// position in the expression in every error.
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/symbolic/expression.hpp"
#include "core/model/diagnostics.hpp"
#include "core/model/lagrangian_spec.hpp"
#include "core/model/scene.hpp"

namespace ll {

// The symbols a Lagrangian's expressions may refer to, named as the user wrote them.
struct LagrangianSymbols {
    std::vector<GiNaC::symbol> q;    // the coordinates: "theta1"
    std::vector<GiNaC::symbol> qd;   // their velocities: "theta1_dot"
    std::vector<GiNaC::symbol> qdd;  // their accelerations: "theta1_ddot" (printing only)
    GiNaC::symbol t{"t"};
};

LagrangianSymbols lagrangianSymbols(const std::vector<std::string>& coordinates);

// What an expression may use besides the parameters.
enum class LagrangianField {
    Kinetic,    // q, q̇
    Potential,  // q only (a velocity is an error that says so)
    Force,      // q, q̇, t
    Pose,       // q, t (visual bodies)
};

// Why `name` cannot name a coordinate, or nothing. `taken` are the names already in
// use (parameters, earlier coordinates and their velocities).
std::optional<Message> whyNotACoordinateName(const std::string& name, const std::vector<std::string>& taken);

// Errors in the coordinate names (field "lagrangian.coordinates[i]"): not identifiers,
// reserved, repeated, a parameter's name, or a velocity name <name>_dot that is taken.
std::vector<Diagnostic> checkCoordinateNames(const std::vector<std::string>& coordinates, const ParameterTable& parameters);

// The expression with the parameter symbols kept. Throws InputError naming `field` for
// a syntax error, an unknown symbol (or one the field may not use: a velocity in the
// potential, t in the kinetic energy), or a division by zero, with the position.
GiNaC::ex parseLagrangianField(const ParameterTable& parameters, const LagrangianSymbols& symbols, const std::string& field,
                               const std::string& text, LagrangianField kind);

// Field paths: "lagrangian.kinetic", "lagrangian.forces[2]", "lagrangian.bodies[1].position[3]".
std::string lagrangianForceField(int coordinate0);
std::string lagrangianBodyField(int body0, const std::string& key);

}  // namespace ll
