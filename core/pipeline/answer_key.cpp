// The answer key: a scene derived once, its entries by the names a student types, the
// names an answer may use, and the check of one answer (core/pipeline/answer_check.hpp).
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <set>

#include "core/model/diagnostics.hpp"
#include "core/pipeline/answer_key_data.hpp"
#include "core/present/display_builder.hpp"
#include "core/present/expression_printer.hpp"
#include "core/symbolic/exact_numbers.hpp"
#include "core/symbolic/function_identity.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/symbolic/trig_names.hpp"

namespace ll {

using GiNaC::ex;

const char* answerErrorKindName(AnswerErrorKind kind) {
    switch (kind) {
        case AnswerErrorKind::Factor: return "factor";
        case AnswerErrorKind::Sign: return "sign";
        case AnswerErrorKind::Link: return "link";
        case AnswerErrorKind::Steiner: return "steiner";
        case AnswerErrorKind::Rotation: return "rotation";
        case AnswerErrorKind::Length: return "length";
        case AnswerErrorKind::ChristoffelIndex: return "christoffel_index";
        case AnswerErrorKind::Dimension: return "dimension";
        case AnswerErrorKind::Coordinates: return "coordinates";
        case AnswerErrorKind::Convention: return "convention";
        case AnswerErrorKind::UnknownSymbol: return "unknown_symbol";
        case AnswerErrorKind::HomePose: return "home_pose";
        case AnswerErrorKind::Translational: return "translational";
        case AnswerErrorKind::RotationalTerm: return "rotational";
    }
    return "";
}

const char* answerVerdictName(AnswerVerdict verdict) {
    switch (verdict) {
        case AnswerVerdict::Right: return "right";
        case AnswerVerdict::Wrong: return "wrong";
        case AnswerVerdict::Unreadable: break;
    }
    return "unreadable";
}

ex christoffel(const GiNaC::matrix& B, const std::vector<GiNaC::symbol>& q, int i, int j, int k, const std::array<int, 3>& signs) {
    return GiNaC::numeric(1, 2) * (signs[0] * B(i, j).diff(q[k]) + signs[1] * B(i, k).diff(q[j]) + signs[2] * B(j, k).diff(q[i]));
}

// An entry name as a student may type it, reduced to what identifies it: T_2^0(1, 4),
// T2_0[1,4] and t20(1,4) are the same key; ω₂ is w2, ∂L/∂θ̇₁ is dl/dthetadot1.
std::string entryKey(const std::string& typed) {
    std::string plain;
    try {
        plain = symbolic::plainSpelling(typed);
    } catch (const symbolic::AnswerUnreadable&) {
        return "";
    }
    std::string key;
    for (char c : plain) {
        if (c == ' ' || c == '_' || c == '^' || c == '{' || c == '}' || c == '\\' || c == '*') continue;
        key += c == '[' ? '(' : c == ']' ? ')' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    for (std::size_t at; (at = key.find("omega")) != std::string::npos;) key.replace(at, 5, "w");
    for (std::size_t at; (at = key.find("dot")) != std::string::npos;) key.replace(at, 3, "d");
    return key;
}

namespace {


std::string indices(std::initializer_list<int> zeroBased, int n) {
    std::string out;
    for (int i : zeroBased) out += (n >= 10 && !out.empty() ? "_" : "") + std::to_string(i + 1);
    return out;
}

void collectSymbols(const ex& e, std::map<std::string, ex>& out) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
        out.emplace(GiNaC::ex_to<GiNaC::symbol>(e).get_name(), e);
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) collectSymbols(e.op(i), out);
}

std::set<std::string> symbolNames(const ex& e) {
    std::map<std::string, ex> found;
    collectSymbols(e, found);
    std::set<std::string> names;
    for (const auto& [name, value] : found) names.insert(name);
    return names;
}

class KeyBuilder {
public:
    explicit KeyBuilder(AnswerKey::Data& k) : k_(k), d_(k.derivation) {}

