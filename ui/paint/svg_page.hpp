#pragma once
// A typeset page as an SVG file of its own, written from the marks the painter draws
// (ui/math_typesetter's MathMarks): each glyph's outline is defined once in <defs> and
// placed with <use> wherever it occurs; rules and brackets are rectangles and paths.
// Outlines, not text: the file shows the same on a machine without Latin Modern.
// (QSvgGenerator, used before, wrote a glyph's whole outline at every occurrence: the
// Panda's 71 pages came to 130 MB in 7 s.)
#include <QSizeF>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

// Glyph outlines as SVG path data in points, each made once for all the pages of an
// export, from marks in device units, devicePerPt of them per point. Lay out at ten per
// point, as the PDF does: at one per point a glyph is shaped at 11 pixels, its advance
// rounded to whole points, and a line of prose came out 3 % too long or short.
class SvgGlyphs {
public:
    explicit SvgGlyphs(double devicePerPt = 10) : perDevice_(1.0 / devicePerPt) {}
    double ptPerDevice() const { return perDevice_; }
    // A font (family, style and pixel size)'s number: compared once per run, not per glyph.
    int font(const QRawFont& raw);
    // The number of glyph `glyph` of font number `font` among those seen; its outline is
    // outline(number).
    int number(int font, quint32 glyph);
    const std::string& outline(int number) const { return outlines_[static_cast<std::size_t>(number)]; }
    // Its element id: "g" and a 64-bit hash of the outline, so that two SVGs inlined in
    // one HTML page (other exports, other robots) give one id only to one shape.
    const std::string& id(int number) const { return ids_[static_cast<std::size_t>(number)]; }

private:
    double perDevice_;
    std::vector<QRawFont> fonts_;
    std::unordered_map<std::uint64_t, int> numbers_;  // by font << 32 | glyph
    std::vector<std::string> outlines_;               // empty for a blank glyph (a space)
    std::vector<std::string> ids_;
};

// The SVG document of one page sizePt points large, black marks on white; the marks are
// in glyphs' device units from the page's top-left corner.
std::string svgPage(const MathMarks& marks, QSizeF sizePt, const std::string& title, SvgGlyphs& glyphs);

}  // namespace ll::ui
