#include "ui/paint/math_typesetter.hpp"

#include "core/present/labels.hpp"
#include "core/present/message_text.hpp"
#include "core/visual/link_colors.hpp"

#include <QCoreApplication>
#include <QFontDatabase>
#include <QFontMetricsF>
#include <QGlyphRun>
#include <QHash>
#include <QTextLayout>
#include <QPainter>
#include <QRawFont>
#include <QRegularExpression>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <unordered_map>

namespace ll::ui {
namespace {

using present::DisplayKind;
using present::DisplayNode;

// Latin Modern Math's MATH constants, per em.
constexpr double axisHeight = 0.250, ruleThickness = 0.040, superscriptUp = 0.363, subscriptDown = 0.247;
constexpr double thinSpace = 3.0 / 18, mediumSpace = 4.0 / 18, thickSpace = 5.0 / 18;
constexpr double scriptScale = 0.7, fractionScale = 0.75, smallestSize = 0.5;

QString families[3];

void loadFonts() {
    static std::once_flag once;
    std::call_once(once, [] {
        const char* files[3] = {"/usr/share/texmf/fonts/opentype/public/lm/lmroman10-regular.otf",
                                "/usr/share/texmf/fonts/opentype/public/lm/lmroman10-italic.otf",
                                "/usr/share/texmf/fonts/opentype/public/lm-math/latinmodern-math.otf"};
        const char* fallback[3] = {"Latin Modern Roman", "Latin Modern Roman", "Latin Modern Math"};
        for (int i = 0; i < 3; ++i) {
            const int id = QFontDatabase::addApplicationFont(files[i]);
            const QStringList names = id >= 0 ? QFontDatabase::applicationFontFamilies(id) : QStringList();
            families[i] = names.isEmpty() ? fallback[i] : names.first();
        }
    });
}

QFont font(int which, double size) {
    loadFonts();
    QFont f(families[which]);
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(mathUnitsPerEm * size))));
    f.setItalic(which == 1);
    f.setHintingPreference(QFont::PreferNoHinting);
    f.setKerning(true);
    return f;
}

struct Metrics {
    double width, ascent, descent;
};

// Advance width and ink extent of a run, cached (layout asks for the same glyphs often).
Metrics measure(const QString& text, int which, double size) {
    static std::map<std::pair<int, int>, QHash<QString, Metrics>> cache;  // by font and size in 1/1000
    static std::mutex mutex;
    std::lock_guard lock(mutex);
    QHash<QString, Metrics>& sized = cache[{which, static_cast<int>(std::lround(size * 1000))}];
    if (auto it = sized.find(text); it != sized.end()) return *it;
    const QFont f = font(which, size);
    const QFontMetricsF fm(f);
    const QRectF ink = fm.tightBoundingRect(text);
    const double scale = f.pixelSize() / (mathUnitsPerEm * size);  // rounding of the pixel size
    Metrics m{fm.horizontalAdvance(text) / scale, std::max(0.0, -ink.top()) / scale, std::max(0.0, ink.bottom()) / scale};
    sized.insert(text, m);
    return m;
}

double em(double size) { return mathUnitsPerEm * size; }

// The ink rectangle of a run in layout units (y down; above the baseline negative), from
// the glyphs' outlines: QFontMetricsF::tightBoundingRect reaches down to the baseline for
// accents (˙ in Latin Modern: 0.675 em tall instead of 0.125), which set the dots of q̇
// far too high.
QRectF inkOf(const QString& text, int which, double size) {
    const QFont f = font(which, size);
    const double scale = f.pixelSize() / (mathUnitsPerEm * size);
    const QRawFont raw = QRawFont::fromFont(f);
    const QList<quint32> glyphs = raw.glyphIndexesForString(text);
    const QList<QPointF> advances = raw.advancesForGlyphIndexes(glyphs);
    QRectF ink;
    double x = 0;
    for (qsizetype i = 0; i < glyphs.size(); ++i) {
        ink = ink.united(raw.boundingRect(glyphs[i]).translated(x, 0));
        x += advances.value(i).x();
    }
    return QRectF(ink.left() / scale, ink.top() / scale, ink.width() / scale, ink.height() / scale);
}

// Moves the pieces of box (a temporary, usually) into `to`, shifted.
void append(MathBox& to, MathBox box, double dx, double dy = 0) {
    // Room grows geometrically: reserving exactly the sum made a line built chunk by chunk
    // copy all its pieces on every chunk (quadratic: 20 s for the expanded Panda's pages).
    if (const std::size_t needed = to.pieces.size() + box.pieces.size(); needed > to.pieces.capacity())
        to.pieces.reserve(std::max(needed, 2 * to.pieces.capacity()));
    for (MathPiece& p : box.pieces) {
        p.at += QPointF(dx, dy);
        to.pieces.push_back(std::move(p));
    }
    for (MathRegion& r : box.regions) {
        r.rect.translate(dx, dy);
        to.regions.push_back(r);
    }
}

}  // namespace

void hcat(MathBox& to, MathBox box, double gap) {
    to.width += gap;
    const double w = box.width, a = box.ascent, d = box.descent;
    append(to, std::move(box), to.width);
    to.width += w;
    to.ascent = std::max(to.ascent, a);
    to.descent = std::max(to.descent, d);
}