    void build() {
        for (const ex& relation : d_.trigToFunctions) {
            k_.toFunctions[relation.lhs()] = relation.rhs();
            k_.toShorthand[relation.rhs()] = relation.lhs();
        }
        for (const ex& relation : d_.parameterValues) {
            const ex value = relation.rhs();
            k_.values[relation.lhs()] = GiNaC::is_a<GiNaC::numeric>(value) ? symbolic::exactFloats(value) : value;
        }
        vocabulary();
        entries();
        if (!k_.scene.lagrangian) roles();
    }

private:
    void vocabulary() {
        symbolic::AnswerVocabulary& v = k_.vocabulary;
        v.robot = d_.system == symbolic::SystemKind::Robot;
        v.q = d_.q;
        v.qd = d_.qd;
        v.qdd = d_.qdd;
        if (!v.robot) v.coordinateNames = d_.coordinateNames;
        std::map<std::string, ex> found;
        for (const symbolic::DerivationStep& step : d_.steps)
            for (const symbolic::DerivationItem& item : step.items) collectSymbols(item.value, found);
        for (const ex* e : {&d_.Ekin, &d_.Epot}) collectSymbols(*e, found);
        for (const GiNaC::matrix* m : {&d_.B, &d_.C, &d_.g, &d_.Q}) collectSymbols(*m, found);
        for (const ex& relation : d_.parameterValues) collectSymbols(relation.lhs(), found);
        const int n = static_cast<int>(d_.q.size());
        for (const auto& [name, value] : found) {
            if (v.robot && symbolic::parseTrigName(name, n)) continue;  // c1, s12: read as cos q1, sin(q1 + q2)
            v.names.emplace(name, value);
        }
        for (int i = 0; i < n; ++i) {  // the derivation's own names of q, q̇, q̈
            v.names.emplace(d_.q[i].get_name(), d_.q[i]);
            v.names.emplace(d_.qd[i].get_name(), d_.qd[i]);
            v.names.emplace(d_.qdd[i].get_name(), d_.qdd[i]);
        }
        // g: the magnitude of gravity when the derivation has it as a number (an axis-aligned g0)
        if (!v.names.count("g") && k_.scene.effects.gravity) {
            const Eigen::Vector3d& g0 = *k_.scene.effects.gravity;
            int nonzero = 0;
            double magnitude = 0;
            for (int a = 0; a < 3; ++a)
                if (g0[a] != 0.0) {
                    ++nonzero;
                    magnitude = std::abs(g0[a]);
                }
            if (nonzero == 1) {
                v.names.emplace("g", symbolic::exactNumber(magnitude));
                v.names.emplace("g0", symbolic::exactNumber(magnitude));
            }
        }
    }

    void add(KeyEntry entry, std::vector<std::string> aliases = {}) {
        entry.value = k_.functions(entry.value);
        const std::size_t index = k_.entries.size();
        k_.ids.push_back(entry.id);
        k_.byKey.emplace(entryKey(entry.id), index);
        for (const std::string& alias : aliases) k_.byKey.emplace(entryKey(alias), index);
        k_.entries.push_back(std::move(entry));
    }

    // A matrix or vector whose entries are the next rows·cols entries added, row by row.
    void whole(const std::string& id, unsigned rows, unsigned cols, std::size_t first, std::vector<std::string> aliases = {}) {
        AnswerKey::Data::Whole w{id, rows, cols, {}};
        for (std::size_t i = 0; i < rows * cols; ++i) w.entries.push_back(first + i);
        const std::size_t index = k_.wholes.size();
        k_.wholeByKey.emplace(entryKey(id), index);
        for (const std::string& alias : aliases)
            if (!alias.empty()) k_.wholeByKey.emplace(entryKey(alias), index);
        k_.wholes.push_back(std::move(w));
    }

