#include "core/symbolic/lagrangian_fields.hpp"

#include <algorithm>
#include <cctype>
#include <regex>

#include "core/model/diagnostics.hpp"

namespace ll {
namespace {

bool isNameCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// 1-based position of the first whole-word `name` in `text`, or 0.
std::size_t wordPosition(const std::string& text, const std::string& name) {
    for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
        const std::size_t end = at + name.size();
        if ((at == 0 || !isNameCharacter(text[at - 1])) && (end == text.size() || !isNameCharacter(text[end]))) return at + 1;
    }
    return 0;
}

// " at position N" of `name` in `text`, or an empty message.
Message at(const std::string& text, const std::string& name) {
    const std::size_t position = wordPosition(text, name);
    return position == 0 ? Message() : message(MessageId::ExpressionAtPosition, position);
}

// The first of `symbols` that e depends on, or nullptr.
const GiNaC::symbol* firstUsed(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& symbols) {
    for (const GiNaC::symbol& s : symbols)
        if (e.has(s)) return &s;
    return nullptr;
}

}  // namespace

LagrangianSymbols lagrangianSymbols(const std::vector<std::string>& coordinates) {
    LagrangianSymbols s;
    for (const std::string& name : coordinates) {
        s.q.emplace_back(name);
        s.qd.emplace_back(name + "_dot");
        s.qdd.emplace_back(name + "_ddot");
    }
    return s;
}

std::optional<Message> whyNotACoordinateName(const std::string& name, const std::vector<std::string>& taken) {
    using enum MessageId;
    static const std::regex identifier("[A-Za-z][A-Za-z0-9_]*");
    static const std::regex robotCoordinate("q[0-9]+");  // q1, q2 name coordinates here too
    if (!std::regex_match(name, identifier)) return message(NotAName, name);
    const auto endsWith = [&](const std::string& suffix) {
        return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (endsWith("_dot") || endsWith("_ddot")) return message(CoordinateNameEndsInDot, name);
    if (!std::regex_match(name, robotCoordinate))
        if (auto why = ParameterTable::whyNotAName(name)) return why;
    const std::string velocity = name + "_dot";
    if (std::find(taken.begin(), taken.end(), name) != taken.end()) return message(CoordinateNameTaken, name);
    if (std::find(taken.begin(), taken.end(), velocity) != taken.end()) return message(VelocityNameTaken, name, velocity);
    return std::nullopt;
}

std::vector<Diagnostic> checkCoordinateNames(const std::vector<std::string>& coordinates, const ParameterTable& parameters) {
    std::vector<Diagnostic> out;
    std::vector<std::string> taken = parameters.names();
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
        if (auto why = whyNotACoordinateName(coordinates[i], taken))
            out.push_back({Severity::Error, "lagrangian.coordinates[" + std::to_string(i) + "]", *why});
        taken.push_back(coordinates[i]);
        taken.push_back(coordinates[i] + "_dot");
    }
    return out;
}

GiNaC::ex parseLagrangianField(const ParameterTable& parameters, const LagrangianSymbols& symbols, const std::string& field,
                               const std::string& text, LagrangianField kind) {
    // Every symbol is known to the parser, so that a misplaced one gets its own message.
    std::vector<GiNaC::symbol> extra = symbols.q;
    extra.insert(extra.end(), symbols.qd.begin(), symbols.qd.end());
    extra.push_back(symbols.t);
    const GiNaC::ex e = parameters.parse(field, text, extra);
    const bool velocities = kind == LagrangianField::Kinetic || kind == LagrangianField::Force;
    const bool time = kind == LagrangianField::Force || kind == LagrangianField::Pose;
    if (!velocities)
        if (const GiNaC::symbol* v = firstUsed(e, symbols.qd))
            throw InputError(field, message(kind == LagrangianField::Potential ? MessageId::PotentialDependsOnVelocity
                                                                               : MessageId::PoseDependsOnVelocity,
                                            v->get_name(), at(text, v->get_name()), text));
    if (!time && e.has(symbols.t))
        throw InputError(field, message(MessageId::EnergyDependsOnTime, kind == LagrangianField::Kinetic ? "E_kin" : "E_pot", at(text, "t"),
                                        text));
    return e;
}

std::string lagrangianForceField(int coordinate0) { return "lagrangian.forces[" + std::to_string(coordinate0) + "]"; }

std::string lagrangianBodyField(int body0, const std::string& key) {
    return "lagrangian.bodies[" + std::to_string(body0) + "]" + (key.empty() ? "" : "." + key);
}

}  // namespace ll
