#include "core/model/usable_number.hpp"

#include <cmath>
#include <limits>

#include "core/model/diagnostics.hpp"

namespace ll {

std::optional<Message> unusableNumber(double value) {
    if (!std::isfinite(value)) return message(MessageId::ValueNotFinite, value);
    if (std::fpclassify(value) == FP_SUBNORMAL) return message(MessageId::ValueSubnormal, value, std::numeric_limits<double>::min());
    return std::nullopt;
}

}  // namespace ll
