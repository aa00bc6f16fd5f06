#include "core/present/term_order.hpp"

#include <algorithm>

namespace ll::present {

void TermKey::add(const SymbolMeaning& symbol, int power) {
    if (symbol.role == SymbolRole::Velocity && power > 0)
        velocities.insert(velocities.end(), power, symbol.indices.empty() ? 0 : symbol.indices.back());
    if (symbol.role == SymbolRole::Trig) trig = true;
    if (symbol.role != SymbolRole::Velocity && !symbol.indices.empty())
        maxIndex = std::max(maxIndex, *std::max_element(symbol.indices.begin(), symbol.indices.end()));
}

int compareTermKeys(const TermKey& a, const TermKey& b) {
    if (a.velocities != b.velocities) return a.velocities < b.velocities ? -1 : 1;
    if (a.maxIndex != b.maxIndex) return a.maxIndex < b.maxIndex ? -1 : 1;
    if (a.trig != b.trig) return a.trig ? 1 : -1;
    if (a.degree != b.degree) return a.degree < b.degree ? -1 : 1;
    return a.text.compare(b.text);
}

bool operator<(const FactorKey& a, const FactorKey& b) {
    if (a.rank != b.rank) return a.rank < b.rank;
    if (a.indices != b.indices) return a.indices < b.indices;
    return a.text < b.text;
}

int symbolRank(SymbolRole role) {
    switch (role) {
        case SymbolRole::Mass: return 1;
        case SymbolRole::Parameter: return 2;
        case SymbolRole::Coordinate: return 3;
        case SymbolRole::Trig: return 4;
        case SymbolRole::Velocity: return 7;
    }
    return 2;
}

FactorKey symbolFactorKey(const std::string& name, const SymbolMeaning& meaning) {
    FactorKey k{symbolRank(meaning.role), meaning.indices.empty() ? std::vector<int>{INT_MAX} : meaning.indices, name};
    if (meaning.role == SymbolRole::Trig) k.indices.push_back(meaning.trigKind == 'c' ? 0 : 1);  // c1 before s1
    return k;
}

}  // namespace ll::present
