#include "core/model/usable_number.hpp"

#include <cmath>
#include <limits>

#include "core/model/diagnostics.hpp"

namespace ll {

std::optional<std::string> unusableNumber(double value) {
    if (!std::isfinite(value)) return "value is not finite (" + formatValue(value) + ")";
    if (std::fpclassify(value) == FP_SUBNORMAL)
        return "value " + formatValue(value) + " is too close to zero for double precision (subnormal: non-zero but below " +
               formatValue(std::numeric_limits<double>::min()) + " in magnitude): write 0 if you mean zero, else check the exponent";
    return std::nullopt;
}

}  // namespace ll