    // T_2^0 is also typed T2(…), I_l2^0 also I_l2(…): the base frame's superscript left out.
    static std::string shortItemName(const symbolic::DerivationItem& item) {
        const std::string i = std::to_string(item.index + 1);
        if (item.quantity == symbolic::Quantity::Transform) return "T_" + i;
        if (item.quantity == symbolic::Quantity::LinkInertia) return "I_l" + i;
        return "";
    }

    // dL/dtheta1_dot is also typed ∂L/∂θ̇1 (read as dL/dtheta_dot1).
    static std::vector<std::string> lagrangianAliases(const std::string& name) {
        const std::string tail = "_dot";
        if (name.size() < tail.size() || name.compare(name.size() - tail.size(), tail.size(), tail) != 0) return {};
        std::string body = name.substr(0, name.size() - tail.size());
        std::size_t digits = body.size();
        while (digits > 0 && std::isdigit(static_cast<unsigned char>(body[digits - 1]))) --digits;
        if (digits == body.size()) return {};
        return {body.substr(0, digits) + tail + body.substr(digits)};
    }

    void entries() {
        const int n = static_cast<int>(d_.q.size());
        // the derivation's items, entry by entry (A_i, T_i^0, p_ci, ω_i, v_ci, I_li^0, …)
        for (const symbolic::DerivationStep& step : d_.steps)
            for (const symbolic::DerivationItem& item : step.items) {
                if (item.quantity == symbolic::Quantity::DhTable || item.quantity == symbolic::Quantity::EquationOfMotion ||
                    item.quantity == symbolic::Quantity::Coordinates || item.quantity == symbolic::Quantity::Velocities ||
                    symbolic::isControlQuantity(item.quantity))
                    continue;
                switch (item.quantity) {  // below, by their entries' textbook names
                    case symbolic::Quantity::MassMatrix:
                    case symbolic::Quantity::CoriolisMatrix:
                    case symbolic::Quantity::GravityVector:
                    case symbolic::Quantity::GeneralizedForces:
                    case symbolic::Quantity::KineticEnergy:
                    case symbolic::Quantity::PotentialEnergy: continue;
                    default: break;
                }
                if (GiNaC::is_a<GiNaC::matrix>(item.value)) {
                    const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(item.value);
                    whole(item.name, m.rows(), m.cols(), k_.entries.size(), {shortItemName(item)});
                    for (unsigned r = 0; r < m.rows(); ++r)
                        for (unsigned c = 0; c < m.cols(); ++c) {
                            KeyEntry e;
                            e.item = item.name;
                            e.quantity = item.quantity;
                            e.index = item.index;
                            e.i = static_cast<int>(r);
                            e.j = static_cast<int>(c);
                            e.value = m(r, c);
                            std::vector<std::string> aliases;
                            const std::string shortName = shortItemName(item);
                            const std::string rc = "(" + std::to_string(r + 1) + "," + std::to_string(c + 1) + ")";
                            if (m.cols() == 1) {
                                e.id = item.name + "(" + std::to_string(r + 1) + ")";
                                aliases.push_back(item.name + rc);
                                if (m.rows() == 3) aliases.push_back(item.name + std::string(1, "xyz"[r]));
                            } else {
                                e.id = item.name + rc;
                            }
                            if (!shortName.empty()) aliases.push_back(shortName + (m.cols() == 1 ? "(" + std::to_string(r + 1) + ")" : rc));
                            add(std::move(e), aliases);
                        }
                } else {
                    KeyEntry e;
                    e.item = item.name;
                    e.quantity = item.quantity;
                    e.index = item.index;
                    e.id = item.name;
                    e.value = item.value;
                    add(std::move(e), lagrangianAliases(item.name));
                }
            }
        whole("B", n, n, k_.entries.size());
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                add({"b" + indices({i, j}, n), EntryKind::MassMatrix, i, j, -1, "", d_.B(i, j)},
                    {"b(" + indices({i}, 0) + "," + indices({j}, 0) + ")"});
        whole("C", n, n, k_.entries.size());
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                add({"c" + indices({i, j}, n), EntryKind::Coriolis, i, j, -1, "", d_.C(i, j)},
                    {"c(" + indices({i}, 0) + "," + indices({j}, 0) + ")"});
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k)
                    add({"c" + indices({i, j, k}, n), EntryKind::Christoffel, i, j, k, "", 0, false},
                        {"c(" + indices({i}, 0) + "," + indices({j}, 0) + "," + indices({k}, 0) + ")"});
        whole("g", n, 1, k_.entries.size());
        for (int i = 0; i < n; ++i) add({"g" + indices({i}, n), EntryKind::Gravity, i, -1, -1, "", d_.g(i, 0)});
        whole("Q", n, 1, k_.entries.size());
        for (int i = 0; i < n; ++i) add({"Q" + indices({i}, n), EntryKind::Force, i, -1, -1, "", d_.Q(i, 0)}, {"tau" + indices({i}, n)});
        add({"E_kin", EntryKind::KineticEnergy, -1, -1, -1, "", d_.Ekin}, {"T", "K"});
        add({"E_pot", EntryKind::PotentialEnergy, -1, -1, -1, "", d_.Epot}, {"U", "V", "P"});
        if (!k_.scene.lagrangian) linkParts(n);
        for (const symbolic::DerivationStep& step : d_.steps)
            for (const symbolic::DerivationItem& item : step.items)
                if (item.quantity == symbolic::Quantity::EquationOfMotion) {
                    const ex relation = item.value;
                    const int row = item.index;
                    const std::string number = std::to_string(row + 1);
                    add({"equation" + number, EntryKind::Equation, row, -1, -1, item.name, relation.lhs() - relation.rhs()},
                        {"eom" + number, "equation_" + number});
                }
    }

