#pragma once
// Which typed numbers LagrangeLab computes with: finite doubles that are zero or normal.
// A subnormal number (non-zero, |x| < 2.2e-308) is refused: it is almost always a slip
// of the exponent (1e-310 for 1e-3), it has lost digits already, and GiNaC's number
// library (CLN) cannot hold it (it throws "floating point underflow"). The scene
// reader, the validation of scenes built in code and the command-line options all ask
// here, so every field is held to the same rule (README, "Scene files": numbers).
#include <optional>
#include <string>

#include "core/model/message.hpp"

namespace ll {

// Why `value` cannot be used as a field's number ("value is not finite (inf)", "value
// 1e-310 is subnormal ..."), or nothing when it can.
std::optional<Message> unusableNumber(double value);

}  // namespace ll
