// The SVG pages (ui/svg_page): written from the marks the painter draws, each glyph's
// outline defined once and placed with <use>. Checked against the painter itself: a page
// rendered from its SVG by Qt's own SVG renderer and the same page painted directly show
// the same ink in the same places, for every page of the 2R and the SCARA. And the file's
// structure: well-formed XML, each outline defined once, every <use> naming a defined
// outline, one <use> per drawn glyph and one rectangle per rule.
#include "test_registry.hpp"

#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QRegularExpression>
#include <QSet>
#include <QSvgRenderer>
#include <QXmlStreamReader>

#include "core/io/scene_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/present/display_builder.hpp"
#include "ui/paint/derivation_pages.hpp"
#include "ui/paint/math_typesetter.hpp"
#include "ui/paint/svg_page.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_svg_page {

using namespace ll;

namespace {

std::shared_ptr<const present::DisplayDocument> documentOf(const char* example) {
    const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example).scene;
    return deriveDisplay(scene, DocumentRequest{}).display;
}

ui::MathMarks marksOf(const ui::DerivationPages& pages, std::size_t page, const ui::SvgGlyphs& glyphs) {
    const double scale = 1.0 / (glyphs.ptPerDevice() * pages.format.unitsPerPt());
    ui::MathMarks marks;
    for (const ui::PlacedBox& b : pages.pages[page]) ui::collectMarks(b.box, b.origin * scale, scale, marks);
    return marks;
}

constexpr double pixelsPerPt = 2.0;

QImage blankPage(const ui::PageFormat& f) {
    QImage image(int(f.widthPt * pixelsPerPt), int(f.heightPt * pixelsPerPt), QImage::Format_RGB32);
    image.fill(Qt::white);
    return image;
}

// Painted as the PDF is, at ten device units per point (glyphs shaped at 110 pixels),
// scaled down to the image.
QImage painted(const ui::DerivationPages& pages, int page) {
    QImage image = blankPage(pages.format);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    painter.scale(pixelsPerPt / 10, pixelsPerPt / 10);
    ui::paintPage(painter, pages, page, 10);
    return image;
}

QImage rendered(const std::string& svg, const ui::PageFormat& format) {
    QSvgRenderer renderer(QByteArray::fromStdString(svg));
    if (!renderer.isValid()) return {};
    QImage image = blankPage(format);
    QPainter painter(&image);
    renderer.render(&painter);
    return image;
}

// Where the two images put their ink: each image's darkness summed over blocks of
// 2 × 2 points, as a share of its whole ink, and the sum of the blocks' differences (0:
// the same distribution; 2: nothing in common). Darkness itself differs: Qt paints text
// from gamma-corrected glyph images, an SVG's outlines as filled paths, a little bolder.
struct Comparison {
    double inkA = 0, inkB = 0, apart = 0;
};

Comparison compare(const QImage& a, const QImage& b) {
    constexpr int block = 4;  // pixels: 2 points at 2 pixels per point
    const int bw = (a.width() + block - 1) / block, bh = (a.height() + block - 1) / block;
    std::vector<double> sa(std::size_t(bw * bh)), sb(sa.size());
    Comparison c;
    for (int y = 0; y < a.height(); ++y) {
        const QRgb* ra = reinterpret_cast<const QRgb*>(a.constScanLine(y));
        const QRgb* rb = reinterpret_cast<const QRgb*>(b.constScanLine(y));
        for (int x = 0; x < a.width(); ++x) {
            const double da = (255 - qGray(ra[x])) / 255.0, db = (255 - qGray(rb[x])) / 255.0;
            const std::size_t at = std::size_t((y / block) * bw + x / block);
            sa[at] += da, sb[at] += db;
            c.inkA += da, c.inkB += db;
        }
    }
    for (std::size_t i = 0; i < sa.size(); ++i) c.apart += std::abs(sa[i] / c.inkA - sb[i] / c.inkB);
    return c;
}

}  // namespace