namespace {

MathBox run(const QString& text, int which, double size) {
    MathBox b;
    if (text.isEmpty()) return b;
    const Metrics m = measure(text, which, size);
    b.width = m.width;
    b.ascent = m.ascent;
    b.descent = m.descent;
    MathPiece p;
    p.kind = MathPiece::Text;
    p.text = text;
    p.font = which;
    p.size = size;
    b.pieces.push_back(p);
    return b;
}

// Greek and letter-like symbols come from the math font: lowercase Greek as math
// italic (U+1D6FC…), capitals and ℓ upright as TeX sets them.
bool isGreekLower(char32_t c) { return c >= 0x03B1 && c <= 0x03C9; }
bool isMathSymbol(char32_t c) { return (c >= 0x0391 && c <= 0x03C9) || c == 0x2113 || c == 0x2112 || (c >= 0x2200 && c <= 0x22FF); }

// A word: Latin letters italic (upright when `upright`), digits and punctuation roman,
// Greek and ℓ from the math font; combining dots over the letter before them.
MathBox word(const QString& text, double size, bool upright) {
    MathBox b;
    const QList<uint> codes = text.toUcs4();
    for (qsizetype i = 0; i < codes.size(); ++i) {
        const char32_t c = codes[i];
        MathBox glyph;
        bool italic = false;
        if (isMathSymbol(c)) {
            char32_t shown = c;
            if (isGreekLower(c) && !upright) shown = 0x1D6FC + (c - 0x03B1);
            glyph = run(QString::fromUcs4(&shown, 1), 2, size);
            italic = isGreekLower(c);
        } else if (c < 0x80 && std::isalpha(static_cast<int>(c)) && !upright) {
            glyph = run(QString(QChar(c)), 1, size);
            italic = true;
        } else if (c == 0x0302 || c == 0x0307 || c == 0x0308) {
            continue;
        } else {
            glyph = run(QString::fromUcs4(&c, 1), 0, size);
        }
        const char32_t next = i + 1 < codes.size() ? codes[i + 1] : 0;
        if (next == 0x0302 || next == 0x0307 || next == 0x0308) {
            // The accent's ink centred over the letter's (skewed right for italics), a
            // small gap above the letter's x-height or top: ˙ ¨ for dots, ˆ for a hat.
            const QString mark = QString(QChar(next == 0x0302 ? 0x02C6 : next == 0x0307 ? 0x02D9 : 0x00A8));
            const MathBox accent = run(mark, 0, size);
            const QRectF ink = inkOf(mark, 0, size);
            const double x = glyph.width / 2 - ink.center().x() + (italic ? 0.1 * em(size) : 0);
            const double baseline = -(std::max(glyph.ascent, 0.45 * em(size)) + 0.08 * em(size)) - ink.bottom();
            append(glyph, accent, x, baseline);
            glyph.ascent = std::max(glyph.ascent, -baseline - ink.top());
        }
        hcat(b, glyph);
        if (italic && i + 1 == codes.size()) b.width += 0.03 * em(size);  // italic correction
    }
    return b;
}

MathBox op(const QString& symbol, double size) { return run(symbol, 2, size); }

MathBox bracket(char kind, double top, double height, double size) {
    MathBox b;
    const double w = (kind == '(' || kind == ')') ? 0.36 * em(size) : kind == '|' ? 0.25 * em(size) : 0.30 * em(size);
    b.width = w;
    b.ascent = -top;
    b.descent = top + height;
    MathPiece p;
    p.kind = MathPiece::Bracket;
    p.bracket = kind;
    p.at = QPointF(0, top);
    p.width = w;
    p.height = height;
    p.size = size;
    b.pieces.push_back(p);
    return b;
}

double scriptSize(double size) { return std::max(smallestSize, size * scriptScale); }

MathBox layout(const DisplayNode& n, double size);

// Delimiters around a box: the font's glyphs at normal heights, drawn to the content's
// height (centred on the axis) when taller.
MathBox fenced(const MathBox& content, char open, char close, double size) {
    MathBox b;
    const double a = axisHeight * em(size);
    if (content.ascent <= 1.0 * em(size) && content.descent <= 0.35 * em(size) && open == '(') {
        hcat(b, run("(", 0, size));
        hcat(b, content);
        hcat(b, run(")", 0, size));
        return b;
    }
    const double half = std::max(content.ascent - a, content.descent + a) + 0.1 * em(size);
    hcat(b, bracket(open, -a - half, 2 * half, size));
    hcat(b, content, 0.04 * em(size));
    hcat(b, bracket(close, -a - half, 2 * half, size), 0.04 * em(size));
    return b;
}

// base with sub- and superscript boxes (either may be empty).
// A letter (`letter`) keeps the font's script shifts whatever accents sit on it; a
// taller base (parentheses, a fraction) lifts the superscript with its top.
MathBox scripted(MathBox base, const MathBox* sub, const MathBox* sup, double size, double italicCorrection = 0, bool letter = false) {
    const double e = em(size);
    double up = 0, down = 0;
    if (sup) up = std::max({superscriptUp * e, letter ? 0.0 : base.ascent - 0.25 * e, sup->descent + 0.1 * e});
    if (sub) down = std::max({subscriptDown * e, base.descent + 0.05 * e, sub->ascent - 0.344 * e});
    if (sup && sub) {
        const double gap = (up - sup->descent) - (sub->ascent - down);
        if (gap < 4 * ruleThickness * e) down += 4 * ruleThickness * e - gap;
    }
    const double x = base.width;
    double w = x;
    if (sup) {
        append(base, *sup, x + italicCorrection, -up);
        base.ascent = std::max(base.ascent, up + sup->ascent);
        w = std::max(w, x + italicCorrection + sup->width);
    }
    if (sub) {
        append(base, *sub, x, down);
        base.descent = std::max(base.descent, down + sub->descent);
        w = std::max(w, x + sub->width);
    }
    base.width = w + 0.02 * e;
    return base;
}

MathBox symbolBoxOf(const DisplayNode& n, double size, const DisplayNode* power);

// A symbol's box: the same few hundred symbols recur thousands of times in a derivation
// (m2, ℓc2, q̇1), and building one glyph by glyph was a third of the layout of the
// Panda's pages. Kept per thread by what it draws (not by node: a freed node's address
// may be reused); with a power stacked on it, built each time.
MathBox symbolBox(const DisplayNode& n, double size, const DisplayNode* power = nullptr) {
    if (power) return symbolBoxOf(n, size, power);
    thread_local std::unordered_map<std::string, MathBox> boxes;
    std::string key;
    key.reserve(n.text.size() + n.subShown.size() + n.supText.size() + 16);
    key.append(n.text).append(1, '\x1f').append(n.subShown).append(1, '\x1f').append(n.supText).append(1, '\x1f');
    key.append(1, static_cast<char>('0' + n.dots)).append(1, n.hat ? 'h' : '-').append(1, n.upright ? 'u' : 'i').append(1, n.subUpright ? 'u' : 'i');
    key.append(std::to_string(std::lround(size * 1000))).append(1, '\x1f').append(std::to_string(n.link));
    if (auto it = boxes.find(key); it != boxes.end()) return it->second;
    return boxes.emplace(std::move(key), symbolBoxOf(n, size, nullptr)).first->second;
}

MathBox symbolBoxOf(const DisplayNode& n, double size, const DisplayNode* power) {
    QString text = QString::fromStdString(n.text);
    if (n.dots && !text.isEmpty()) text.insert(text[0].isHighSurrogate() ? 2 : 1, QChar(n.dots == 1 ? 0x0307 : 0x0308));
    if (n.hat && !text.isEmpty()) text.insert(text[0].isHighSurrogate() ? 2 : 1, QChar(0x0302));  // one accent: dots or a hat
    const bool upright = n.upright;
    MathBox base = word(text, size, upright);
    const double s = scriptSize(size);
    MathBox sub, sup;
    const bool hasSub = !n.subShown.empty(), hasSup = !n.supText.empty() || power;
    if (hasSub) sub = word(QString::fromStdString(n.subShown), s, n.subUpright);
    if (power) sup = layout(*power, s);  // ℓ_c1²: the power stacked over the subscript
    else if (hasSup) sup = word(QString::fromStdString(n.supText), s, false);
    if (n.link >= 0) {  // the symbol and its subscript in its link's colour (the power stays ink)
        for (MathPiece& p : base.pieces) p.link = n.link;
        for (MathPiece& p : sub.pieces) p.link = n.link;
    }
    if (!hasSub && !hasSup) return base;
    return scripted(base, hasSub ? &sub : nullptr, hasSup ? &sup : nullptr, size, n.upright ? 0 : 0.03 * em(size), true);
}

bool isWordNode(const DisplayNode& n) {
    if (n.kind == DisplayKind::Symbol) return n.upright;
    if (n.kind == DisplayKind::Function) return true;
    if (n.kind == DisplayKind::Power) return n.children[0]->kind == DisplayKind::Function;
    return false;
}

MathBox functionBox(const DisplayNode& n, double size, const DisplayNode* power) {
    MathBox name = word(QString::fromStdString(n.text), size, true);
    if (power) {
        const MathBox sup = layout(*power, scriptSize(size));
        name = scripted(name, nullptr, &sup, size);
    }
    MathBox args;
    for (std::size_t i = 0; i < n.children.size(); ++i) {
        if (i) hcat(args, run(",", 0, size), 0), args.width += thinSpace * em(size);
        hcat(args, layout(*n.children[i], size));
    }
    if (n.plain == "abs") return fenced(args, '|', '|', size);
    hcat(name, fenced(args, '(', ')', size));
    return name;
}

MathBox fractionBox(const DisplayNode& n, double size) {
    const double partSize = std::max(smallestSize, size * fractionScale), e = em(size);
    auto side = [&](const DisplayNode& x) {
        return layout(x.kind == DisplayKind::Fence ? *x.children[0] : x, partSize);  // no parentheses in a fraction
    };
    const MathBox num = side(*n.children[0]), den = side(*n.children[1]);
    const double theta = ruleThickness * e, a = axisHeight * e, pad = 0.1 * e;
    const double up = std::max(0.394 * e, a + theta / 2 + theta * 1.5 + num.descent);
    const double down = std::max(0.345 * e, -a + theta / 2 + theta * 1.5 + den.ascent);
    MathBox b;
    b.width = std::max(num.width, den.width) + 2 * pad;
    append(b, num, (b.width - num.width) / 2, -up);
    append(b, den, (b.width - den.width) / 2, down);
    MathPiece rule;
    rule.kind = MathPiece::Rule;
    rule.at = QPointF(0, -a - theta / 2);
    rule.width = b.width;
    rule.height = theta;
    b.pieces.push_back(rule);
    b.ascent = up + num.ascent;
    b.descent = down + den.descent;
    return b;
}

MathBox matrixBox(const DisplayNode& n, double size) {
    const double e = em(size);
    const std::size_t rows = n.rows.size(), cols = rows ? n.rows[0].size() : 0;
    std::vector<std::vector<MathBox>> cell(rows, std::vector<MathBox>(cols));
    std::vector<double> width(cols, 0), ascent(rows, 0.7 * e), descent(rows, 0.3 * e);
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < cols; ++j) {
            cell[i][j] = layout(*n.rows[i][j], size);
            width[j] = std::max(width[j], cell[i][j].width);
            ascent[i] = std::max(ascent[i], cell[i][j].ascent);
            descent[i] = std::max(descent[i], cell[i][j].descent);
        }
    const double rowGap = 0.5 * e, colGap = 1.0 * e, a = axisHeight * e;
    double height = 0;
    for (std::size_t i = 0; i < rows; ++i) height += ascent[i] + descent[i] + (i ? rowGap : 0);
    MathBox body;
    const double top = -a - height / 2;
    double y = top, x0 = 0.2 * e;
    std::vector<MathRegion> regions;  // this matrix's cells, not those of matrices inside them
    for (std::size_t i = 0; i < rows; ++i) {
        y += ascent[i];
        double x = x0;
        for (std::size_t j = 0; j < cols; ++j) {
            cell[i][j].regions.clear();
            append(body, cell[i][j], x + (width[j] - cell[i][j].width) / 2, y);  // centred columns
            regions.push_back({QRectF(x - colGap / 2, y - ascent[i] - rowGap / 2, width[j] + colGap, ascent[i] + descent[i] + rowGap),
                               static_cast<int>(i), static_cast<int>(j)});
            x += width[j] + colGap;
        }
        y += descent[i] + rowGap;
    }
    body.regions = std::move(regions);
    body.width = x0 * 2 - colGap;
    for (double w : width) body.width += w + colGap;
    body.ascent = -top;
    body.descent = top + height;
    MathBox b;
    const double margin = 0.12 * e;
    hcat(b, bracket('[', top - margin, height + 2 * margin, size));
    hcat(b, body);
    hcat(b, bracket(']', top - margin, height + 2 * margin, size));
    return b;
}

