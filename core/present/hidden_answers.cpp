#include "core/present/hidden_answers.hpp"

namespace ll::present {

namespace {

// The structured form's single entries (b_jk, c_ij, g_j, Q_j) of a matrix of the dynamics.
Quantity singleEntryOf(Quantity matrix) {
    switch (matrix) {
        case Quantity::MassMatrix: return Quantity::MassMatrixEntry;
        case Quantity::CoriolisMatrix: return Quantity::CoriolisEntry;
        case Quantity::GravityVector: return Quantity::GravityEntry;
        case Quantity::GeneralizedForces: return Quantity::ForceEntry;
        default: return matrix;
    }
}

// `node` with the child `from` (compared by identity) replaced by `to`, one level deep.
DisplayPtr replaced(const DisplayPtr& node, const DisplayPtr& from, const DisplayPtr& to) {
    if (!node) return node;
    if (node == from) return to;
    auto copy = std::make_shared<DisplayNode>(*node);
    for (DisplayPtr& child : copy->children)
        if (child == from) child = to;
    return copy;
}

void hideIn(DisplayItem& item, const EntryPlace& place) {
    const bool whole = place.row < 0 || !item.value || item.value->kind != DisplayKind::Matrix;
    DisplayPtr value = hiddenAnswer();
    if (!whole) {
        auto matrix = std::make_shared<DisplayNode>(*item.value);
        const auto r = static_cast<std::size_t>(place.row), c = static_cast<std::size_t>(std::max(place.col, 0));
        if (r >= matrix->rows.size() || c >= matrix->rows[r].size()) return;
        matrix->rows[r][c] = hiddenAnswer();
        // B is symmetric: b_ji would give b_ij away
        if (item.quantity == Quantity::MassMatrix && c < matrix->rows.size() && r < matrix->rows[c].size())
            matrix->rows[c][r] = hiddenAnswer();
        value = matrix;
    }
    if (item.quantity == Quantity::EquationOfMotion && item.equation && !item.equation->children.empty()) {
        // both sides are the answer's: the left (B q̈ + C q̇ + g) hidden, the inputs Q kept
        item.equation = replaced(item.equation, item.equation->children.front(), hiddenAnswer());
        return;
    }
    item.equation = replaced(item.equation, item.value, value);
    item.value = value;
}

bool holds(const DisplayItem& item, const EntryPlace& place) {
    if (item.quantity == place.quantity) return place.index < 0 || item.row == place.index;
    // the structured form: the single entry b_jk as its own item
    return item.quantity == singleEntryOf(place.quantity) && item.quantity != place.quantity && item.row == place.row &&
           std::max(item.col, 0) == std::max(place.col, 0);
}

}  // namespace

DisplayPtr hiddenAnswer() {
    static const DisplayPtr shown = displayRaw("?", "\\boxed{?}", "?");
    return shown;
}

DisplayDocument withAnswersHidden(const DisplayDocument& document, const std::vector<EntryPlace>& hidden) {
    DisplayDocument out = document;
    // The control law writes τ with the derived g, B, C in place: it would give them away.
    if (!hidden.empty()) std::erase_if(out.steps, [](const DisplayStep& s) { return s.number == symbolic::controlStepNumber; });
    for (const EntryPlace& place : hidden)
        for (DisplayStep& step : out.steps) {
            if (step.number != place.step) continue;
            for (DisplayItem& item : step.items) {
                if (!holds(item, place)) continue;
                if (item.quantity == place.quantity) hideIn(item, place);
                else hideIn(item, {place.step, item.quantity, item.row, -1, -1});  // the whole single entry
            }
        }
    return out;
}

}  // namespace ll::present
