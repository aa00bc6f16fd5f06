#pragma once
// Display-only rewriting of an expanded polynomial in c_i = cos q_i, s_i = sin q_i into
// the textbook's combined-angle shorthand, exactly:
//   k c_A c_B M − k s_A s_B M → k c_{A∪B} M,    k s_A c_B M + k c_A s_B M → k s_{A∪B} M
// for disjoint index sets A, B, repeated to a fixpoint (c1 c2 − s1 s2 → c12, and on to
// c123). Only sums of angles: differences are not the shorthand used here.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "core/symbolic/trig_names.hpp"

namespace ll::present {

using symbolic::TrigName;

// Rewrites expressions of one system. Keeps the symbols it introduces, so entries of
// one matrix, or several results, share c12 and definitions() covers them all.
class AngleSumCombiner {
public:
    // q: the coordinates q1..qn that the definitions are written in. The c_i, s_i of
    // the input are recognised by name (derivation.hpp).
    explicit AngleSumCombiner(std::vector<GiNaC::symbol> q);

    // e expanded and rewritten; other factors (parameters, velocities) stay as they are.
    GiNaC::ex combine(const GiNaC::ex& e);
    GiNaC::matrix combine(const GiNaC::matrix& m);

    // c12 == cos(q1 + q2), s12 == sin(q1 + q2), ... for every combined symbol that
    // combine() produced or met, in a fixed order; e.subs(definitions()) removes them.
    GiNaC::lst definitions() const;

private:
    const GiNaC::symbol& symbolFor(const TrigName& trig);
    std::vector<GiNaC::symbol> q_;
    std::map<TrigName, GiNaC::symbol> symbols_;  // every trig symbol seen or made
};

struct AngleSumForm {
    GiNaC::ex value;
    GiNaC::lst definitions;  // of the combined symbols in value (c12 == cos(q1 + q2))
};

// One-shot form of AngleSumCombiner (a matrix is combined entry by entry).
AngleSumForm combineAngleSums(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& q);

}  // namespace ll::present
