#pragma once
// A plot's tick step: 1, 2, 2.5 or 5 times a power of ten, the smallest at or above
// `least` (the window's time axes, the lab report's SVG plots).
#include <cmath>

namespace ll::ui {

inline double roundStep(double least) {
    const double decade = std::pow(10.0, std::floor(std::log10(least)));
    for (double m : {1.0, 2.0, 2.5, 5.0})
        if (m * decade >= least * (1 - 1e-9)) return m * decade;
    return 10 * decade;
}

}  // namespace ll::ui
