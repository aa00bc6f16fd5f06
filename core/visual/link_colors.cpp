#include "core/visual/link_colors.hpp"

namespace ll {

Rgba linkColor(int link) {
    static const Rgba palette[] = {{0 / 255.0f, 114 / 255.0f, 178 / 255.0f, 1},  {230 / 255.0f, 159 / 255.0f, 0, 1},
                                   {0, 158 / 255.0f, 115 / 255.0f, 1},           {204 / 255.0f, 121 / 255.0f, 167 / 255.0f, 1},
                                   {86 / 255.0f, 180 / 255.0f, 233 / 255.0f, 1}, {213 / 255.0f, 94 / 255.0f, 0, 1}};
    return palette[(link % 6 + 6) % 6];
}

}  // namespace ll