    // The structured form's names (β_jk⁽ⁱ⁾ = beta{j}_{k}_{i}, γ_j⁽ⁱ⁾ = gamma{j}_{i}), made when asked.
    void linkParts(int n) {
        for (int i = 0; i < n; ++i)
            for (int j = 0; j <= i; ++j) {
                const std::string L = std::to_string(i + 1), J = std::to_string(j + 1);
                for (int k = j; k <= i; ++k) {
                    const std::string K = std::to_string(k + 1);
                    add({"beta" + J + "_" + K + "_" + L, EntryKind::LinkPart, i, j, k, "", 0, false}, {"beta" + J + K + "(" + L + ")"});
                }
                if (k_.scene.effects.gravity) add({"gamma" + J + "_" + L, EntryKind::LinkPart, i, j, -1, "", 0, false}, {"gamma" + J + "(" + L + ")"});
            }
    }

    // The roles of the symbols by link (a mass, an inertia, a centre of mass, a DH length),
    // and the units they give the dimension check.
    void roles() {
        const GiNaC::symbol t("t");
        const symbolic::SymbolicRobot robot = symbolic::symbolicRobot(k_.scene, k_.mode, t);
        const std::map<std::string, int> owned = symbolic::linkSymbols(robot);
        std::map<std::string, int> conflicts;
        auto unit = [&](const std::string& name, Dimension dimension) {
            auto [it, inserted] = k_.units.emplace(name, dimension);
            if (!inserted && it->second != dimension) conflicts[name] = 1;
        };
        auto symbolOf = [&](const std::string& name) -> std::optional<GiNaC::symbol> {
            auto it = k_.vocabulary.names.find(name);
            if (it == k_.vocabulary.names.end() || !GiNaC::is_a<GiNaC::symbol>(it->second)) return std::nullopt;
            return GiNaC::ex_to<GiNaC::symbol>(it->second);
        };
        k_.links.resize(robot.joints.size());
        for (std::size_t i = 0; i < robot.joints.size(); ++i) {
            const symbolic::SymbolicJoint& joint = robot.joints[i];
            const std::set<std::string> mass = symbolNames(joint.mass);
            std::set<std::string> inertia = symbolNames(joint.inertia), com = symbolNames(joint.com);
            std::set<std::string> lengths = symbolNames(joint.a);
            for (const std::string& s : symbolNames(joint.d)) lengths.insert(s);
            for (const std::string& s : mass) unit(s, {1, 0, 0});
            for (const std::string& s : inertia)
                if (!mass.count(s)) unit(s, {1, 2, 0});
            for (const std::string& s : com)
                if (!mass.count(s)) unit(s, {0, 1, 0});
            for (const std::string& s : lengths) unit(s, {0, 1, 0});
            LinkRoles& roles = k_.links[i];
            auto own = [&](const std::string& s) {
                auto it = owned.find(s);
                return it != owned.end() && it->second == static_cast<int>(i);
            };
            for (const std::string& s : mass)
                if (own(s))
                    if (auto sym = symbolOf(s)) roles.mass.push_back(*sym);
            for (const std::string& s : inertia)
                if (own(s) && !mass.count(s))
                    if (auto sym = symbolOf(s)) roles.inertia.push_back(*sym);
            for (const std::string& s : com)
                if (own(s) && !mass.count(s) && !inertia.count(s))
                    if (auto sym = symbolOf(s)) roles.com.push_back(*sym);
            for (const std::string& s : lengths)
                if (auto sym = symbolOf(s)) roles.lengths.push_back(*sym);
            const bool prismatic = joint.type == JointType::Prismatic;
            unit(d_.q[i].get_name(), {0, prismatic ? 1 : 0, 0});
            unit(d_.qd[i].get_name(), {0, prismatic ? 1 : 0, -1});
            unit(d_.qdd[i].get_name(), {0, prismatic ? 1 : 0, -2});
        }
        if (symbolOf("g")) unit("g", {0, 1, -2});  // the textbook symbol of gravity
        // the masses and g0 for the link parts, in the derivation's own symbols (by name)
        const auto adopt = [&](const ex& e) {
            std::map<std::string, ex> found;
            collectSymbols(e, found);
            GiNaC::exmap own;
            for (const auto& [name, symbol] : found)
                if (auto it = k_.vocabulary.names.find(name); it != k_.vocabulary.names.end()) own[symbol] = it->second;
            return e.subs(own, GiNaC::subs_options::no_pattern);
        };
        for (const symbolic::SymbolicJoint& joint : robot.joints) k_.masses.push_back(adopt(joint.mass));
        for (unsigned r = 0; r < 3; ++r) k_.gravity(r, 0) = robot.hasGravity ? adopt(robot.gravity(r, 0)) : ex(0);
        for (const auto& [name, ignored] : conflicts) k_.units.erase(name);
    }

