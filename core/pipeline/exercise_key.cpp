// What an exercise set takes from the answer key: the tasks of a step, the default tasks,
// and a right answer in Maxima's syntax (core/pipeline/exercise_set.hpp). GiNaC, under its lock.
#include <cctype>
#include <sstream>

#include "core/pipeline/answer_key_data.hpp"
#include "core/present/display_builder.hpp"
#include "core/present/expression_printer.hpp"
#include "core/present/labels.hpp"
#include "core/present/textbook_form.hpp"
#include "core/pipeline/exercise_set.hpp"
#include "core/symbolic/exact_numbers.hpp"
#include "core/symbolic/ginac_lock.hpp"

namespace ll {
namespace {

// The quantity of the derivation an entry belongs to (its step's), or nothing (a
// Christoffel symbol: C's entries are asked instead).
std::optional<std::pair<symbolic::Quantity, int>> quantityOfEntry(const KeyEntry& e) {
    using symbolic::Quantity;
    switch (e.kind) {
        case EntryKind::MassMatrix: return std::pair{Quantity::MassMatrix, -1};
        case EntryKind::Coriolis: return std::pair{Quantity::CoriolisMatrix, -1};
        case EntryKind::Gravity: return std::pair{Quantity::GravityVector, -1};
        case EntryKind::Force: return std::pair{Quantity::GeneralizedForces, -1};
        case EntryKind::KineticEnergy: return std::pair{Quantity::KineticEnergy, -1};
        case EntryKind::PotentialEnergy: return std::pair{Quantity::PotentialEnergy, -1};
        case EntryKind::Equation: return std::pair{Quantity::EquationOfMotion, e.i};
        case EntryKind::Item: return std::pair{e.quantity, e.index};
        case EntryKind::Christoffel: break;
    }
    return std::nullopt;
}

int stepOfEntry(const AnswerKey::Data& k, const KeyEntry& e) {
    const auto quantity = quantityOfEntry(e);
    if (!quantity) return -1;
    for (const symbolic::DerivationStep& step : k.derivation.steps)
        for (const symbolic::DerivationItem& item : step.items)
            if (item.quantity == quantity->first && (quantity->second < 0 || item.index == quantity->second)) return step.number;
    return -1;
}

// Worth asking: not zero, not a constant of a matrix (the 1 of a transform's last row),
// not b_ij below the diagonal (it is b_ji).
bool worthAsking(const AnswerKey::Data& k, const KeyEntry& e) {
    if (e.kind == EntryKind::Christoffel) return false;
    if (e.kind == EntryKind::MassMatrix && e.i > e.j) return false;
    const GiNaC::ex value = k.valueOf(e).expand();
    if (value.is_zero()) return false;
    return !(e.kind == EntryKind::Item && GiNaC::is_a<GiNaC::numeric>(value));
}

const KeyEntry* entryById(const AnswerKey::Data& k, const std::string& id) {
    for (const KeyEntry& e : k.entries)
        if (e.id == id) return &e;
    return nullptr;
}

}  // namespace

std::vector<std::string> entriesOfSteps(const AnswerKey& key, int first, int last) {
    const auto lock = symbolic::lockGinac();
    const AnswerKey::Data& k = key.data();
    std::vector<std::string> ids;
    for (const KeyEntry& e : k.entries) {
        const int step = stepOfEntry(k, e);
        if (step >= first && step <= last && worthAsking(k, e)) ids.push_back(e.id);
    }
    return ids;
}

std::vector<std::string> defaultEntries(const AnswerKey& key) {
    const auto lock = symbolic::lockGinac();
    const AnswerKey::Data& k = key.data();
    std::vector<std::string> ids;
    for (EntryKind kind : {EntryKind::MassMatrix, EntryKind::Gravity, EntryKind::Coriolis})
        for (const KeyEntry& e : k.entries)
            if (e.kind == kind && worthAsking(k, e)) ids.push_back(e.id);
    return ids;
}

present::DisplayPtr exerciseAnswerDisplay(const AnswerKey& key, const std::string& id) {
    const auto lock = symbolic::lockGinac();
    const AnswerKey::Data& k = key.data();
    const KeyEntry* found = entryById(k, id);
    if (!found) return nullptr;
    const KeyEntry& e = *found;
    present::DisplayOptions options = present::displayOptions(present::printOptionsFor(k.derivation, present::Style::Text));
    options.readableNumbers = true;
    options.typedDecimals = k.derivation.typedDecimals;
    present::TextbookForm form(k.derivation);  // as the derivation reads: c12, common factors, grouped
    if (e.kind == EntryKind::Equation) {
        std::vector<present::DisplayPtr> parts;
        for (const GiNaC::ex& part : form.equationParts(e.i))
            if (!part.is_zero()) parts.push_back(present::buildDisplay(part, options));
        if (const GiNaC::ex* relation = k.itemValue(k.derivation, symbolic::Quantity::EquationOfMotion, e.i))
            return present::displayEquation(present::displaySumOf(parts),
                                            present::buildDisplay(form(relation->rhs(), form.plainGrouping()), options));
    }
    // the derivation's own value, in its textbook form (c12, not c1 c2 − s1 s2)
    const symbolic::Derivation& d = k.derivation;
    GiNaC::ex value;
    switch (e.kind) {
        case EntryKind::MassMatrix: value = d.B(e.i, e.j); break;
        case EntryKind::Coriolis: value = d.C(e.i, e.j); break;
        case EntryKind::Gravity: value = d.g(e.i, 0); break;
        case EntryKind::Force: value = d.Q(e.i, 0); break;
        case EntryKind::KineticEnergy: value = d.Ekin; break;
        case EntryKind::PotentialEnergy: value = d.Epot; break;
        case EntryKind::Item:
            if (const GiNaC::ex* item = k.itemValue(d, e.quantity, e.index))
                value = GiNaC::is_a<GiNaC::matrix>(*item) ? GiNaC::ex_to<GiNaC::matrix>(*item)(e.i, e.j) : *item;
            break;
        default: value = k.valueOf(e).subs(k.toShorthand, GiNaC::subs_options::no_pattern);
    }
    const symbolic::Grouping grouping = e.kind == EntryKind::Coriolis ? symbolic::Grouping::Velocities : form.plainGrouping();
    return present::displayEquation(present::displayLabel(id, entryLatex(id)), present::buildDisplay(form(value, grouping), options));
}

std::string maximaAnswer(const AnswerKey& key, const std::string& id) {
    const auto lock = symbolic::lockGinac();
    const KeyEntry* e = entryById(key.data(), id);
    if (!e) return "";
    std::ostringstream out;
    out << symbolic::exactFloats(key.data().valueOf(*e));  // GiNaC's own syntax: 2*a1*lc2*m2*cos(q2), a1^2, 1/2
    std::string text = out.str();
    for (std::size_t at = 0; (at = text.find("Pi", at)) != std::string::npos; at += 3) {
        const bool alone = (at == 0 || !std::isalnum(static_cast<unsigned char>(text[at - 1]))) &&
                           (at + 2 >= text.size() || !std::isalnum(static_cast<unsigned char>(text[at + 2])));
        if (alone) text.replace(at, 2, "%pi");
    }
    return e->kind == EntryKind::Equation ? text + " = 0" : text;
}

}  // namespace ll