MathBox layout(const DisplayNode& n, double size) {
    const double e = em(size);
    const bool script = size < 0.95;
    switch (n.kind) {
        case DisplayKind::Symbol: return symbolBox(n, size);
        case DisplayKind::Number: {
            MathBox b = run(QString::fromStdString(n.text), 0, size);
            if (!n.exponent.empty()) {
                const bool mantissa = !n.text.empty();  // empty: 1, left out (10⁻⁴)
                if (mantissa) hcat(b, op(QString(QChar(0x22C5)), size), thinSpace * e);
                MathBox ten = run("10", 0, size);
                const MathBox x = run(QString::fromStdString(n.exponent).replace('-', QChar(0x2212)), 0, scriptSize(size));
                hcat(b, scripted(ten, nullptr, &x, size), mantissa ? thinSpace * e : 0);
            }
            return b;
        }
        case DisplayKind::Sum: {
            MathBox b;
            const double gap = script ? 0 : mediumSpace * e;
            for (std::size_t i = 0; i < n.children.size(); ++i) {
                const MathBox sign = op(n.negative[i] ? QString(QChar(0x2212)) : QString("+"), size);
                if (i == 0) {
                    if (n.negative[i]) hcat(b, sign);
                } else {
                    hcat(b, sign, gap);
                    b.width += gap;
                }
                hcat(b, layout(*n.children[i], size));
            }
            return b;
        }
        case DisplayKind::Product: {
            MathBox b;
            for (std::size_t i = 0; i < n.children.size(); ++i) {
                const DisplayNode& c = *n.children[i];
                if (i > 0) {
                    if (c.kind == DisplayKind::Number) {  // 2·3: a centred dot, as a binary operator
                        const double gap = script ? 0 : mediumSpace * e;
                        hcat(b, op(QString(QChar(0x22C5)), size), gap);
                        b.width += gap;
                    } else if (isWordNode(c) || isWordNode(*n.children[i - 1])) {
                        b.width += thinSpace * e;
                    } else {
                        b.width += 0.04 * e;  // letters of a product a hair apart
                    }
                }
                hcat(b, layout(c, size));
            }
            return b;
        }
        case DisplayKind::Fraction: return fractionBox(n, size);
        case DisplayKind::Power: {
            const DisplayNode &base = *n.children[0], &x = *n.children[1];
            if (base.kind == DisplayKind::Function) return functionBox(base, size, &x);
            if (base.kind == DisplayKind::Symbol) return symbolBox(base, size, &x);
            const MathBox sup = layout(x, scriptSize(size));
            const bool italic = base.kind == DisplayKind::Symbol && !base.upright;
            return scripted(layout(base, size), nullptr, &sup, size, italic ? 0.03 * e : 0);
        }
        case DisplayKind::Root: {
            const MathBox content = layout(*n.children[0], size);
            MathBox b;
            const double top = -content.ascent - 0.15 * e, height = content.ascent + content.descent + 0.15 * e;
            hcat(b, bracket('r', top, height, size));
            hcat(b, content, 0.05 * e);
            MathPiece bar;
            bar.kind = MathPiece::Rule;
            bar.at = QPointF(b.width - content.width - 0.05 * e, top);
            bar.width = content.width + 0.05 * e;
            bar.height = ruleThickness * e;
            b.pieces.push_back(bar);
            b.ascent = std::max(b.ascent, -top);
            return b;
        }
        case DisplayKind::Fence: return fenced(layout(*n.children[0], size), '(', ')', size);
        case DisplayKind::Function: return functionBox(n, size, nullptr);
        case DisplayKind::Matrix: return matrixBox(n, size);
        case DisplayKind::Equation: {
            MathBox b = layout(*n.children[0], size);
            const double gap = script ? 0 : thickSpace * e;
            std::string relation = n.text;
            relation.erase(std::remove(relation.begin(), relation.end(), ' '), relation.end());
            hcat(b, op(QString::fromStdString(relation), size), gap);
            b.width += gap;
            hcat(b, layout(*n.children[1], size));
            return b;
        }
        case DisplayKind::List: {
            MathBox items;
            for (std::size_t i = 0; i < n.children.size(); ++i) {
                if (i) hcat(items, run(",", 0, size)), items.width += thinSpace * e;
                hcat(items, layout(*n.children[i], size));
            }
            MathBox b = run("{", 0, size);
            hcat(b, items);
            hcat(b, run("}", 0, size));
            return b;
        }
        case DisplayKind::Raw: {
            if (n.moreTerms > 0)  // a cut sum's rest (elided): words, so in the reader's language
                return run(QCoreApplication::translate("MathTypesetter", "⋯ (%n more terms)", nullptr, static_cast<int>(n.moreTerms)), 0,
                           size);
            if (n.children.empty()) return run(QString::fromStdString(n.text), 0, size);
            MathBox b;  // a row (a label's shown form, a formula's part): its children side by side
            for (const present::DisplayPtr& c : n.children) hcat(b, layout(*c, size));
            return b;
        }
    }
    return {};
}