    AnswerKey::Data& k_;
    const symbolic::Derivation& d_;
};

// As the derivation prints: the trig shorthand (c12), and numbers spelled as the document
// spells them (the scene's decimals as typed, 9.81 rather than 981/100). A right answer
// (`exact`) keeps every digit, so that copied back it is right.
std::string printed(const AnswerKey::Data& k, const ex& e, present::Style style, bool exact = false) {
    present::DisplayOptions options = present::displayOptions(present::printOptionsFor(k.derivation, style));
    options.readableNumbers = true;
    options.allDigits = exact;
    options.typedDecimals = k.derivation.typedDecimals;
    const ex shorthand = e.subs(k.toShorthand, GiNaC::subs_options::no_pattern);
    return present::renderDisplay(*present::buildDisplay(shorthand, options), present::displayStyle(style));
}

}  // namespace

const ex& AnswerKey::Data::valueOf(const KeyEntry& entry) const {
    if (!entry.ready) {
        entry.value = entry.kind == EntryKind::LinkPart
                          ? functions(linkPart(entry))
                          : christoffel(GiNaC::ex_to<GiNaC::matrix>(functions(derivation.B)), derivation.q, entry.i, entry.j, entry.k);
        entry.ready = true;
    }
    return entry.value;
}

const ex* AnswerKey::Data::itemValue(const symbolic::Derivation& d, symbolic::Quantity quantity, int index) const {
    for (const symbolic::DerivationStep& step : d.steps)
        for (const symbolic::DerivationItem& item : step.items)
            if (item.quantity == quantity && item.index == index) return &item.value;
    return nullptr;
}