class TestSvgPage : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY2(ui::mathFontsAvailable(), "fonts-lmodern is not installed"); }

    // Every page, rendered from its SVG and painted directly: about the same ink, in the
    // same places. Measured on these 12 pages: 0.12 to 0.16 apart (the SVG's bolder
    // strokes); every glyph a quarter point to the right, 0.25 to 0.28; every tenth glyph
    // the next one in the font, 0.19 to 0.23.
    void pagesShowWhatThePainterPaints() {
        for (const char* example : {"planar_2r.json", "scara.json"}) {
            const ui::DerivationPages pages = ui::paginate(*documentOf(example));
            QVERIFY(pages.pages.size() >= 3);
            ui::SvgGlyphs glyphs;
            for (std::size_t i = 0; i < pages.pages.size(); ++i) {
                const std::string svg =
                    ui::svgPage(marksOf(pages, i, glyphs), QSizeF(pages.format.widthPt, pages.format.heightPt), "t", glyphs);
                const QImage fromSvg = rendered(svg, pages.format);
                QVERIFY2(!fromSvg.isNull(), "QSvgRenderer refused the page");
                const Comparison c = compare(painted(pages, int(i)), fromSvg);
                const QString where =
                    QString("%1 page %2: ink %3 and %4 px, %5 apart").arg(example).arg(i + 1).arg(c.inkA).arg(c.inkB).arg(c.apart);
                QVERIFY2(c.inkA > 500, qPrintable(where));  // not a blank page (the shortest is a last line)
                QVERIFY2(c.inkB > 0.95 * c.inkA && c.inkB < 1.4 * c.inkA, qPrintable(where));
                QVERIFY2(c.apart < 0.175, qPrintable(where));
            }
        }
    }
    // Brackets and radicals too (the 2R and the SCARA have no root): a root over a sum, the
    // fraction in parentheses drawn to its height, and a matrix in square brackets,
    // painted and from the SVG. Measured: 0.19 apart (larger glyphs than a page's, so
    // the SVG's bolder edges weigh more); without the parentheses 0.34, without the
    // radicals' strokes 0.27.
    void bracketsAndRadicalsAsPainted() {
        using namespace ll::present;
        const DisplayPtr x = displaySymbolName("x", 0), y = displaySymbolName("y", 1);
        const DisplayPtr sum = displaySumOf({x, y});
        const DisplayPtr root = displayNode(DisplayKind::Root, {sum});
        const DisplayPtr tall = displayNode(DisplayKind::Fence, {displayNode(DisplayKind::Fraction, {sum, x})});
        auto matrix = std::make_shared<DisplayNode>();
        matrix->kind = DisplayKind::Matrix;
        matrix->rows = {{x, y}, {root, tall}};
        const ui::MathBox box = ui::layoutMath(*displayNode(DisplayKind::Product, {root, tall, matrix}), 2.0);
        QString brackets;
        for (const ui::MathPiece& p : box.pieces)
            if (p.kind == ui::MathPiece::Bracket) brackets += p.bracket;
        for (const char b : {'r', '(', ')', '[', ']'}) QVERIFY2(brackets.contains(b), qPrintable(brackets));

        ui::PageFormat format;
        format.widthPt = box.width / format.unitsPerPt() + 20;
        format.heightPt = box.height() / format.unitsPerPt() + 20;
        const QPointF origin(10 * format.unitsPerPt(), 10 * format.unitsPerPt() + box.ascent);
        ui::DerivationPages pages{format, {{ui::PlacedBox{box, origin}}}};
        ui::SvgGlyphs glyphs;
        const ui::MathMarks marks = marksOf(pages, 0, glyphs);
        int strokes = 0, fills = 0;
        for (const ui::MathMarks::Shape& s : marks.shapes)
            strokes += s.kind == ui::MathMarks::Shape::Stroke, fills += s.kind == ui::MathMarks::Shape::Fill;
        QCOMPARE(strokes, 2);  // the two radicals
        QCOMPARE(fills, 4);    // two pairs of parentheses
        const QImage fromSvg = rendered(ui::svgPage(marks, QSizeF(format.widthPt, format.heightPt), "t", glyphs), format);
        QVERIFY(!fromSvg.isNull());
        const Comparison c = compare(painted(pages, 0), fromSvg);
        const QString where = QString("ink %1 and %2 px, %3 apart").arg(c.inkA).arg(c.inkB).arg(c.apart);
        QVERIFY2(c.inkA > 500, qPrintable(where));
        QVERIFY2(c.inkB > 0.95 * c.inkA && c.inkB < 1.4 * c.inkA, qPrintable(where));
        QVERIFY2(c.apart < 0.24, qPrintable(where));
    }

    // The file itself: well-formed; each outline once in <defs>, each used; one <use>
    // per glyph drawn (a space draws nothing) and one rectangle per rule and bracket bar,
    // beside the white background.
    void eachOutlineDefinedOnce() {
        const ui::DerivationPages pages = ui::paginate(*documentOf("planar_2r.json"));
        ui::SvgGlyphs glyphs;
        for (std::size_t i = 0; i < pages.pages.size(); ++i) {
            const ui::MathMarks marks = marksOf(pages, i, glyphs);
            const std::string svg = ui::svgPage(marks, QSizeF(pages.format.widthPt, pages.format.heightPt), "B & C <2R>", glyphs);
            const QString text = QString::fromStdString(svg);

            QXmlStreamReader xml(text);
            int uses = 0, rects = 0;
            QSet<QString> defined, referenced;
            QString title;
            while (!xml.atEnd()) {
                xml.readNext();
                if (!xml.isStartElement()) continue;
                if (xml.name() == u"path" && xml.attributes().hasAttribute("id")) {
                    const QString id = xml.attributes().value("id").toString();
                    QVERIFY2(!defined.contains(id), qPrintable("defined twice: " + id));
                    defined.insert(id);
                } else if (xml.name() == u"use") {
                    ++uses;
                    referenced.insert(xml.attributes().value("http://www.w3.org/1999/xlink", "href").toString().mid(1));
                } else if (xml.name() == u"rect") {
                    ++rects;
                } else if (xml.name() == u"title") {
                    title = xml.readElementText();
                }
            }
            QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
            QCOMPARE(title, QString("B & C <2R>"));
            QCOMPARE(referenced, defined);

            int drawn = 0;
            for (const ui::MathMarks::Glyphs& run : marks.glyphs)
                for (const quint32 g : run.indexes) drawn += !run.font.pathForGlyph(g).isEmpty();
            QVERIFY(drawn > 100);
            QCOMPARE(uses, drawn);
            QVERIFY(defined.size() < drawn / 2);  // glyphs recur: that is what <use> saves
            int rules = 0;
            for (const ui::MathMarks::Shape& s : marks.shapes) rules += s.kind == ui::MathMarks::Shape::Rect;
            QCOMPARE(rects, rules + 1);
        }
    }

    // Two exports (the 2R and the SCARA, each with its own glyph numbering) inlined in
    // one HTML page share one id namespace: an id names one outline in both, and a glyph
    // both draw has one id.
    void idsNameOneOutlineAcrossExports() {
        QHash<QString, QString> outlineOf;
        QSet<QString> seen[2];
        const char* scenes[] = {"planar_2r.json", "scara.json"};
        for (int e = 0; e < 2; ++e) {
            const ui::DerivationPages pages = ui::paginate(*documentOf(scenes[e]));
            ui::SvgGlyphs glyphs;
            for (std::size_t i = 0; i < pages.pages.size(); ++i) {
                const std::string svg =
                    ui::svgPage(marksOf(pages, i, glyphs), QSizeF(pages.format.widthPt, pages.format.heightPt), scenes[e], glyphs);
                QXmlStreamReader xml(QString::fromStdString(svg));
                while (!xml.atEnd()) {
                    xml.readNext();
                    if (!xml.isStartElement() || xml.name() != u"path" || !xml.attributes().hasAttribute("id")) continue;
                    const QString id = xml.attributes().value("id").toString(), d = xml.attributes().value("d").toString();
                    QVERIFY2(outlineOf.value(id, d) == d, qPrintable("two outlines named " + id));
                    outlineOf.insert(id, d);
                    seen[e].insert(id);
                }
            }
        }
        QVERIFY(seen[0].size() > 30 && seen[1].size() > 30);
        QVERIFY(QSet<QString>(seen[0]).intersect(seen[1]).size() > 20);
    }
};

static int runSvgPage(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("DISPLAY")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    TestSvgPage test;
    return QTest::qExec(&test, argc, argv);
}
LL_TEST_PROGRAM(runSvgPage)

}  // namespace test_svg_page
#include "test_svg_page.moc"