// A bracket's marks in device units: rectangles for [ ] and |, a filled crescent for
// ( ), a stroked tick for the radical sign.
void bracketShapes(const MathPiece& b, double scale, std::vector<MathMarks::Shape>& out) {
    using Shape = MathMarks::Shape;
    const double e = em(b.size), t = 0.045 * e;
    const QRectF r(b.at.x() * scale, b.at.y() * scale, b.width * scale, b.height * scale);
    QPainterPath path;
    const double x0 = r.left() + 0.1 * e * scale, x1 = r.right() - 0.08 * e * scale;
    const auto rect = [&](const QRectF& box) { out.push_back({Shape::Rect, box, {}, 0}); };
    switch (b.bracket) {
        case '[':
        case ']': {
            const bool open = b.bracket == '[';
            const double stem = open ? x0 : x1, arm = open ? x1 : x0;
            rect(QRectF(std::min(stem, stem + (open ? 0 : -t * scale)), r.top(), t * scale, r.height()));
            rect(QRectF(std::min(stem, arm), r.top(), std::abs(arm - stem), t * scale * 0.9));
            rect(QRectF(std::min(stem, arm), r.bottom() - t * scale * 0.9, std::abs(arm - stem), t * scale * 0.9));
            return;
        }
        case '(':
        case ')': {
            // A crescent: outer and inner curves through the ends, thickest in the middle.
            const bool open = b.bracket == '(';
            const double dir = open ? 1 : -1, mid = r.center().y();
            const double tip = open ? x1 : x0, bulge = open ? x0 - 0.12 * e * scale : x1 + 0.12 * e * scale;
            path.moveTo(tip, r.top());
            path.quadTo(bulge, mid, tip, r.bottom());
            path.quadTo(bulge + dir * 2.2 * t * scale, mid, tip, r.top());
            path.closeSubpath();
            out.push_back({Shape::Fill, {}, path, 0});
            return;
        }
        case '|': rect(QRectF(r.center().x() - t * scale / 2, r.top(), t * scale, r.height())); return;
        case 'r': {  // radical sign
            path.moveTo(r.left(), r.bottom() - r.height() * 0.35);
            path.lineTo(r.left() + r.width() * 0.3, r.bottom() - r.height() * 0.42);
            path.lineTo(r.left() + r.width() * 0.55, r.bottom());
            path.lineTo(r.right(), r.top() + t * scale / 2);
            out.push_back({Shape::Stroke, {}, path, t * scale});
            return;
        }
        default: return;
    }
}

}  // namespace