std::optional<ex> AnswerKey::Data::entryValue(const symbolic::Derivation& d, const KeyEntry& e) const {
    // another derivation's symbols are other objects with the same names: this key's, by name
    GiNaC::exmap trig, own;
    for (const ex& relation : d.trigToFunctions) trig[relation.lhs()] = relation.rhs();
    for (std::size_t i = 0; i < d.q.size() && i < derivation.q.size(); ++i) {
        own[d.q[i]] = derivation.q[i];
        own[d.qd[i]] = derivation.qd[i];
        own[d.qdd[i]] = derivation.qdd[i];
    }
    auto adopt = [&](const ex& v) {
        std::map<std::string, ex> found;
        collectSymbols(v, found);
        GiNaC::exmap byName = own;
        for (const auto& [name, symbol] : found)
            if (auto it = vocabulary.names.find(name); it != vocabulary.names.end() && !byName.count(symbol)) byName[symbol] = it->second;
        return v.subs(byName, GiNaC::subs_options::no_pattern);
    };
    auto f = [&](const ex& v) { return adopt(v.subs(trig, GiNaC::subs_options::no_pattern)); };
    switch (e.kind) {
        case EntryKind::MassMatrix: return f(d.B(e.i, e.j));
        case EntryKind::Coriolis: return f(d.C(e.i, e.j));
        case EntryKind::Christoffel: return christoffel(GiNaC::ex_to<GiNaC::matrix>(f(d.B)), derivation.q, e.i, e.j, e.k);
        case EntryKind::Gravity: return f(d.g(e.i, 0));
        case EntryKind::Force: return f(d.Q(e.i, 0));
        case EntryKind::KineticEnergy: return f(d.Ekin);
        case EntryKind::PotentialEnergy: return f(d.Epot);
        case EntryKind::Equation: {
            const ex* v = itemValue(d, symbolic::Quantity::EquationOfMotion, e.i);
            if (!v) return std::nullopt;
            return f(v->lhs() - v->rhs());
        }
        case EntryKind::LinkPart: return std::nullopt;  // made from this derivation's items only
        case EntryKind::Item: {
            const ex* v = itemValue(d, e.quantity, e.index);
            if (!v) return std::nullopt;
            if (GiNaC::is_a<GiNaC::matrix>(*v)) return f(GiNaC::ex_to<GiNaC::matrix>(*v)(e.i, e.j));
            return f(*v);
        }
    }
    return std::nullopt;
}

AnswerKey::AnswerKey() : data_(std::make_unique<Data>()) {}
AnswerKey::~AnswerKey() {
    const auto lock = symbolic::lockGinac();  // GiNaC objects die under the lock
    data_.reset();
}

std::shared_ptr<const AnswerKey> AnswerKey::build(const Scene& scene, symbolic::ParameterMode mode) {
    const auto lock = symbolic::lockGinac();
    std::shared_ptr<AnswerKey> key(new AnswerKey());
    Data& k = *key->data_;
    k.scene = scene;
    k.mode = mode;
    if (scene.lagrangian) {
        k.derivation = symbolic::deriveLagrangian(scene, mode);
    } else {
        symbolic::DerivationOptions options;
        options.mode = mode;
        k.derivation = symbolic::deriveRobot(scene, options);
    }
    KeyBuilder(k).build();
    return key;
}

const std::vector<std::string>& AnswerKey::entries() const { return data_->ids; }

std::string AnswerKey::entryId(const std::string& typed) const {
    auto it = data_->byKey.find(entryKey(typed));
    return it == data_->byKey.end() ? "" : data_->entries[it->second].id;
}

