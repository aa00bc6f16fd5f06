#pragma once
// One number style per entry. A student writes 0.0005 and 0.0001, and never 1·10⁻⁴, so
// an entry (a scalar, an equation as a whole, each entry of a matrix) whose decimals all
// fit in eight places after the point shows them all as plain decimals (5·10⁻⁴ → 0.0005;
// the UR5's b11 with 0.0110055 and 0.160218), and one where some decimal needs more
// (the UR5's I_l4⁰[1,1] with 0.00156933 and 0.000670586) shows every decimal below 1 in
// scientific notation (1.56933·10⁻³ − 6.70586·10⁻⁴ c1² s2² …), never the two mixed.
// Integers, fractions and decimals of 1 or more are never touched; a mantissa of 1 is
// left out everywhere (10⁻⁴, not 1·10⁻⁴: number_spelling.cpp). Plain (JSON's exact
// values, re-parsing) never changes.
//
// Tried first and dropped: six places (the UR5's b11 became 1.60218·10⁻¹ + 2.10875 c2²
// + … for one 0.0110055), and one style per matrix (its b66 of 0.000… turned all of B
// into powers of ten).
#include "core/present/display_document.hpp"
#include "core/present/display_tree.hpp"

namespace ll::present {

enum class NumberStyle { Plain, Scientific };

// The style `node`'s decimals call for.
NumberStyle numberStyleOf(const DisplayNode& node);

// `node` with its decimals in `style`; the subtrees without a change are shared, not copied.
DisplayPtr withNumberStyle(const DisplayPtr& node, NumberStyle style);

// An item's equation and value in the one style its equation calls for.
void useOneNumberStyle(DisplayItem& item);

}  // namespace ll::present
