#pragma once
// A native math typesetter over the display tree (core/present/display_tree.hpp): boxes
// with width, ascent and descent laid out by TeX's rules for math, in Latin Modern
// (fonts-lmodern: Latin Modern Roman for letters and digits, Latin Modern Math for
// Greek, operators and brackets), painted with QPainter on any device — a widget, an
// PDF (QPdfWriter, text stays text), a QImage; its marks are also written as SVG
// (ui/svg_page).
//
// Units: layout is in em/40 ("units", 40 per em at size 1); paint scales them. Rules,
// with Latin Modern Math's constants (per 1000 em): math axis 250; fraction rule 40,
// numerator and denominator one size smaller (×0.75), centred on the axis with gaps of
// the rule's thickness; superscripts up 363, subscripts down 247, both at ×0.7 (×0.5
// in scripts of scripts); dots as accents over the letter; matrices with columns
// centred 1 em apart, rows 0.5 em apart, brackets drawn to the content's height;
// upright numbers and function names, italic variables; TeX's spacing: thick space
// around relations (5/18 em), medium around + and − (4/18 em), thin space beside
// function names and words (3/18 em), none in scripts.
#include <QFont>
#include <QList>
#include <QPainterPath>
#include <QPointF>
#include <QRawFont>
#include <QRectF>
#include <QString>
#include <memory>
#include <vector>

#include "core/present/display_document.hpp"

class QPainter;

namespace ll::ui {

// One thing to draw, relative to the box's origin on its baseline (y grows downwards).
struct MathPiece {
    enum Kind { Text, Rule, Bracket } kind = Text;
    QPointF at;        // Text: baseline start; Rule: top-left; Bracket: top-left
    QString text;      // Text
    int font = 0;      // Text: 0 roman, 1 italic, 2 math (Greek, operators)
    double size = 1;   // Text: relative size (1 normal, 0.7 script)
    double width = 0, height = 0;  // Rule, Bracket
    char bracket = '[';            // Bracket: [ ] ( ) |
};

struct MathBox {
    double width = 0, ascent = 0, descent = 0;  // units
    std::vector<MathPiece> pieces;
    double height() const { return ascent + descent; }
};

constexpr double mathUnitsPerEm = 40.0;

// Appends box to the right of `to` (gap units between), on the same baseline.
void hcat(MathBox& to, MathBox box, double gap = 0);

// node with every sum longer than maxTerms cut to its first terms and "⋯ (N more terms)",
// wherever it is (an entry, a product's parentheses, a fraction, a matrix cell).
present::DisplayPtr elided(const present::DisplayPtr& node, std::size_t maxTerms);

// The box of a node at relative size `size` (1 normal, 0.7 script, 0.5 scriptscript).
MathBox layoutMath(const present::DisplayNode& node, double size = 1.0);

// An equation "label = value" set to at most maxWidth units: a sum too wide breaks
// before its top-level + and − (continuation lines indented past "label = "). A sum of
// more than maxTypesetTerms terms (core/present/display_tree.hpp), at any depth, shows
// its first two thirds of that and "⋯ (N more terms)": the text and JSON formats keep
// every term. Returns the lines.
using present::maxTypesetTerms;
std::vector<MathBox> layoutEquation(const present::DisplayNode& equation, double maxWidth);

// An item of a derivation the same way; a matrix too wide becomes its entries listed
// under it, each named as core/present/labels.hpp names them (b11 = …, each breaking the
// same way).
std::vector<MathBox> layoutItem(const present::DisplayItem& item, double maxWidth);

// A step's general formula (core/present/latex_formula.hpp): its parts side by side,
// 2 em apart, a new line where the next part would pass maxWidth.
std::vector<MathBox> layoutFormula(const present::DisplayNode& formula, double maxWidth, double size = 1.0);

// A line of prose (a step's title or general formula) in the roman or bold font.
MathBox layoutText(const QString& text, double size = 1.0, bool bold = false);

// Prose with the symbols it names set as math: a single Latin letter with an index or
// dots (q1, c12, b7,10, x_0, q_i, q̇), or before a relation sign (the m of "m = 0"), is
// the typeset symbol, italic with its subscript; the rest is roman text, as layoutText
// sets it.
MathBox layoutProse(const QString& text, double size = 1.0);

// What boxes draw, in device units: every glyph of a font at one pixel size as one run,
// and the rules and brackets in the boxes' order. The one description both paintMarks
// (any QPainter) and the SVG writer (ui/svg_page) draw from.
struct MathMarks {
    struct Glyphs {
        QRawFont font;  // a family and style at a pixel size
        QList<quint32> indexes;
        QList<QPointF> positions;  // each glyph's origin on its baseline
    };
    struct Shape {
        enum Kind { Rect, Fill, Stroke } kind = Rect;
        QRectF rect;         // Rect: filled
        QPainterPath path;   // Fill: filled (its own fill rule); Stroke: drawn with the pen
        double penWidth = 0; // Stroke
    };
    std::vector<Glyphs> glyphs;
    std::vector<Shape> shapes;
};

// Adds box's marks, its origin (baseline start) at `origin`, in units scaled by `scale`
// device units per layout unit.
void collectMarks(const MathBox& box, QPointF origin, double scale, MathMarks& marks);

// Paints marks in the painter's pen colour: the shapes, then the glyph runs.
void paintMarks(QPainter& painter, const MathMarks& marks);

// Draws box with its origin (baseline start) at `origin`, in units scaled by `scale`
// device units per layout unit (collectMarks, then paintMarks).
void paintMath(QPainter& painter, const MathBox& box, QPointF origin, double scale);

// The three fonts (roman, italic, math) at a size in units; loads fonts-lmodern's files
// into Qt's font database on first use. False when the font files are missing.
bool mathFontsAvailable();

}  // namespace ll::ui
