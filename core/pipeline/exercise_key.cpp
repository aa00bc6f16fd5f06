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

const KeyEntry* entryById(const AnswerKey::Data& k, const std::string& id) {
    for (const KeyEntry& e : k.entries)
        if (e.id == id) return &e;
    return nullptr;
}

}  // namespace

std::vector<std::string> entriesOfSteps(const AnswerKey& key, int first, int last) {
    std::vector<std::string> ids;
    for (int step = first; step <= last; ++step)
        for (const std::string& id : key.practiceEntries(step)) ids.push_back(id);
    return ids;
}

std::vector<std::string> defaultEntries(const AnswerKey& key) {
    const auto lock = symbolic::lockGinac();
    std::vector<std::string> worth = key.practiceEntries(7), more = key.practiceEntries(8), ids;
    worth.insert(worth.end(), more.begin(), more.end());
    for (EntryKind kind : {EntryKind::MassMatrix, EntryKind::Gravity, EntryKind::Coriolis})
        for (const KeyEntry& e : key.data().entries)
            if (e.kind == kind && std::find(worth.begin(), worth.end(), e.id) != worth.end()) ids.push_back(e.id);
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
