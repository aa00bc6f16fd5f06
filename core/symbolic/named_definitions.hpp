#pragma once
// An ordered table of small named quantities, the way SYMORO, ROBOTRAN and the explicit
// PUMA model of Armstrong–Khatib–Burdick write a robot's dynamics: each entry is a
// few operations over the coordinates (c_i, s_i, q_i), the parameters and earlier
// names; B, C and g are short sums over the names. Naming while deriving keeps every
// expression small, so the cost grows polynomially with the joints instead of
// exponentially (../shared/notes/derivation-at-scale.md).
//
// name() hash-conses: an expression (or its negative) is named once; numbers, symbols
// and number·symbol are never named. Each definition is expanded and trig-reduced on
// its own (TrigContext::reduce). Plain data (strings, indices) describes each entry so
// that printers and the display tree can render the table without GiNaC knowledge.
// Call everything with the GiNaC lock held (ginac_lock.hpp).
#include <atomic>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include <ginac/ginac.h>

#include "core/model/message.hpp"

#include "core/symbolic/shared_symbol.hpp"
#include "core/symbolic/trig_context.hpp"

namespace ll::symbolic {

struct NamedDefinition {
    GiNaC::ex symbol;               // a GiNaC::symbol made once on the heap (sharedSymbol): every expression naming it shares it
    std::string name;               // its plain name, a re-parsable identifier: "z2x_4"
    GiNaC::ex value;                // over q, c_i, s_i, parameters and earlier names
    std::string latex;              // "{}^{4}z_{2,x}"
    Message meaning;                // "x of axis z_2 of frame 2 in the frame of link 4" (an id of symbolic.def)
    int step = 0;                   // the step of the course notes where it arises (1..8)
    int link = -1;                  // the link (0-based) whose quantity it is (β_jk⁽ⁱ⁾, J_P,j⁽ⁱ⁾, its frames); -1: none
    std::string unit;               // SI, "" when dimensionless: "m" for an origin, "kg·m²" for β between revolute joints
    std::vector<int> dependencies;  // indices of the earlier entries its value uses
    std::uint64_t coordinates = 0;  // bit k set: depends on q_{k+1} (directly or through names)
};

class NamedDefinitions {
public:
    explicit NamedDefinitions(const TrigContext& tc);

    // When set, name() and unfold() throw Cancelled before each new name or unfolding
    // step once *cancel is true; the table keeps only whole entries.
    void setCancel(const std::atomic<bool>* cancel) { cancel_ = cancel; }

    // e reduced; returned as it is when it is zero, a number, a symbol or number·symbol;
    // the entry's symbol (or its negative) when e (or −e) was named before; else a new
    // entry named `plain`, of `link` (−1: none), in `unit`.
    GiNaC::ex name(const GiNaC::ex& e, const std::string& plain, const std::string& latex, const Message& meaning, int step, int link = -1,
                   const std::string& unit = "");

    const std::vector<NamedDefinition>& entries() const { return entries_; }
    int size() const { return static_cast<int>(entries_.size()); }
    // The entry of a symbol, -1 for any other symbol.
    int indexOf(const GiNaC::ex& symbol) const;
    // The coordinates e depends on (bit k: q_{k+1}), through the names it uses.
    std::uint64_t coordinatesOf(const GiNaC::ex& e) const;
    // The entries e uses directly, ascending.
    std::vector<int> dependenciesOf(const GiNaC::ex& e) const;
    // Every entry e needs, directly or not, ascending (its dependency cone).
    std::vector<int> coneOf(const GiNaC::ex& e) const;

    // e with every name unfolded into c_i, s_i, q_i and parameters, reduced: the fully
    // expanded form, with constant angles that are numbers folded (TrigContext::reduce). Memoised per name; checks `cancel` (and the table's own flag)
    // between names.
    GiNaC::ex unfold(const GiNaC::ex& e, const std::atomic<bool>* cancel = nullptr);

    const TrigContext& trig() const { return tc_; }

private:
    const TrigContext& tc_;
    const std::atomic<bool>* cancel_ = nullptr;
    std::vector<NamedDefinition> entries_;
    std::unordered_map<GiNaC::ex, int, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> byValue_;
    // By symbol, hashed (a symbol's hash is its serial number's): a std::map compared
    // symbols through GiNaC's compare, type check first, at every step of every lookup.
    std::unordered_map<GiNaC::ex, int, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> bySymbol_;
    std::unordered_map<GiNaC::ex, int, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> coordinateOf_;  // q_k, c_k, s_k → k
    std::vector<GiNaC::ex> unfolded_;                                                            // memo of unfold, per entry
    std::vector<bool> isUnfolded_;
};

// Numbers for every entry of a table, in order, at one state: each definition
// evaluated with doubles from the values of its inputs. `inputs` gives q_i, c_i, s_i,
// q̇_i and the parameters their values (symbol == number).
class DefinitionValues {
public:
    // Throws Cancelled when *cancel turns true (checked every few entries).
    DefinitionValues(const NamedDefinitions& table, const GiNaC::lst& inputs, const std::atomic<bool>* cancel = nullptr);
    double operator()(const GiNaC::ex& e) const;  // any expression over the inputs and names
    // The same with every sum taken over absolute values: the size of the terms whose
    // cancellation gives operator()(e), for telling a rounding residue from a value.
    double magnitude(const GiNaC::ex& e) const;

private:
    // By symbol, hashed: a std::map of GiNaC comparisons made these lookups a third of
    // the Panda's structured derivation.
    using Values = std::unordered_map<GiNaC::ex, double, std::hash<GiNaC::ex>, GiNaC::ex_is_equal>;
    Values values_, magnitudes_;
};

}  // namespace ll::symbolic
