#include "core/pipeline/entry_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <stdexcept>

#include "core/dynamics/link_contributions.hpp"
#include "core/model/quantity_units.hpp"
#include "core/present/display_tree.hpp"
#include "core/present/labels.hpp"
#include "core/symbolic/compiled_expressions.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/index_list.hpp"
#include "core/symbolic/trig_names.hpp"

namespace ll {
namespace {

using present::Quantity;

std::string folded(const std::string& id) {
    std::string out;
    for (char c : id)
        if (c != '_') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool revolute(const Scene& scene, int joint) { return !scene.lagrangian && scene.robot.joints.at(joint).dh.type == JointType::Revolute; }

// One unit for a whole item whose joints are all alike, else "" (mixed).
std::string uniform(const Scene& scene, std::string (*unit)(bool)) {
    if (scene.lagrangian) return "";
    bool anyRevolute = false, anyPrismatic = false;
    for (const Joint& j : scene.robot.joints) (j.dh.type == JointType::Revolute ? anyRevolute : anyPrismatic) = true;
    return anyRevolute && anyPrismatic ? "" : unit(anyRevolute);
}

// The unit of an entry (row, col) or of a whole item (row = col = −1).
std::string unitOf(const Scene& scene, Quantity q, int row, int col) {
    const bool robot = !scene.lagrangian;
    switch (q) {
        case Quantity::MassMatrix:
        case Quantity::MassMatrixEntry: return robot && row >= 0 ? massMatrixUnit(revolute(scene, row), revolute(scene, col)) : "";
        case Quantity::CoriolisMatrix:
        case Quantity::CoriolisEntry: return robot && row >= 0 ? coriolisUnit(revolute(scene, row), revolute(scene, col)) : "";
        case Quantity::GravityVector:
        case Quantity::GravityEntry:
        case Quantity::GeneralizedForces:
        case Quantity::ForceEntry: return robot && row >= 0 ? forceUnit(revolute(scene, row)) : "";
        case Quantity::KineticEnergy:
        case Quantity::PotentialEnergy:
        case Quantity::Lagrangian: return robot ? "J" : "";
        case Quantity::ComPosition: return "m";
        case Quantity::ComVelocity: return "m/s";
        case Quantity::AngularVelocity: return "rad/s";
        case Quantity::LinkInertia: return "kg·m²";
        case Quantity::Coordinates: return uniform(scene, coordinateUnit);
        case Quantity::Velocities: return uniform(scene, velocityUnit);
        default: return "";
    }
}

// The coordinates and velocities whose symbols occur in e: q_k, c_k, s_k, c12… (robots,
// by the trig shorthand's names), the coordinates themselves (a typed Lagrangian).
void scanSymbols(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& q, const std::vector<GiNaC::symbol>& qd, bool robot,
                 CatalogueEntry& entry) {
    const int n = static_cast<int>(q.size());
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
        const GiNaC::symbol& s = GiNaC::ex_to<GiNaC::symbol>(*it);
        for (int k = 0; k < n; ++k) {
            if (s.is_equal(q[k])) entry.coordinates |= std::uint64_t(1) << k;
            if (s.is_equal(qd[k])) entry.velocities |= std::uint64_t(1) << k;
        }
        if (robot)
            if (const auto trig = symbolic::parseTrigName(s.get_name(), n))
                for (int k : trig->indices) entry.coordinates |= std::uint64_t(1) << (k - 1);
    }
}

// The largest magnitude of link `link`'s part of the whole quantity (all of B for an
// entry of B): what tells a part that is rounding from one that counts.
double familyScale(Quantity q, const LinkContributions& c, int link) {
    switch (q) {
        case Quantity::MassMatrix:
        case Quantity::MassMatrixEntry: return c.B(link).cwiseAbs().maxCoeff();
        case Quantity::CoriolisMatrix:
        case Quantity::CoriolisEntry: return c.C(link).cwiseAbs().maxCoeff();
        case Quantity::GravityVector:
        case Quantity::GravityEntry: return c.g(link).cwiseAbs().maxCoeff();
        case Quantity::KineticEnergy: return std::abs(c.Ekin(link));
        case Quantity::PotentialEnergy: return std::abs(c.Epot(link));
        default: return 0.0;
    }
}

// The links of the per-link sums (b, c, g, E_kin, E_pot): those whose part is not zero.
class LinkFinder {
public:
    explicit LinkFinder(const Scene& scene) {
        if (!scene.lagrangian) contributions_.emplace(scene.robot, scene.effects);
    }
    std::vector<int> of(const CatalogueEntry& entry) {
        if (!contributions_) return {};
        return contributions_->linksIn([&](const LinkContributions& c, int i) { return linkPart(entry, c, i); },
                                       [&](const LinkContributions& c, int i) { return familyScale(entry.quantity, c, i); });
    }

private:
    std::optional<LinkContributions> contributions_;
};

bool isPerLink(const Scene& scene, Quantity q) {
    if (scene.lagrangian) return false;
    switch (q) {
        case Quantity::MassMatrix:
        case Quantity::MassMatrixEntry:
        case Quantity::CoriolisMatrix:
        case Quantity::CoriolisEntry:
        case Quantity::GravityVector:
        case Quantity::GravityEntry:
        case Quantity::KineticEnergy:
        case Quantity::PotentialEnergy: return true;
        default: return false;
    }
}

// The matrices listed entry by entry in the catalogue (their entries are what is picked).
bool byEntries(Quantity q) {
    return q == Quantity::MassMatrix || q == Quantity::CoriolisMatrix || q == Quantity::GravityVector || q == Quantity::GeneralizedForces;
}

// What a derivation item cannot be picked as: the DH table, an equation of motion,
// d/dt ∂L/∂q̇_i (it holds q̈, which no state gives) and the control law's items (they hold
// the error and the reference, which no state of the robot alone gives either).
bool pickable(Quantity q) {
    return q != Quantity::DhTable && q != Quantity::EquationOfMotion && q != Quantity::MomentumRate && !symbolic::isControlQuantity(q);
}

std::string labelOf(const present::DisplayItem& item) {
    if (item.equation && item.equation->kind == present::DisplayKind::Equation)
        return present::renderDisplay(*item.equation->children[0], present::DisplayStyle::Text);
    return item.name;
}

// Collects the entries and their expressions, then compiles the tape.
class Builder {
public:
    Builder(const Scene& scene, std::vector<GiNaC::symbol> q, std::vector<GiNaC::symbol> qd)
        : scene_(scene), q_(std::move(q)), qd_(std::move(qd)), links_(scene) {
        catalogue_ = std::make_shared<EntryCatalogue>();
        catalogue_->n = static_cast<int>(q_.size());
    }

