#pragma once
// One colour per link, the same everywhere a link is shown: its rods in the 3D view and
// in rendered videos, its row in the window's tables, its inertial parameters (m_i, I_i,
// ℓc_i) in the typeset formulas. Colour-blind-safe Okabe–Ito hues, in turn.
namespace ll {

struct Rgba {
    float r = 0.5f, g = 0.5f, b = 0.5f, a = 1.0f;
};

// Link `link` (0-based); the palette repeats after six links.
Rgba linkColor(int link);

}  // namespace ll