std::string AnswerKey::rightAnswer(const std::string& id) const {
    const auto lock = symbolic::lockGinac();
    auto it = data_->byKey.find(entryKey(id));
    if (it == data_->byKey.end()) return "";
    return printed(*data_, data_->valueOf(data_->entries[it->second]), present::Style::Text, true);
}

namespace {

// The verdict on one expression for one entry, into `out` (verdict, hints, kinds, links,
// points); what was read and the entry's id are the caller's.
void judge(const AnswerKey::Data& k, const KeyEntry& entry, std::size_t index, const ex& answer, AnswerCheck& out) {
    const ex right = k.valueOf(entry);
    symbolic::IdentitySampler sampler(0x1a9a4e5eULL + index);
    try {
        bool same = false;
        if (entry.kind == EntryKind::Equation) {  // an equation times any constant is the same equation
            const auto ratio = symbolic::constantRatio(answer, right, sampler);
            same = ratio && !ratio->is_zero();
            out.points = 6;
        } else {
            const symbolic::IdentityResult r = symbolic::sameFunction(answer, right, sampler);
            same = r.same;
            out.points = r.points;
            out.sixtyDigits = r.exactness == symbolic::Exactness::SixtyDigits;
        }
        if (!same && !k.values.empty() && entry.kind != EntryKind::Equation) {
            // numbers written for some parameters: those (the right answer's, absent from the
            // answer) replaced by their values in the right answer only; the others stay symbols
            GiNaC::exmap written;
            for (const auto& [symbol, value] : k.values)
                if (right.has(symbol) && !answer.has(symbol)) written[symbol] = value;
            if (!written.empty() && symbolic::sameFunction(answer, right.subs(written, GiNaC::subs_options::no_pattern), sampler).same) {
                same = true;
                out.withValues = true;
            }
        }
        if (same) {
            out.verdict = AnswerVerdict::Right;
            // not the derivation's form term by term (GiNaC orders terms and factors itself, so
            // another order alone is not "different"; factored or expanded is)
            if (!out.withValues) out.writtenDifferently = !(answer - right).is_zero() && entry.kind != EntryKind::Equation;
            return;
        }
        out.verdict = AnswerVerdict::Wrong;
        explainWrongAnswer(k, entry, answer, out);
    } catch (const std::domain_error&) {
        out.verdict = AnswerVerdict::Unreadable;
        out.problem = message(MessageId::AnswerNotComparable);
        out.hints.clear();
        out.kinds.clear();
    }
}

// A whole matrix or vector answered at once: each entry judged, the verdict right when
// every one is, the hints entry by entry.
void judgeWhole(const AnswerKey::Data& k, const AnswerKey::Data::Whole& whole, const symbolic::ReadAnswer& read, AnswerCheck& out) {
    GiNaC::matrix shown(static_cast<unsigned>(read.rows.size()), static_cast<unsigned>(read.rows[0].size()));
    for (unsigned r = 0; r < shown.rows(); ++r)
        for (unsigned c = 0; c < shown.cols(); ++c) shown(r, c) = read.rows[r][c];
    out.readAs = printed(k, shown, present::Style::Text);
    out.readAsLatex = printed(k, shown, present::Style::Latex);
    if (shown.rows() != whole.rows || shown.cols() != whole.cols) {
        out.problem = message(MessageId::AnswerShape, whole.id, whole.rows, whole.cols, shown.rows(), shown.cols());
        return;
    }
    int right = 0;
    std::vector<Message> entryHints;
    out.verdict = AnswerVerdict::Right;
    out.points = 0;
    for (unsigned r = 0; r < whole.rows; ++r)
        for (unsigned c = 0; c < whole.cols; ++c) {
            const std::size_t index = whole.entries[r * whole.cols + c];
            AnswerCheck one;
            judge(k, k.entries[index], index, shown(r, c), one);
            out.points = std::max(out.points, one.points);
            out.sixtyDigits = out.sixtyDigits || one.sixtyDigits;
            if (one.verdict == AnswerVerdict::Unreadable) {
                out.verdict = AnswerVerdict::Unreadable;
                out.problem = one.problem;
                return;
            }
            if (one.verdict == AnswerVerdict::Right) {
                ++right;
                continue;
            }
            out.verdict = AnswerVerdict::Wrong;
            const std::string at =
                whole.cols == 1 ? "(" + std::to_string(r + 1) + ")" : "(" + std::to_string(r + 1) + "," + std::to_string(c + 1) + ")";
            if (entryHints.size() < 3)
                entryHints.push_back(Message(MessageId::HintEntry, {literal(at), one.hints.empty() ? Message() : one.hints[0]}));
            for (AnswerErrorKind kind : one.kinds)
                if (std::find(out.kinds.begin(), out.kinds.end(), kind) == out.kinds.end()) out.kinds.push_back(kind);
            for (int link : one.links)
                if (std::find(out.links.begin(), out.links.end(), link) == out.links.end()) out.links.push_back(link);
        }
    if (out.verdict == AnswerVerdict::Wrong) {
        out.hints.push_back(message(MessageId::HintEntriesRight, right, whole.rows * whole.cols));
        out.hints.insert(out.hints.end(), entryHints.begin(), entryHints.end());
    }
}

}  // namespace

