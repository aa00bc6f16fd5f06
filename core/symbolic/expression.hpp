#pragma once
// Named parameters of a scene and the numeric fields written as expressions of
// them ("l1/2", "m2*l2^2/12", "-pi/2", "90°"). GiNaC parses; each parameter is a symbol,
// so a symbolic derivation can keep the symbols while the simulation substitutes
// the values. Every expression may use pi and the degree units of
// core/symbolic/angle_units.hpp (deg = π/180, "90°", "90 deg"); its characters are checked
// first, so messages quote whole characters and count positions in characters.
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/symbolic/angle_units.hpp"
#include "core/model/message.hpp"
#include "core/model/scene.hpp"

namespace ll {

// Whether a field takes degrees ("90°", "90 deg"): angle fields do, a length or a mass
// does not (a degree sign there is a slip, refused naming the field).
enum class AngleUnits { Allowed, Refused };

class ParameterTable {
public:
    // Adds a parameter. `field` names it in errors ("parameters.l1"). Throws
    // InputError when the name is not an identifier, is reserved or is taken.
    void define(const std::string& field, const std::string& name, double value);
    // Adds a parameter defined by an expression of the parameters defined before
    // it; returns its value.
    double define(const std::string& field, const std::string& name, const std::string& text);

    // The expression with the parameter symbols kept (pi is GiNaC's Pi). Throws
    // InputError naming `field` for a syntax error or an unknown symbol.
    GiNaC::ex parse(const std::string& field, const std::string& text) const;
    // The same, where the text may also use the `extra` symbols (a Lagrangian's
    // coordinates, velocities and t; listed first in unknown-symbol messages), and
    // where substituting the parameter values must not divide by zero ("x/(k-2)" with
    // k = 2 fails, naming the position of the '/').
    GiNaC::ex parse(const std::string& field, const std::string& text, const std::vector<GiNaC::symbol>& extra) const;
    // The expression's value with every parameter substituted. Throws InputError
    // naming `field` also for division by zero, a complex or a non-finite value, and
    // for a degree unit when `units` is Refused.
    double evaluate(const std::string& field, const std::string& text, AngleUnits units = AngleUnits::Allowed) const;

    bool contains(const std::string& name) const;
    const std::vector<std::string>& names() const { return names_; }  // definition order
    const GiNaC::symbol& symbol(const std::string& name) const;       // throws std::out_of_range
    double value(const std::string& name) const;                      // throws std::out_of_range
    // What the parameter was defined as: an expression of earlier parameters' symbols,
    // or its number.
    const GiNaC::ex& definition(const std::string& name) const;  // throws std::out_of_range
    // symbol == value for every parameter, for GiNaC::ex::subs.
    GiNaC::lst values() const;

    // Why `name` cannot name a parameter, or nothing if it can. Reserved: pi, Pi, I,
    // Euler, Catalan, t, q<i>, qd<i>, qdd<i> (joint coordinates in derivations) and
    // the names of GiNaC's functions (sin, cos, sqrt, ...).
    static std::optional<Message> whyNotAName(const std::string& name);

private:
    struct Parameter {
        GiNaC::symbol symbol;
        double value = 0.0;
        GiNaC::ex definition;
    };
    const Parameter& find(const std::string& name) const;
    void add(const std::string& field, const std::string& name, double value, GiNaC::ex definition);
    PreparedExpression prepare(const std::string& field, const std::string& text) const;
    double toNumber(const std::string& field, const PreparedExpression& source, const GiNaC::ex& expression) const;
    GiNaC::ex parse(const std::string& field, const PreparedExpression& source, const std::vector<GiNaC::symbol>& extra,
                    bool checkValues) const;

    std::vector<std::string> names_;
    std::vector<Parameter> parameters_;  // parallel to names_
    GiNaC::symtab symbols_;              // what the parser may refer to
};

// The table a scene's parameters build: expressions from Scene::expressions
// ("parameters.<name>"), numbers otherwise. Throws InputError if they do not parse.
ParameterTable parameterTable(const Scene& scene);

}  // namespace ll