bool mathFontsAvailable() {
    loadFonts();
    return QFontDatabase::families().contains(families[2]);
}

QFont textbookFont(QFont base) {
    loadFonts();
    base.setFamily(families[0]);
    // Latin Modern's x-height is a sixth smaller than DejaVu's: as large to the eye
    if (base.pointSizeF() > 0) base.setPointSizeF(base.pointSizeF() * 1.15);
    else if (base.pixelSize() > 0) base.setPixelSize(static_cast<int>(base.pixelSize() * 1.15 + 0.5));
    return base;
}

MathBox layoutMath(const DisplayNode& node, double size) { return layout(node, size); }

std::vector<MathBox> layoutFormula(const DisplayNode& formula, double maxWidth, double size) {
    std::vector<MathBox> lines(1);
    const double gap = 2 * em(size);
    for (const present::DisplayPtr& part : formula.children) {
        const MathBox box = layout(*part, size);
        if (!lines.back().pieces.empty() && lines.back().width + gap + box.width > maxWidth) lines.emplace_back();
        hcat(lines.back(), box, lines.back().pieces.empty() ? 0 : gap);
    }
    if (formula.children.empty()) lines.back() = run(QString::fromStdString(formula.text), 0, size);
    return lines;
}

MathBox layoutText(const QString& text, double size, bool bold) {
    MathBox b = run(text, 0, size);
    if (bold)
        for (MathPiece& p : b.pieces) p.font = 3;
    return b;
}

