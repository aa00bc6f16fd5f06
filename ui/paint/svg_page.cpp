#include "ui/paint/svg_page.hpp"

#include <QPainterPath>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <unordered_set>

#include "core/io/xml_text.hpp"

namespace ll::ui {
namespace {

// x with at most three decimals (a thousandth of a point), no trailing zeros, no "-0";
// 0 for what is not a finite number (nan or inf would make the file invalid).
void appendNumber(std::string& out, double x) {
    if (!std::isfinite(x) || std::abs(x) > 1e15) {
        out += '0';
        return;
    }
    double rounded = std::round(x * 1000.0) / 1000.0;
    if (rounded == 0) rounded = 0;  // -0 → 0
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, rounded, std::chars_format::fixed, 3);
    if (error != std::errc()) {
        out += '0';
        return;
    }
    const char* last = end;
    while (last > buffer && last[-1] == '0') --last;
    if (last > buffer && last[-1] == '.') --last;
    out.append(buffer, static_cast<std::size_t>(last - buffer));
}

// QPainterPath's elements, times k, as SVG path data: M, L and C (its curves are cubic; a
// quadratic one arrives as a cubic).
std::string pathData(const QPainterPath& path, double k) {
    std::string d;
    for (int i = 0; i < path.elementCount(); ++i) {
        const QPainterPath::Element e = path.elementAt(i);
        if (!d.empty()) d += ' ';
        switch (e.type) {
            case QPainterPath::MoveToElement: d += 'M'; break;
            case QPainterPath::LineToElement: d += 'L'; break;
            case QPainterPath::CurveToElement: d += 'C'; break;
            case QPainterPath::CurveToDataElement: break;
        }
        appendNumber(d, k * e.x);
        d += ' ';
        appendNumber(d, k * e.y);
    }
    return d;
}

}  // namespace

int SvgGlyphs::font(const QRawFont& raw) {
    for (std::size_t i = 0; i < fonts_.size(); ++i)
        if (fonts_[i] == raw) return static_cast<int>(i);
    fonts_.push_back(raw);
    return static_cast<int>(fonts_.size() - 1);
}

int SvgGlyphs::number(int font, quint32 glyph) {
    const std::uint64_t key = (static_cast<std::uint64_t>(font) << 32) | glyph;
    if (auto it = numbers_.find(key); it != numbers_.end()) return it->second;
    const int n = static_cast<int>(outlines_.size());
    outlines_.push_back(pathData(fonts_[static_cast<std::size_t>(font)].pathForGlyph(glyph), perDevice_));
    std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a
    for (const char c : outlines_.back()) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    char id[24];
    std::snprintf(id, sizeof id, "g%016llx", static_cast<unsigned long long>(hash));
    ids_.emplace_back(id);
    numbers_.emplace(key, n);
    return n;
}

std::string svgPage(const MathMarks& marks, QSizeF sizePt, const std::string& title, SvgGlyphs& glyphs) {
    const double k = glyphs.ptPerDevice();
    // The shapes, then the glyphs, as paintMarks draws them. The page's glyphs as numbers first: <defs> lists those this page uses, in the
    // order they first occur.
    std::vector<std::vector<int>> numbers(marks.glyphs.size());
    std::vector<int> used;
    std::vector<char> seen;
    for (std::size_t r = 0; r < marks.glyphs.size(); ++r) {
        const MathMarks::Glyphs& run = marks.glyphs[r];
        const int font = glyphs.font(run.font);
        numbers[r].reserve(static_cast<std::size_t>(run.indexes.size()));
        for (const quint32 g : run.indexes) {
            const int n = glyphs.number(font, g);
            numbers[r].push_back(n);
            if (static_cast<std::size_t>(n) >= seen.size()) seen.resize(static_cast<std::size_t>(n) + 1, 0);
            if (!seen[static_cast<std::size_t>(n)] && !glyphs.outline(n).empty()) used.push_back(n);
            seen[static_cast<std::size_t>(n)] = 1;
        }
    }

    std::size_t uses = 0;
    for (const std::vector<int>& run : numbers) uses += run.size();
    std::string out;
    out.reserve(4096 + 50 * uses + 60 * marks.shapes.size());
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"";
    appendNumber(out, sizePt.width());
    out += "pt\" height=\"";
    appendNumber(out, sizePt.height());
    out += "pt\" viewBox=\"0 0 ";
    appendNumber(out, sizePt.width());
    out += ' ';
    appendNumber(out, sizePt.height());
    out += "\">\n<title>";
    appendXmlEscaped(out, title);
    out += "</title>\n<defs>\n";
    std::unordered_set<std::string_view> defined;  // two glyphs of one outline (one id): defined once
    for (const int n : used) {
        if (!defined.insert(glyphs.id(n)).second) continue;
        out += "<path id=\"" + glyphs.id(n) + "\" d=\"";
        out += glyphs.outline(n);
        out += "\"/>\n";
    }
    out += "</defs>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n<g fill=\"#000000\" stroke=\"none\">\n";
    for (const MathMarks::Shape& s : marks.shapes) {
        switch (s.kind) {
            case MathMarks::Shape::Rect:
                out += "<rect x=\"";
                appendNumber(out, k * s.rect.x());
                out += "\" y=\"";
                appendNumber(out, k * s.rect.y());
                out += "\" width=\"";
                appendNumber(out, k * s.rect.width());
                out += "\" height=\"";
                appendNumber(out, k * s.rect.height());
                out += "\"/>\n";
                break;
            case MathMarks::Shape::Fill:
                out += s.path.fillRule() == Qt::OddEvenFill ? "<path fill-rule=\"evenodd\" d=\"" : "<path d=\"";
                out += pathData(s.path, k);
                out += "\"/>\n";
                break;
            case MathMarks::Shape::Stroke:  // QPen's defaults: square caps, bevelled joins
                out += "<path fill=\"none\" stroke=\"#000000\" stroke-linecap=\"square\" stroke-linejoin=\"bevel\" stroke-width=\"";
                appendNumber(out, k * s.penWidth);
                out += "\" d=\"";
                out += pathData(s.path, k);
                out += "\"/>\n";
                break;
        }
    }
    for (std::size_t r = 0; r < marks.glyphs.size(); ++r) {
        const MathMarks::Glyphs& run = marks.glyphs[r];
        for (qsizetype i = 0; i < run.indexes.size(); ++i) {
            const int n = numbers[r][static_cast<std::size_t>(i)];
            if (glyphs.outline(n).empty()) continue;
            out += "<use xlink:href=\"#" + glyphs.id(n) + "\" x=\"";
            appendNumber(out, k * run.positions[i].x());
            out += "\" y=\"";
            appendNumber(out, k * run.positions[i].y());
            out += "\"/>\n";
        }
    }
    out += "</g>\n</svg>\n";
    return out;
}

}  // namespace ll::ui
