#pragma once
// The one sentence that says which coordinates have an input, used by the derivation
// (step 8), `derive` and `simulate`:
//   "inputs on q1, q2 (fully actuated)"
//   "inputs on theta2 (underactuated: m = 1 < n = 2)"
//   "no inputs (underactuated: m = 0 < n = 2)"
#include <string>
#include <vector>

namespace ll {

// actuated: 0-based coordinates with an input; coordinateNames: all n coordinates.
std::string actuationText(const std::vector<int>& actuated, const std::vector<std::string>& coordinateNames);

}  // namespace ll