namespace {

// Whether a relation sign (= < > ≤ ≥ ≠) comes next in text from `at`, after spaces.
bool beforeRelation(const QString& text, qsizetype at) {
    while (at < text.size() && text[at] == QChar(' ')) ++at;
    return at < text.size() && QStringView(u"=<>\u2264\u2265\u2260").contains(text[at]);
}

}  // namespace

MathBox layoutProse(const QString& text, double size) {
    // A Latin letter not inside a word, perhaps dotted (q̇, q̈), then digits (q1, c12,
    // b22; b7,10 once an index has two digits) or an underscore and digits or one
    // lowercase letter (x_0, q_i); not followed by a letter, mark, digit or _. A bare
    // letter (the x of "x of axis") stays text unless a relation follows it (m = 0 < n).
    // Lists in prose are ", "-separated, so a comma between digits belongs to the indices.
    thread_local const QRegularExpression symbol(QStringLiteral(
        "(?<![\\p{L}\\p{M}\\p{N}_])([A-Za-z])(\\x{0307}|\\x{0308})?(?:_([0-9]+|[a-z])|([0-9]+(?:,[0-9]+)*))?(?![\\p{L}\\p{M}\\p{N}_])"));
    MathBox b;
    qsizetype at = 0;
    for (QRegularExpressionMatchIterator it = symbol.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const bool dotted = m.hasCaptured(2), indexed = m.hasCaptured(3) || m.hasCaptured(4);
        if (!dotted && !indexed && !beforeRelation(text, m.capturedEnd())) continue;
        hcat(b, run(text.mid(at, m.capturedStart() - at), 0, size));
        DisplayNode n;
        n.kind = DisplayKind::Symbol;
        n.text = m.captured(1).toStdString();
        n.subShown = (m.hasCaptured(3) ? m.captured(3) : m.captured(4)).toStdString();
        n.dots = !dotted ? 0 : m.captured(2) == QChar(0x0307) ? 1 : 2;
        hcat(b, symbolBox(n, size));
        at = m.capturedEnd();
    }
    if (at == 0) return run(text, 0, size);
    hcat(b, run(text.mid(at), 0, size));
    return b;
}

namespace {

struct Chunk {
    MathBox box;
    bool breakBefore = false;
};

MathBox spaced(const MathBox& box, double before) {
    MathBox b;
    hcat(b, box, before);
    return b;
}

std::size_t leafCount(const DisplayNode& n) {
    std::size_t count = n.children.empty() && n.rows.empty() ? 1 : 0;
    for (const auto& c : n.children) count += leafCount(*c);
    return count;
}

bool isFencedSum(const DisplayNode& n) { return n.kind == DisplayKind::Fence && n.children[0]->kind == DisplayKind::Sum; }

// A node as pieces a line may break between (before the signs of its sums).
void chunks(const DisplayNode& n, std::vector<Chunk>& out, double maxWidth) {
    const double e = em(1);
    if (n.kind == DisplayKind::Equation) {
        chunks(*n.children[0], out, maxWidth);
        out.push_back({spaced(op("=", 1.0), thickSpace * e), false});
        out.back().box.width += thickSpace * e;
        chunks(*n.children[1], out, maxWidth);
        return;
    }
    if (n.kind == DisplayKind::Sum) {
        for (std::size_t i = 0; i < n.children.size(); ++i) {
            if (i > 0 || n.negative[i]) {
                MathBox sign = spaced(op(n.negative[i] ? QString(QChar(0x2212)) : QString("+"), 1.0), i ? mediumSpace * e : 0);
                if (i) sign.width += mediumSpace * e;
                out.push_back({sign, i > 0});
            }
            chunks(*n.children[i], out, maxWidth);
        }
        return;
    }
    if (n.kind == DisplayKind::Product && leafCount(n) > 12 && layout(n, 1.0).width > maxWidth / 2 &&
        std::any_of(n.children.begin(), n.children.end(), [](const present::DisplayPtr& c) { return isFencedSum(*c); })) {
        for (std::size_t i = 0; i < n.children.size(); ++i) {
            const DisplayNode& c = *n.children[i];
            const double gap = i == 0 ? 0 : isWordNode(c) || isWordNode(*n.children[i - 1]) ? thinSpace * e : 0.04 * e;
            if (isFencedSum(c)) {
                out.push_back({spaced(run("(", 0, 1.0), gap), false});
                chunks(*c.children[0], out, maxWidth);
                out.push_back({run(")", 0, 1.0), false});
            } else {
                out.push_back({spaced(layout(c, 1.0), gap), false});
            }
        }
        return;
    }
    out.push_back({layout(n, 1.0), false});
}

}  // namespace