AnswerCheck AnswerKey::check(const AnswerRequest& request) const {
    const auto lock = symbolic::lockGinac();
    const Data& k = *data_;
    AnswerCheck out;
    out.entry = request.entry;
    const std::string typed = entryKey(request.entry);
    auto it = k.byKey.find(typed);
    auto whole = k.wholeByKey.find(typed);
    if (it == k.byKey.end() && whole == k.wholeByKey.end()) {
        std::string some;
        for (const char* id : {"b11", "c121", "g1", "E_kin", "p_c1(1)", "T_1^0(1,4)", "B", "p_c1"})
            if (k.byKey.count(entryKey(id)) || k.wholeByKey.count(entryKey(id))) some += (some.empty() ? "" : ", ") + std::string(id);
        if (some.empty())
            for (std::size_t i = 0; i < k.ids.size() && i < 5; ++i) some += (some.empty() ? "" : ", ") + k.ids[i];
        out.problem = message(MessageId::AnswerUnknownEntry, request.entry, some);
        return out;
    }
    symbolic::ReadAnswer read;
    try {
        read = symbolic::readAnswer(request.answer, k.vocabulary);
    } catch (const symbolic::AnswerUnreadable& e) {
        out.problem = e.message();
        out.position = e.position();
        if (e.unknownName()) out.kinds.push_back(AnswerErrorKind::UnknownSymbol);
        return out;
    }
    if (it == k.byKey.end()) {  // a whole matrix or vector: B, p_c2, T_2^0
        const Data::Whole& w = k.wholes[whole->second];
        out.entry = w.id;
        if (read.rows.empty()) {
            out.problem = message(MessageId::AnswerMatrixNeeded, w.id, w.rows, w.cols);
            return out;
        }
        if (request.reveal) {
            GiNaC::matrix right(w.rows, w.cols);
            for (unsigned i = 0; i < w.rows * w.cols; ++i) right(i / w.cols, i % w.cols) = k.valueOf(k.entries[w.entries[i]]);
            out.rightAnswer = printed(k, right, present::Style::Text, true);
        }
        judgeWhole(k, w, read, out);
        return out;
    }
    const KeyEntry& entry = k.entries[it->second];
    out.entry = entry.id;
    if (!read.rows.empty()) {
        out.problem = message(MessageId::AnswerOneEntry, entry.id);
        return out;
    }
    const ex answer = read.value;
    out.readAs = printed(k, answer, present::Style::Text) + (read.equation ? " = 0" : "");
    out.readAsLatex = printed(k, answer, present::Style::Latex) + (read.equation ? " = 0" : "");
    if (request.reveal) out.rightAnswer = printed(k, k.valueOf(entry), present::Style::Text, true);
    judge(k, entry, it->second, answer, out);
    return out;
}

}  // namespace ll
