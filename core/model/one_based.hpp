#pragma once
// The notes number joints, links and coordinates from 1 (q1, b12, T_2^0); the code
// indexes from 0. idx(i) is the number the notes write for index i.
#include <string>

namespace ll {

inline std::string idx(int i) { return std::to_string(i + 1); }

}  // namespace ll