present::DisplayPtr elided(const present::DisplayPtr& node, std::size_t maxTerms) {
    const DisplayNode& n = *node;
    std::shared_ptr<DisplayNode> copy;  // made at the first change: most nodes stay shared
    const auto changed = [&]() -> DisplayNode& {
        if (!copy) copy = std::make_shared<DisplayNode>(n);
        return *copy;
    };
    std::size_t kept = n.children.size();
    if (n.kind == DisplayKind::Sum && n.children.size() > maxTerms) {
        DisplayNode& c = changed();
        kept = maxTerms * 2 / 3;
        c.children.resize(kept);
        c.negative.resize(kept);
        c.children.push_back(present::displayMoreTerms(n.children.size() - kept));
        c.negative.push_back(false);
    }
    // Sums anywhere: inside a product's parentheses, a fraction, a matrix entry.
    for (std::size_t i = 0; i < kept; ++i)
        if (n.children[i])
            if (present::DisplayPtr e = elided(n.children[i], maxTerms); e != n.children[i]) changed().children[i] = std::move(e);
    for (std::size_t r = 0; r < n.rows.size(); ++r)
        for (std::size_t j = 0; j < n.rows[r].size(); ++j)
            if (n.rows[r][j])
                if (present::DisplayPtr e = elided(n.rows[r][j], maxTerms); e != n.rows[r][j]) changed().rows[r][j] = std::move(e);
    return copy ? copy : node;
}

std::vector<MathBox> layoutItem(const present::DisplayItem& item, double maxWidth, present::Language language) {
    const double e = em(1);
    const DisplayNode& full = *item.equation;
    if (full.kind != DisplayKind::Equation || full.children[1]->kind != DisplayKind::Matrix) return layoutEquation(full, maxWidth);
    // Nobody reads an entry of thousands of terms on a page: its first terms and a count.
    const present::DisplayPtr shortened = elided(std::shared_ptr<const DisplayNode>(&full, [](const DisplayNode*) {}), maxTypesetTerms);
    MathBox whole = layout(*shortened, 1.0);
    if (whole.width <= maxWidth) return {whole};
    // Too wide: the matrix by name, then its entries one by one.
    const DisplayNode& rhs = *shortened->children[1];
    MathBox head = layout(*shortened->children[0], 1.0);
    const std::size_t rows = rhs.rows.size(), cols = rows ? rhs.rows[0].size() : 0;
    const bool zeros = present::hasZeroEntry(rhs);  // zero entries are left out (B_m of the PUMA: 30 of 36), and said so
    const auto words = [&](ll::MessageId id) { return QString::fromStdString(present::messageText(id, language)); };
    hcat(head,
         layoutText(QString(" (%1×%2), ").arg(rows).arg(cols) + words(ll::MessageId::DocumentEntryByEntry) +
                    (zeros ? ", " + words(ll::MessageId::DocumentZerosLeftOut) + ":" : QString(":"))),
         0.3 * e);
    std::vector<MathBox> lines{head};
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < cols; ++j) {
            if (present::isZeroNumber(*rhs.rows[i][j])) continue;
            const auto entry = present::displayEquation(present::entryLabel(item, i, j), rhs.rows[i][j]);
            for (MathBox& line : layoutEquation(*entry, maxWidth - 1.5 * e)) {
                MathBox indented;
                line.regions = {{QRectF(0, -line.ascent, line.width, line.height()), static_cast<int>(i), static_cast<int>(j)}};
                hcat(indented, line, 1.5 * e);
                lines.push_back(std::move(indented));
            }
        }
    return lines;
}

std::vector<MathBox> layoutEquation(const DisplayNode& full, double maxWidth) {
    const double e = em(1);
    // Nobody reads an entry of thousands of terms on a page: its first terms and a count.
    const present::DisplayPtr shortened = elided(std::shared_ptr<const DisplayNode>(&full, [](const DisplayNode*) {}), maxTypesetTerms);
    const DisplayNode& equation = *shortened;
    MathBox whole = layout(equation, 1.0);
    if (whole.width <= maxWidth || equation.kind != DisplayKind::Equation) return {whole};
    const DisplayNode& lhs = *equation.children[0];
    std::vector<MathBox> lines;
    // Break before top-level + and − (and inside a long parenthesised sum, before its
    // own signs); continuation lines indented past "name = " (at most a third of a line).
    std::vector<Chunk> pieces;
    chunks(equation, pieces, maxWidth);
    const double indent = lhs.kind == DisplayKind::Sum  // an equation of motion: a hanging indent
                              ? 2 * e
                              : std::min(layout(lhs, 1.0).width + 2 * thickSpace * e + op("=", 1.0).width, maxWidth / 3);
    // Greedy over groups: a chunk where a break may come with the chunks up to the next.
    std::vector<MathBox> groups;
    for (const Chunk& c : pieces) {
        if (groups.empty() || c.breakBefore) groups.emplace_back();
        hcat(groups.back(), c.box);
    }
    MathBox line;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (g > 0 && line.width + groups[g].width > maxWidth && line.width > indent + e) {
            lines.push_back(line);
            line = MathBox();
            line.width = indent;
        }
        hcat(line, groups[g]);
    }
    lines.push_back(line);
    return lines;
}