    // One entry: `value` (a scalar, or a matrix row by row) in its own symbols; `computed`
    // the same as the tape computes it (with the names and shorthand substituted away
    // when the tape has no definitions for them).
    void add(CatalogueEntry entry, const GiNaC::ex& value, const GiNaC::ex& computed) {
        scanSymbols(value, q_, qd_, !scene_.lagrangian, entry);
        entry.first = static_cast<int>(outputs_.size());
        if (GiNaC::is_a<GiNaC::matrix>(computed)) {
            const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(computed);
            entry.rows = static_cast<int>(m.rows());
            entry.cols = static_cast<int>(m.cols());
            for (unsigned r = 0; r < m.rows(); ++r)
                for (unsigned c = 0; c < m.cols(); ++c) outputs_.push_back(m(r, c));
        } else {
            outputs_.push_back(computed);
        }
        if (entry.perLink && !value.expand().is_zero()) entry.links = links_.of(entry);
        if (entry.link >= 0 && entry.links.empty()) entry.links = {entry.link};
        catalogue_->entries.push_back(std::move(entry));
    }

    std::shared_ptr<EntryCatalogue> finish(const std::vector<symbolic::TapeDefinition>& definitions) {
        std::vector<GiNaC::symbol> inputs = q_;
        inputs.insert(inputs.end(), qd_.begin(), qd_.end());
        inputs.emplace_back("t");
        time_ = inputs.back();
        std::vector<GiNaC::ex> outputs;
        for (const GiNaC::ex& e : outputs_) outputs.push_back(e.subs(timeSymbol_ == time_));
        catalogue_->values = symbolic::compileExpressions(outputs, inputs, definitions);
        return catalogue_;
    }

