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
    QPointF at;                    // Text: baseline start; Rule: top-left; Bracket: top-left
    QString text;                  // Text
    int font = 0;                  // Text: 0 roman, 1 italic, 2 math (Greek, operators)
    double size = 1;               // Text: relative size (1 normal, 0.7 script)
    double width = 0, height = 0;  // Rule, Bracket
    char bracket = '[';            // Bracket: [ ] ( ) |
    int link = -1;                 // Text: a link's inertial parameter (m2, ℓc2), drawn in its colour by the window
};

// Where an entry of a matrix (row, col, 0-based) is drawn, relative to the box's origin:
// what a click in the window picks.
struct MathRegion {
    QRectF rect;  // units
    int row = 0, col = 0;
};

struct MathBox {
    double width = 0, ascent = 0, descent = 0;  // units
    std::vector<MathPiece> pieces;
    std::vector<MathRegion> regions;  // the cells of the outermost matrix in it, if any
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
std::vector<MathBox> layoutItem(const present::DisplayItem& item, double maxWidth, present::Language language = present::Language::English);

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
        int link = -1;             // collected by link: the link whose symbols these are (−1: ink)
    };
    struct Shape {
        enum Kind { Rect, Fill, Stroke } kind = Rect;
        QRectF rect;          // Rect: filled
        QPainterPath path;    // Fill: filled (its own fill rule); Stroke: drawn with the pen
        double penWidth = 0;  // Stroke
    };
    std::vector<Glyphs> glyphs;
    std::vector<Shape> shapes;
};

// Adds box's marks, its origin (baseline start) at `origin`, in units scaled by `scale`
// device units per layout unit. `byLink`: a link's symbols in runs of their own, to be
// painted in its colour (the window); pages keep one run per font.
void collectMarks(const MathBox& box, QPointF origin, double scale, MathMarks& marks, bool byLink = false);

// Paints marks in the painter's pen colour (a link's runs in the link's colour): the
// shapes, then the glyph runs.
void paintMarks(QPainter& painter, const MathMarks& marks);

// Draws box with its origin (baseline start) at `origin`, in units scaled by `scale`
// device units per layout unit (collectMarks, then paintMarks); `linkColours`: each
// link's inertial parameters in its colour (core/visual/link_colors).
void paintMath(QPainter& painter, const MathBox& box, QPointF origin, double scale, bool linkColours = false);

// The three fonts (roman, italic, math) at a size in units; loads fonts-lmodern's files
// into Qt's font database on first use. False when the font files are missing.
bool mathFontsAvailable();

// `base` in Latin Modern Roman, for a widget's text that names symbols with dots (q̇, q̈):
// Qt 6.4 on Debian 12 draws no combining mark at all in DejaVu Sans, the desktop's sans
// font (DejaVu Serif and Latin Modern draw them), so "B q̈ + C q̇" would read "B q + C q".
QFont textbookFont(QFont base);

}  // namespace ll::ui
