#pragma once
// A derivation typeset on pages (ui/math_typesetter): the title, each step's heading and
// general formula, and this system's results, one item after another; a page breaks
// between items, never through one (only an item taller than a page is split, between
// its lines). The same pages are written as PDF (QPdfWriter: text stays text), SVG
// (ui/svg_page: each glyph's outline defined once) and PNG, headless (Qt's offscreen
// platform is enough).
#include <QString>
#include <functional>
#include <string>
#include <vector>

#include "core/present/derivation_document.hpp"
#include "ui/paint/math_typesetter.hpp"

class QPainter;

namespace ll::ui {

struct PageFormat {
    double widthPt = 842, heightPt = 595;  // A4 landscape: long entries need the width
    double marginPt = 42;
    double fontPt = 11;                                            // the em of the formulas
    double unitsPerPt() const { return mathUnitsPerEm / fontPt; }  // layout units per point
};

struct PlacedBox {
    MathBox box;
    QPointF origin;  // baseline start, in layout units from the page's top-left corner
};

struct DerivationPages {
    PageFormat format;
    std::vector<std::vector<PlacedBox>> pages;
    present::Language language = present::Language::English;  // the document's: the file's title
};

DerivationPages paginate(const present::DisplayDocument& document, const PageFormat& format = {});

// The same, handing each page to `sink` as soon as it is complete, in order.
using PageSink = std::function<void(std::vector<PlacedBox>&&)>;
void paginate(const present::DisplayDocument& document, const PageFormat& format, const PageSink& sink);

// Page `index` onto a painter whose device has `devicePerPt` device units per point.
void paintPage(QPainter& painter, const DerivationPages& pages, int index, double devicePerPt);

// Writes the file; false with a one-line reason in `error`. SVG and PNG write page 1 to
// `path` and page k to path's stem + "-k" + extension; `written` lists the files.
bool writePdf(const DerivationPages& pages, const QString& path, std::string& error);
bool writePdf(const present::DisplayDocument& document, const QString& path, std::string& error, const PageFormat& format = {},
              int* pageCount = nullptr);
bool writeSvg(const DerivationPages& pages, const QString& path, std::string& error, std::vector<QString>* written = nullptr);
bool writePng(const DerivationPages& pages, const QString& path, std::string& error, std::vector<QString>* written = nullptr,
              double dpi = 150);

// The page files beside `path` past its first `pageCount` (STEM-(pageCount+1).EXT and on,
// while they exist): left by an earlier, longer export into the same name. They are
// named to the user, never deleted (they may be kept on purpose).
std::vector<QString> pagesBeyond(const QString& path, int pageCount);
// Their names as a message gives them: "b-5.svg", or "b-5.svg … b-9.svg".
QString fileNameRange(const std::vector<QString>& files);

}  // namespace ll::ui