    void setTimeSymbol(const GiNaC::symbol& t) { timeSymbol_ = t; }
    const Scene& scene() const { return scene_; }

private:
    const Scene& scene_;
    std::vector<GiNaC::symbol> q_, qd_;
    GiNaC::symbol timeSymbol_{"t"}, time_;
    LinkFinder links_;
    std::vector<GiNaC::ex> outputs_;
    std::shared_ptr<EntryCatalogue> catalogue_;
};

// The entry of `item` (the step's index-th), or its cell (row, col) when cell is set.
CatalogueEntry entryOf(const Scene& scene, const present::DisplayItem& item, int step, int index, bool cell = false, int row = -1,
                       int col = -1) {
    CatalogueEntry e;
    e.quantity = item.quantity;
    e.step = step;
    e.item = index;
    e.cell = cell;
    e.row = cell ? row : item.row;
    e.col = cell ? col : std::max(item.col, 0);
    e.perLink = isPerLink(scene, item.quantity);
    if (cell) {
        e.id = e.label = present::entryName(item, static_cast<std::size_t>(row), static_cast<std::size_t>(col));
    } else {
        e.id = item.name;
        e.label = labelOf(item);
    }
    switch (item.quantity) {
        case Quantity::ComPosition:
        case Quantity::ComVelocity:
        case Quantity::AngularVelocity:
        case Quantity::LinkInertia:
        case Quantity::ComJacobian: e.link = item.row; break;
        default: break;
    }
    const bool wholeMatrix = !cell && (item.quantity == Quantity::MassMatrix || item.quantity == Quantity::CoriolisMatrix ||
                                       item.quantity == Quantity::GravityVector || item.quantity == Quantity::GeneralizedForces);
    e.unit = wholeMatrix ? "" : unitOf(scene, item.quantity, e.row, e.col);
    return e;
}

}  // namespace

double linkPart(const CatalogueEntry& e, const LinkContributions& c, int link) {
    switch (e.quantity) {
        case Quantity::MassMatrix:
        case Quantity::MassMatrixEntry: return e.row >= 0 ? c.B(link)(e.row, e.col) : 0.0;
        case Quantity::CoriolisMatrix:
        case Quantity::CoriolisEntry: return e.row >= 0 ? c.C(link)(e.row, e.col) : 0.0;
        case Quantity::GravityVector:
        case Quantity::GravityEntry: return e.row >= 0 ? c.g(link)(e.row) : 0.0;
        case Quantity::KineticEnergy: return c.Ekin(link);
        case Quantity::PotentialEnergy: return c.Epot(link);
        default: return 0.0;
    }
}

const CatalogueEntry* EntryCatalogue::find(const std::string& id) const {
    for (const CatalogueEntry& e : entries)
        if (e.id == id) return &e;
    const CatalogueEntry* found = nullptr;
    for (const CatalogueEntry& e : entries)
        if (folded(e.id) == folded(id)) {
            if (found) return nullptr;  // ambiguous
            found = &e;
        }
    return found;
}

const CatalogueEntry* EntryCatalogue::at(int step, int item, int row, int col) const {
    for (const CatalogueEntry& e : entries)
        if (e.step == step && e.item == item && (!e.cell || (e.row == row && e.col == col))) return &e;
    return nullptr;
}

const CatalogueEntry* EntryCatalogue::ofQuantity(Quantity quantity, int row, int col) const {
    // The matrix and its single entries are one quantity, in two forms.
    const auto family = [](Quantity q) {
        switch (q) {
            case Quantity::MassMatrixEntry: return Quantity::MassMatrix;
            case Quantity::CoriolisEntry: return Quantity::CoriolisMatrix;
            case Quantity::GravityEntry: return Quantity::GravityVector;
            case Quantity::ForceEntry: return Quantity::GeneralizedForces;
            default: return q;
        }
    };
    for (const CatalogueEntry& e : entries)
        if (family(e.quantity) == family(quantity) && (row < 0 || (e.row == row && e.col == std::max(col, 0)))) return &e;
    return nullptr;
}

std::vector<const CatalogueEntry*> EntryCatalogue::fedBy(int link) const {
    std::vector<const CatalogueEntry*> out;
    for (const CatalogueEntry& e : entries)
        if (std::find(e.links.begin(), e.links.end(), link) != e.links.end()) out.push_back(&e);
    return out;
}

void EntryCatalogue::evaluate(const double* q, const double* qd, double t, std::vector<double>& out) const {
    std::vector<double> input(2 * n + 1);
    std::copy(q, q + n, input.begin());
    std::copy(qd, qd + n, input.begin() + n);
    input[2 * n] = t;
    out.resize(static_cast<std::size_t>(values.outputCount()));
    values.evaluate(input.data(), out.data());
}

std::shared_ptr<EntryCatalogue> expandedCatalogue(const Scene& scene, const symbolic::Derivation& d,
                                                  const present::DisplayDocument& shown) {
    const auto lock = symbolic::lockGinac();
    Builder build(scene, d.q, d.qd);
    build.setTimeSymbol(d.t);
    const auto toNumbers = [&](const GiNaC::ex& e) { return e.subs(d.trigToFunctions).subs(d.parameterValues); };
    for (std::size_t s = 0; s < shown.steps.size() && s < d.steps.size(); ++s) {
        const symbolic::DerivationStep& step = d.steps[s];
        for (std::size_t i = 0; i < shown.steps[s].items.size() && i < step.items.size(); ++i) {
            const present::DisplayItem& item = shown.steps[s].items[i];
            const GiNaC::ex& value = step.items[i].value;
            if (!pickable(item.quantity)) continue;
            if (byEntries(item.quantity) && GiNaC::is_a<GiNaC::matrix>(value)) {
                const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(value);
                for (unsigned r = 0; r < m.rows(); ++r)
                    for (unsigned c = 0; c < m.cols(); ++c)
                        build.add(entryOf(scene, item, static_cast<int>(s), static_cast<int>(i), true, static_cast<int>(r),
                                          static_cast<int>(c)),
                                  m(r, c), toNumbers(m(r, c)));
                continue;
            }
            build.add(entryOf(scene, item, static_cast<int>(s), static_cast<int>(i)), value, toNumbers(value));
        }
    }
    return build.finish({});
}

std::shared_ptr<EntryCatalogue> structuredCatalogue(const Scene& scene, const symbolic::StructuredDynamics& st,
                                                    const present::DisplayDocument& shown) {
    const auto lock = symbolic::lockGinac();
    const symbolic::TrigContext& tc = *st.trig;
    Builder build(scene, tc.q(), tc.qd());
    build.setTimeSymbol(tc.t());
    // The tape computes the shorthand, the parameters and every name once, in order.
    std::vector<symbolic::TapeDefinition> definitions;
    for (const GiNaC::ex& rel : st.trigToFunctions) definitions.push_back({rel.lhs(), rel.rhs()});
    for (const GiNaC::ex& rel : st.parameterValues) definitions.push_back({rel.lhs(), rel.rhs()});
    std::map<std::string, const symbolic::NamedDefinition*> byName;
    for (const symbolic::NamedDefinition& def : st.table->entries()) {
        definitions.push_back({def.symbol, def.value});
        byName[def.name] = &def;
    }
    for (std::size_t s = 0; s < shown.steps.size(); ++s)
        for (std::size_t i = 0; i < shown.steps[s].items.size(); ++i) {
            const present::DisplayItem& item = shown.steps[s].items[i];
            CatalogueEntry e = entryOf(scene, item, static_cast<int>(s), static_cast<int>(i));
            GiNaC::ex value;
            switch (item.quantity) {
                case Quantity::NamedQuantity: {
                    const auto it = byName.find(item.name);
                    if (it == byName.end()) continue;
                    value = it->second->symbol;
                    e.row = e.col = -1;
                    e.link = it->second->link;
                    e.unit = it->second->unit;
                    break;
                }
                case Quantity::MassMatrixEntry: value = st.B(item.row, item.col); break;
                case Quantity::CoriolisEntry: value = st.C(item.row, item.col); break;
                case Quantity::GravityEntry: value = st.g(item.row, 0); break;
                case Quantity::ForceEntry: value = st.Q(item.row, 0); break;
                default: continue;
            }
            // Its value is over the table's names: the coordinates it depends on are theirs.
            e.coordinates = st.table->coordinatesOf(value);
            const CatalogueEntry shown = e;
            build.add(std::move(e), value, value);
            if (item.quantity == Quantity::MassMatrixEntry && item.row != item.col) {
                // B is symmetric: the form shows b_jk for j < k only; b_kj is the same item.
                CatalogueEntry mirror = shown;
                std::swap(mirror.row, mirror.col);
                mirror.id = mirror.label = "b" + symbolic::joined({std::to_string(mirror.row + 1), std::to_string(mirror.col + 1)});
                build.add(std::move(mirror), value, value);
            }
        }
    return build.finish(definitions);
}

}  // namespace ll
