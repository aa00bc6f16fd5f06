#include "core/model/usable_number.hpp"

#include <cmath>
#include <limits>

#include "core/model/diagnostics.hpp"

namespace ll {

std::optional<std::string> unusableNumber(double value) {
    if (!std::isfinite(value)) return "value is not finite (" + formatValue(value) + ")";
    if (std::fpclassify(value) == FP_SUBNORMAL)
        return "value " + formatValue(value) + " is too close to zero for double precision (subnormal, below " +
               formatValue(std::numeric_limits<double>::min()) + "): write 0 for zero, else check the exponent";
    return std::nullopt;
}

}  // namespace ll
