#pragma once
// The order in which a sum's terms and a product's factors are shown, the same on
// every run (GiNaC's own order follows hashes). Decided from what the symbols mean
// (symbol_names.hpp); the builder (display_builder.hpp) fills the keys.
//
// Terms of a sum, by their key compared in turn:
//   1. the indices of its velocity factors (none first; q̇1 before q̇1 q̇2 before q̇2),
//   2. the largest index of any other symbol (I1, m1 ℓc1² before I2),
//   3. without trigonometry before with it, 4. total degree, 5. the term's Plain
//   rendering without its coefficient; then 6. the coefficient.
// Factors of a product: number, constants (π), masses, other parameters, coordinates,
// c/s symbols, functions, parenthesised sums, velocities; within a group by index, then
// by name (m2 a1 ℓc2 s2 q̇2).
#include <climits>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/present/symbol_names.hpp"

namespace ll::present {

struct TermKey {
    std::vector<int> velocities;  // indices of the velocity factors, with repetition, sorted
    int maxIndex = -1;            // of every other symbol
    bool trig = false;
    GiNaC::numeric degree = 0;
    std::string text;  // Plain, without the coefficient
    // What a symbol adds (its power given): its velocity indices or its largest index,
    // and whether it is a c/s.
    void add(const SymbolMeaning& symbol, int power);
};

// <0, 0 or >0: the display order of two terms by everything but their coefficients.
int compareTermKeys(const TermKey& a, const TermKey& b);

// A factor's place in a product.
struct FactorKey {
    int rank = 0;
    std::vector<int> indices;
    std::string text;  // the factor's Plain spelling, the last tie-break
};
bool operator<(const FactorKey& a, const FactorKey& b);

// The rank of a symbol by what it means, and of the other kinds of factor.
int symbolRank(SymbolRole role);
inline constexpr int numberRank = 0, functionRank = 5, sumRank = 6;

// A symbol's key: its rank, its indices (none sorts last) and, for a c/s, c before s.
FactorKey symbolFactorKey(const std::string& name, const SymbolMeaning& meaning);

}  // namespace ll::present
