#pragma once
// The names of the trigonometric shorthand of derivation.hpp, spelled and parsed in one
// place: c1 = cos q1, s12 = sin(q1 + q2), c9_10 = cos(q9 + q10).
#include <optional>
#include <string>
#include <vector>

namespace ll::symbolic {

struct TrigName {
    char kind = 'c';           // 'c' or 's'
    std::vector<int> indices;  // 1-based, ascending: c12 → {1, 2}
    auto operator<=>(const TrigName&) const = default;
};

// "c1", "s12", "c9_10". With 10 or more coordinates every combined name is joined by
// '_' (c1_2), so that c12 can only mean cos q12 there.
std::string trigSymbolName(const TrigName& trig, int coordinateCount = 0);

// The inverse; nullopt for anything else (lc1, c0, an index above coordinateCount when
// that is given, repeated indices). coordinateCount 0 means unknown (read as < 10).
std::optional<TrigName> parseTrigName(const std::string& name, int coordinateCount = 0);

}  // namespace ll::symbolic