// The glyphs of a piece of text in a font at a pixel size, shaped once: a page repeats
// the same few strings (c, 2, =, +, q̇) thousands of times, and drawText shaped each
// again (HarfBuzz and the font lookup were a fifth of the Panda's 73-page PDF). Glyph
// runs keep the text real in a PDF: its font subset maps glyphs back to characters.
// Positions are relative to the baseline. One cache per thread (exports run on workers).
static const QList<QGlyphRun>& shapedRuns(int which, int pixels, const QString& text) {
    struct Key {
        int which, pixels;
        QString text;
        bool operator==(const Key& o) const { return which == o.which && pixels == o.pixels && text == o.text; }
    };
    struct KeyHash {
        size_t operator()(const Key& k) const { return qHash(k.text) ^ (size_t(k.which) << 24) ^ size_t(k.pixels); }
    };
    thread_local std::unordered_map<Key, QList<QGlyphRun>, KeyHash> cache;
    Key key{which, pixels, text};
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    if (cache.size() > 50000) cache.clear();  // a bound, far above a document's distinct pieces
    QFont f = font(which == 3 ? 0 : which, 1.0);
    if (which == 3) f.setBold(true);
    f.setPixelSize(pixels);
    QTextLayout layout(text, f);
    layout.beginLayout();
    QTextLine line = layout.createLine();
    layout.endLayout();
    QList<QGlyphRun> runs = layout.glyphRuns();
    const double ascent = line.isValid() ? line.ascent() : 0.0;
    for (QGlyphRun& run : runs) {  // from the layout's top-left to the baseline
        QList<QPointF> positions = run.positions();
        for (QPointF& point : positions) point.ry() -= ascent;
        run.setPositions(positions);
    }
    return cache.emplace(std::move(key), std::move(runs)).first->second;
}

void collectMarks(const MathBox& box, QPointF origin, double scale, MathMarks& marks, bool byLink) {
    // One glyph run per font and size, however many boxes: a PDF or SVG pays per run (a
    // text object with its font, colour and matrix), and a formula set letter by letter
    // (italic m, subscript 2, roman a…) was one run per piece, 69,000 in the Panda's 71
    // pages.
    for (const MathPiece& p : box.pieces) {
        switch (p.kind) {
            case MathPiece::Text: {
                // Fonts are set in device pixels: scale the pixel size, not the painter, so
                // the PDF keeps real text at the right size.
                const int pixels = std::max(1, static_cast<int>(std::lround(mathUnitsPerEm * p.size * scale)));
                const QPointF at = p.at * scale;
                const int link = byLink ? p.link : -1;
                for (const QGlyphRun& run : shapedRuns(p.font, pixels, p.text)) {
                    const QRawFont raw = run.rawFont();
                    auto same = std::find_if(marks.glyphs.begin(), marks.glyphs.end(),
                                             [&](const MathMarks::Glyphs& g) { return g.font == raw && g.link == link; });
                    if (same == marks.glyphs.end()) same = marks.glyphs.insert(marks.glyphs.end(), MathMarks::Glyphs{raw, {}, {}, link});
                    same->indexes.append(run.glyphIndexes());
                    for (const QPointF& position : run.positions()) same->positions.append(origin + (position + at));
                }
                break;
            }
            case MathPiece::Rule:
                marks.shapes.push_back(
                    {MathMarks::Shape::Rect, QRectF(origin + p.at * scale, QSizeF(p.width * scale, p.height * scale)), {}, 0});
                break;
            case MathPiece::Bracket: {
                MathPiece shifted = p;
                shifted.at = p.at + (origin / scale);
                bracketShapes(shifted, scale, marks.shapes);
                break;
            }
        }
    }
}

void paintMarks(QPainter& painter, const MathMarks& marks) {
    painter.save();
    const QColor ink = painter.pen().color();
    for (const MathMarks::Shape& s : marks.shapes) {
        switch (s.kind) {
            case MathMarks::Shape::Rect: painter.fillRect(s.rect, ink); break;
            case MathMarks::Shape::Fill: painter.fillPath(s.path, ink); break;
            case MathMarks::Shape::Stroke: {  // as svg_page writes it: square caps, bevelled joins, no fill
                painter.save();
                painter.setPen(QPen(ink, s.penWidth, Qt::SolidLine, Qt::SquareCap, Qt::BevelJoin));
                painter.setBrush(Qt::NoBrush);
                painter.drawPath(s.path);
                painter.restore();
                break;
            }
        }
    }
    // After the rules and brackets, each font's glyphs as one run.
    for (const MathMarks::Glyphs& g : marks.glyphs) {
        if (g.link >= 0) {
            const Rgba c = linkColor(g.link);
            painter.setPen(QColor::fromRgbF(c.r * 0.85f, c.g * 0.85f, c.b * 0.85f));  // a shade darker: text on white
        } else {
            painter.setPen(ink);
        }
        QGlyphRun run;
        run.setRawFont(g.font);
        run.setGlyphIndexes(g.indexes);
        run.setPositions(g.positions);
        painter.drawGlyphRun(QPointF(0, 0), run);
    }
    painter.restore();
}

void paintMath(QPainter& painter, const MathBox& box, QPointF origin, double scale, bool linkColours) {
    MathMarks marks;
    collectMarks(box, origin, scale, marks, linkColours);
    paintMarks(painter, marks);
}

}  // namespace ll::ui
