// Where the answer key's entries stand in the derivation, and which of a step's entries an
// exercise asks for (core/pipeline/answer_check.hpp: AnswerKey::place, practiceEntries).
#include "core/pipeline/answer_check.hpp"
#include "core/pipeline/answer_key_data.hpp"

namespace ll {

namespace {

using symbolic::Quantity;

// The quantity of the derivation's item an entry kind belongs to.
Quantity itemQuantity(EntryKind kind) {
    switch (kind) {
        case EntryKind::MassMatrix: return Quantity::MassMatrix;
        case EntryKind::Coriolis: return Quantity::CoriolisMatrix;
        case EntryKind::Gravity: return Quantity::GravityVector;
        case EntryKind::Force: return Quantity::GeneralizedForces;
        case EntryKind::KineticEnergy: return Quantity::KineticEnergy;
        case EntryKind::PotentialEnergy: return Quantity::PotentialEnergy;
        case EntryKind::Equation: return Quantity::EquationOfMotion;
        default: return Quantity::NamedQuantity;
    }
}

present::EntryPlace placeOf(const AnswerKey::Data& k, const KeyEntry& e) {
    present::EntryPlace p;
    if (e.kind == EntryKind::Christoffel) return p;  // C is shown, its symbols are not
    if (e.kind == EntryKind::Item) {
        p.quantity = e.quantity;
        p.index = e.index;
        p.row = e.i;
        p.col = e.j;
    } else {
        p.quantity = itemQuantity(e.kind);
        if (e.kind == EntryKind::Equation) p.index = e.i;
        else if (e.kind != EntryKind::KineticEnergy && e.kind != EntryKind::PotentialEnergy) {
            p.row = e.i;
            p.col = std::max(e.j, 0);
        }
    }
    for (const symbolic::DerivationStep& step : k.derivation.steps)
        for (const symbolic::DerivationItem& item : step.items)
            if (item.quantity == p.quantity && (p.index < 0 || item.index == p.index)) p.step = step.number;
    return p;
}

const KeyEntry* entryNamed(const AnswerKey& key, const std::string& typed) {
    const std::string id = key.entryId(typed);
    for (const KeyEntry& e : key.data().entries)
        if (!id.empty() && e.id == id) return &e;
    return nullptr;
}

}  // namespace

present::EntryPlace AnswerKey::place(const std::string& id) const {
    const KeyEntry* e = entryNamed(*this, id);
    return e ? placeOf(*data_, *e) : present::EntryPlace{};
}

std::vector<std::string> AnswerKey::practiceEntries(int step) const {
    const auto lock = symbolic::lockGinac();
    std::vector<std::string> out;
    for (const KeyEntry& e : data_->entries) {
        if (e.kind == EntryKind::Christoffel || e.kind == EntryKind::LinkPart || placeOf(*data_, e).step != step) continue;
        if (e.kind == EntryKind::MassMatrix && e.i > e.j) continue;  // it is b_ji
        const GiNaC::ex value = data_->valueOf(e).expand();
        if (value.is_zero() || (e.kind == EntryKind::Item && GiNaC::is_a<GiNaC::numeric>(value))) continue;  // nothing to derive
        out.push_back(e.id);
    }
    return out;
}

std::vector<std::string> AnswerKey::entriesOf(const std::string& typed) const {
    if (const std::string id = entryId(typed); !id.empty()) return {id};
    const auto whole = data_->wholeByKey.find(entryKey(typed));
    if (whole == data_->wholeByKey.end()) return {};
    std::vector<std::string> out;
    for (std::size_t e : data_->wholes[whole->second].entries) out.push_back(data_->entries[e].id);
    return out;
}

}  // namespace ll
