// math_typesetter and derive --format pdf|svg|png: layout metrics by TeX's rules (a
// fraction is taller than its numerator and its parts smaller, a subscript sits lower
// and smaller, a matrix's brackets span its rows, long sums break, wide matrices become
// entries), and the exports: the 2R's PDF holds b11's symbols as text (pdftotext) and
// renders non-blank (pdftoppm), SVG and PNG are non-blank, bad input exits 2 in one line;
// long sums are cut at any depth; a PDF laid out on a second thread has every page, in
// order, with one text object per font of a formula.
#include "test_registry.hpp"

#include <QApplication>
#include <QImage>
#include <QPainter>
#include <QProcess>
#include <QSvgRenderer>
#include <QTemporaryDir>

#include "core/io/scene_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "ui/paint/derivation_pages.hpp"
#include "ui/paint/math_typesetter.hpp"
#include "pdf_streams.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_math_typesetter {

using namespace ll;
using namespace ll::symbolic;
using namespace ll::present;
using ll::ui::MathBox;
using ll::ui::MathPiece;

namespace {

std::shared_ptr<DisplayNode> symbolNode(const std::string& base, const std::string& sub = {}) {
    auto n = std::make_shared<DisplayNode>();
    n->kind = DisplayKind::Symbol;
    n->text = n->latex = n->plain = n->name = base;
    n->subShown = n->subText = n->subLatex = sub;
    return n;
}

const MathPiece* pieceWithText(const MathBox& box, const QString& text, int nth = 0) {
    for (const MathPiece& p : box.pieces)
        if (p.kind == MathPiece::Text && p.text == text && nth-- == 0) return &p;
    return nullptr;
}

// Share of pixels darker than mid-grey.
double inked(const QImage& image) {
    qint64 dark = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) dark += qGray(image.pixel(x, y)) < 128;
    return double(dark) / (double(image.width()) * image.height());
}

struct Run {
    int code;
    QString out, err;
};

Run run(const QStringList& args, const QString& program = LL_CLI) {
    QProcess p;
    p.start(program, args);
    p.waitForFinished(300000);
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()), QString::fromUtf8(p.readAllStandardError())};
}

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

// m_i·a_1 + m_{i+1}·a_1 + … : `count` terms.
std::shared_ptr<DisplayNode> sumOf(int count, int first = 0) {
    auto sum = std::make_shared<DisplayNode>();
    sum->kind = DisplayKind::Sum;
    for (int i = first; i < first + count; ++i) {
        sum->children.push_back(displayNode(DisplayKind::Product, {symbolNode("m", std::to_string(i)), symbolNode("a", "1")}));
        sum->negative.push_back(i % 3 == 0);
    }
    return sum;
}

// The "⋯ (N more terms)" node of a cut sum, or null.
const DisplayNode* moreTerms(const DisplayNode& sum) {
    if (sum.kind != DisplayKind::Sum || sum.children.empty()) return nullptr;
    const DisplayNode& last = *sum.children.back();
    return last.kind == DisplayKind::Raw && last.text.find("more terms") != std::string::npos ? &last : nullptr;
}

// The text objects (BT … ET) in a PDF's content streams.
int pdfTextObjects(const QByteArray& pdf) {
    int objects = 0;
    for (const QByteArray& stream : test::inflatedStreams(pdf)) objects += int(stream.count("BT\n"));
    return objects;
}

}  // namespace

class TestMathTypesetter : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY2(ui::mathFontsAvailable(), "fonts-lmodern is not installed"); }

    void fractionIsTallerThanItsNumeratorAndCentredOnTheAxis() {
        const auto a = symbolNode("a"), b = symbolNode("b");
        const auto fraction = displayNode(DisplayKind::Fraction, {a, b});
        const MathBox f = ui::layoutMath(*fraction), alone = ui::layoutMath(*a);
        QVERIFY(f.height() > alone.height());
        QVERIFY(f.ascent > alone.ascent && f.descent > alone.descent);
        const MathPiece* numerator = pieceWithText(f, "a");
        QVERIFY(numerator);
        QVERIFY(numerator->size < 1.0);  // smaller than the text around it
        QVERIFY(numerator->at.y() < 0);  // above the baseline
        const MathPiece* rule = nullptr;
        for (const MathPiece& p : f.pieces)
            if (p.kind == MathPiece::Rule) rule = &p;
        QVERIFY(rule);
        const double axis = -(rule->at.y() + rule->height / 2);  // the rule's middle on the math axis
        QVERIFY(std::abs(axis - 0.25 * ui::mathUnitsPerEm) < 0.5);
    }

    void subscriptSitsLowerAndSmaller() {
        const MathBox x = ui::layoutMath(*symbolNode("m", "2"));
        const MathPiece* base = pieceWithText(x, "m");
        const MathPiece* sub = pieceWithText(x, "2");
        QVERIFY(base && sub);
        QVERIFY(sub->at.y() > base->at.y());  // lower (y grows downwards)
        QVERIFY(sub->size < base->size);
        QVERIFY(sub->at.x() > base->at.x());
        QCOMPARE(base->font, 1);  // italic variable
        QCOMPARE(sub->font, 0);   // upright digit
        // A superscript sits higher than the baseline and smaller.
        const auto power = displayNode(DisplayKind::Power, {symbolNode("a"), displayNumber("2", "2", "2")});
        const MathBox p = ui::layoutMath(*power);
        const MathPiece* two = pieceWithText(p, "2");
        QVERIFY(two && two->at.y() < 0 && two->size < 1.0);
    }

    void matrixBracketsSpanTheRows() {
        auto m = std::make_shared<DisplayNode>();
        m->kind = DisplayKind::Matrix;
        for (const char* r : {"x", "y", "z"}) m->rows.push_back({symbolNode(r)});
        const MathBox box = ui::layoutMath(*m);
        const MathPiece *x = pieceWithText(box, "x"), *z = pieceWithText(box, "z");
        QVERIFY(x && z && z->at.y() > x->at.y());
        int brackets = 0;
        for (const MathPiece& p : box.pieces) {
            if (p.kind != MathPiece::Bracket) continue;
            ++brackets;
            QVERIFY(p.at.y() < x->at.y() - 0.5 * ui::mathUnitsPerEm);  // above the first row's letters
            QVERIFY(p.at.y() + p.height > z->at.y());                  // below the last row's baseline
        }
        QCOMPARE(brackets, 2);
        QVERIFY(box.height() > 3 * ui::layoutMath(*symbolNode("x")).height());
    }

    void longSumsBreakAndWideMatricesBecomeEntries() {
        std::vector<DisplayPtr> terms;
        auto sum = std::make_shared<DisplayNode>();
        sum->kind = DisplayKind::Sum;
        for (int i = 0; i < 60; ++i) {
            sum->children.push_back(displayNode(DisplayKind::Product, {symbolNode("m", std::to_string(i)), symbolNode("a", "1")}));
            sum->negative.push_back(i % 3 == 0);
        }
        const auto equation = displayEquation(symbolNode("b", "11"), sum);
        const double width = 30 * ui::mathUnitsPerEm;
        const auto lines = ui::layoutEquation(*equation, width);
        QVERIFY(lines.size() > 2);
        for (const MathBox& l : lines) QVERIFY(l.width <= width + 1);
        auto m = std::make_shared<DisplayNode>();
        m->kind = DisplayKind::Matrix;
        m->rows = {{sum, sum}, {sum, sum}};
        DisplayItem B;
        B.name = "B";
        B.quantity = Quantity::MassMatrix;
        B.value = m;
        B.equation = displayEquation(symbolNode("B"), m);
        const auto entries = ui::layoutItem(B, width);
        QVERIFY(entries.size() > 4 * 2);          // a heading and four entries, each broken
        QVERIFY(pieceWithText(entries[1], "b"));  // b11, named by the quantity: B's entries are b_jk
    }

    // Nobody reads thousands of terms on a page: a long sum is cut wherever it sits (the
    // expanded Panda's entries are products with a sum of thousands of terms in
    // parentheses: 415 pages, 23 s). Text and JSON keep every term; short parts stay shared.
    void sumsAreElidedAtAnyDepth() {
        const auto longSum = sumOf(300), shortSum = sumOf(5, 400);
        const auto product = displayNode(DisplayKind::Product, {symbolNode("m", "2"), displayNode(DisplayKind::Fence, {longSum})});
        const auto fraction = displayNode(DisplayKind::Fraction, {product, shortSum});
        const auto equation = displayEquation(symbolNode("b", "11"), fraction);
        const DisplayPtr cut = ui::elided(equation, ui::maxTypesetTerms);
        const DisplayNode& inner = *cut->children[1]->children[0]->children[1]->children[0];  // = (frac) (num) (fence) sum
        QCOMPARE(inner.kind, DisplayKind::Sum);
        QCOMPARE(inner.children.size(), ui::maxTypesetTerms * 2 / 3 + 1);
        QCOMPARE(inner.negative.size(), inner.children.size());
        const DisplayNode* more = moreTerms(inner);
        QVERIFY(more);
        QCOMPARE(QString::fromStdString(more->text), QString("⋯ (%1 more terms)").arg(300 - int(ui::maxTypesetTerms * 2 / 3)));
        QCOMPARE(present::moreTermsCount(*more), std::size_t(300 - ui::maxTypesetTerms * 2 / 3));  // the count its text shows
        QCOMPARE(present::moreTermsCount(*longSum->children.back()), std::size_t(0));
        QCOMPARE(cut->children[1]->children[1], DisplayPtr(shortSum));     // untouched: shared, not copied
        QVERIFY(longSum->children.size() == 300 && !moreTerms(*longSum));  // the original keeps every term
        const DisplayPtr same = ui::elided(displayEquation(symbolNode("b", "12"), shortSum), ui::maxTypesetTerms);
        QVERIFY(!moreTerms(*same->children[1]));
        // Typeset, the cut entry takes a few lines, not the dozens its 300 terms would.
        const double width = 40 * ui::mathUnitsPerEm;
        const auto full = ui::layoutEquation(*displayEquation(symbolNode("b", "11"), product), width);
        QVERIFY2(full.size() <= 8, qPrintable(QString::number(full.size())));
    }

    // `derive --format pdf|svg|png` builds its trees already cut (forPages): each sum of
    // more than maxTypesetTerms terms is ordered whole but only its shown terms are built.
    // Every item renders on the pages exactly as the full tree does, in Text, LaTeX and
    // Plain: the expanded PUMA 560 with symbolic parameters (C and the equations: sums of
    // hundreds of terms, cut) and numeric ones (none that long), and a hand-typed
    // Lagrangian whose g has 100 terms beside I1 θ̈1 in its equation (each part of an
    // equation is cut alone, then the joined sum is cut again with the true count).
    void pagesTreesAreBuiltAsThePagesCutThem() {
        std::string potential;
        for (int k = 1; k <= 100; ++k) potential += (k > 1 ? " + " : "") + std::string("theta1^") + std::to_string(k);
        const Scene longG = parseScene(R"({"format": "lagrangelab-scene/1", "name": "long g", "parameters": {"I1": 0.5},
            "lagrangian": {"coordinates": ["theta1"], "kinetic": "I1*theta1_dot^2/2", "potential": ")" +
                                       potential + R"(", "forces": [0], "bodies": []},
            "initial": {"q": [0.1], "qd": [0]}})");
        const Scene puma = loadScene(std::string(LL_EXAMPLES_DIR) + "/puma560.json").scene;
        const struct {
            const char* name;
            const Scene& scene;
            ParameterMode mode;
            bool cuts;
        } cases[] = {{"PUMA 560 symbolic", puma, ParameterMode::Textbook, true},
                     {"PUMA 560 numeric", puma, ParameterMode::Numeric, false},
                     {"long g", longG, ParameterMode::Parametric, true}};
        for (const auto& c : cases) {
            DocumentRequest request;
            request.mode = c.mode;
            const auto full = deriveDisplay(c.scene, request, DerivationForm::Expanded).display;
            request.forPages = true;
            const auto cut = deriveDisplay(c.scene, request, DerivationForm::Expanded).display;
            QCOMPARE(cut->steps.size(), full->steps.size());
            int cutItems = 0;
            for (std::size_t i = 0; i < full->steps.size(); ++i) {
                QCOMPARE(cut->steps[i].items.size(), full->steps[i].items.size());
                for (std::size_t j = 0; j < full->steps[i].items.size(); ++j) {
                    const DisplayItem &a = full->steps[i].items[j], &b = cut->steps[i].items[j];
                    const DisplayPtr fullOnPage = ui::elided(a.equation, ui::maxTypesetTerms);
                    const DisplayPtr cutOnPage = ui::elided(b.equation, ui::maxTypesetTerms);
                    cutItems += fullOnPage != a.equation;
                    for (const DisplayStyle style : {DisplayStyle::Text, DisplayStyle::Latex, DisplayStyle::Plain})
                        QVERIFY2(renderDisplay(*fullOnPage, style) == renderDisplay(*cutOnPage, style),
                                 qPrintable(QString("%1: %2").arg(c.name, QString::fromStdString(a.name))));
                }
            }
            QVERIFY2(c.cuts ? cutItems >= 1 : cutItems == 0, qPrintable(QString("%1: %2 items cut").arg(c.name).arg(cutItems)));
        }
    }

    // Many items on many pages: every page arrives, in order, and each formula's glyphs are one text object
    // per font (they were one per letter or subscript: 69,000 in the Panda's PDF).
    void pdfPagesOfManyItems() {
        DisplayDocument document;
        document.systemName = "pipeline";
        DisplayStep step;
        step.number = 4;
        step.title = literal("Sums");
        step.formulaText = "b = sum";
        const int items = 300;
        for (int i = 0; i < items; ++i) {
            DisplayItem item;
            item.name = "b" + std::to_string(i);
            item.equation = displayEquation(symbolNode("b", std::to_string(i)), sumOf(12, i));
            item.value = item.equation->children[1];
            item.note = literal("item " + std::to_string(i + 1) + " of " + std::to_string(items));
            step.items.push_back(item);
        }
        document.steps.push_back(step);
        document.actuation = "all actuated";
        const ui::DerivationPages pages = ui::paginate(document);
        QVERIFY(pages.pages.size() > 5);
        std::size_t boxes = 0;
        for (const auto& page : pages.pages) boxes += page.size();

        QTemporaryDir dir;
        const QString pdf = dir.filePath("pipeline.pdf");
        std::string error;
        int written = 0;
        QVERIFY2(ui::writePdf(document, pdf, error, {}, &written), error.c_str());
        QCOMPARE(written, int(pages.pages.size()));
        const Run info = run({pdf}, "pdfinfo");
        const QRegularExpressionMatch count = QRegularExpression(R"(Pages:\s+(\d+))").match(info.out);
        QVERIFY(count.hasMatch());
        QCOMPARE(count.captured(1).toInt(), int(pages.pages.size()));
        const Run text = run({"-layout", pdf, "-"}, "pdftotext");
        QCOMPARE(text.code, 0);
        qsizetype last = -1;
        for (int i : {1, 2, items / 2, items - 1, items}) {  // present and in order
            const qsizetype at = text.out.indexOf(QString("item %1 of %2").arg(i).arg(items));
            QVERIFY2(at > last, qPrintable(QString("item %1").arg(i)));
            last = at;
        }
        QFile file(pdf);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const int objects = pdfTextObjects(file.readAll());
        // Per box at most roman, italic, math and bold, each at text and script size (here
        // about 4); one per letter or subscript it was over 40 for each of these entries.
        QVERIFY2(objects >= int(pages.pages.size()) && objects <= 8 * int(boxes),
                 qPrintable(QString("%1 text objects for %2 boxes").arg(objects).arg(boxes)));

        // A failing write names its reason and leaves no file.
        const QString blocked = dir.filePath("no/such/folder/x.pdf");
        QVERIFY(!ui::writePdf(document, blocked, error));
        QVERIFY(!error.empty());
        QVERIFY(!QFileInfo::exists(blocked));
    }

    // Numbers as the scene typed them (issue 39): a₁ = 1.375 reads 1.375, not 11/8, in
    // text, LaTeX and the typeset PDF (DH table, A₁, T₂⁰); the acrobot's typed gravity
    // 9.8 reads 9.8, not 49/5; a typed Lagrangian's sin²θ stays sin²θ where 1 − cos²θ is
    // longer (the spherical pendulum's b₂₂).
    void numbersAsTyped() {
        QTemporaryDir dir;
        const QString arm = dir.filePath("decimal_2r.json");
        QFile f(arm);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "lagrangelab-scene/1", "name": "decimal 2R", "robot": {"convention": "standard", "joints": [
            {"type": "revolute", "a": 1.375, "alpha": 0, "d": 0, "theta": 0, "mass": 2.5, "com": [-0.6875, 0, 0], "inertia": {"xx": 0, "yy": 0.3, "zz": 0.3}},
            {"type": "revolute", "a": 1.5, "alpha": 0, "d": 0, "theta": 0, "mass": 1.25, "com": [-0.75, 0, 0], "inertia": {"xx": 0, "yy": 0.2, "zz": 0.2}}]},
            "effects": {"gravity": [0, -9.8, 0]}})");
        f.close();
        const Run text = run({"derive", arm, "--numeric"});
        QVERIFY2(text.code == 0, qPrintable(text.err));
        QVERIFY2(text.out.contains("1.375 c1 + 1.5 c12"), qPrintable(text.out));
        const Run latex = run({"derive", arm, "--numeric", "--format", "latex"});
        QVERIFY(latex.out.contains("1.375") && latex.out.contains("1.5"));
        const QString pdf = dir.filePath("decimal.pdf");
        QCOMPARE(run({"derive", arm, "--numeric", "--format", "pdf", "--out", pdf}).code, 0);
        const Run pages = run({pdf, "-"}, "pdftotext");
        QVERIFY(pages.out.contains("1.375"));
        for (const QString& out : {text.out, latex.out, pages.out}) {
            QVERIFY2(!out.contains("11/8") && !out.contains("{11}{8}") && !out.contains("3/2") && !out.contains("{3}{2}"),
                     "a typed decimal shown as a fraction");
        }

        const Run acrobot = run({"derive", example("acrobot.json")});
        QVERIFY(acrobot.out.contains("9.8 m2 ℓc2 c12") && !acrobot.out.contains("49/5"));
        // JSON's expr is for machines: the exact 49/5 there (it read 9.8000000000000007).
        const Run json = run({"derive", example("acrobot.json"), "--format", "json"});
        QVERIFY2(json.out.contains("(49/5)*m2*lc2*cos(q1+q2)") && !json.out.contains("9.8000000000000007"),
                 qPrintable(json.out.right(2000)));

        const QString pendulum = dir.filePath("spherical.json");
        QFile p(pendulum);
        QVERIFY(p.open(QIODevice::WriteOnly));
        p.write(R"json({"format": "lagrangelab-scene/1", "name": "spherical pendulum", "parameters": {"m": 1.5, "l": 0.8, "g": 9.81},
            "lagrangian": {"coordinates": ["theta", "phi"], "kinetic": "m*l^2*(theta_dot^2 + sin(theta)^2*phi_dot^2)/2",
            "potential": "-m*g*l*cos(theta)"}, "initial": {"q": [0.5, 0], "qd": [0, 1]}})json");
        p.close();
        const Run spherical = run({"derive", pendulum});
        QVERIFY2(spherical.code == 0, qPrintable(spherical.err));
        QVERIFY2(spherical.out.contains("m l² sin²(θ) φ̈") && !spherical.out.contains("cos²"), qPrintable(spherical.out));
    }

    // A typed Lagrangian's labels as the notes write them (issue 40): ∂L/∂θ̇1, d/dt ∂L/∂θ̇1,
    // ∂L/∂θ1 and the inputs on θ2, in text, LaTeX and the typeset PDF; no dL/d, theta or
    // _dot left of the names the user typed.
    void lagrangianLabelsAsTheNotesWriteThem() {
        const QString scene = example("mass_spring_pair_lagrangian.json");
        const Run text = run({"derive", scene});
        QVERIFY2(text.code == 0, qPrintable(text.err));
        for (const char* s : {"∂L/∂θ̇1 = I1 θ̇1", "d/dt ∂L/∂θ̇1 = I1 θ̈1", "∂L/∂θ1 = ", "Actuation: inputs on θ2",
                              // typed K2*(theta1-theta2)^2/2: shown as typed, not expanded
                              "E_pot = 1/2 K1 θ1² + 1/2 K2 (θ1 − θ2)²",
                              // L = E_kin − E_pot as the notes write it: the kinetic terms first (issue 51)
                              "L = 1/2 I1 θ̇1² + 1/2 I2 θ̇2² − 1/2 K1 θ1² − 1/2 K2 (θ1 − θ2)²"})
            QVERIFY2(text.out.contains(QString::fromUtf8(s)), s);
        const Run latex = run({"derive", scene, "--format", "latex"});
        QVERIFY(latex.out.contains(R"(\frac{\partial \mathcal{L}}{\partial \dot{\theta}_{1}})"));
        QVERIFY2(latex.out.contains(R"(\frac{1}{2} K_{2} {\left(\theta_{1} - \theta_{2}\right)}^{2})"), qPrintable(latex.out));
        QVERIFY(latex.out.contains(R"(inputs on $\theta_{2}$)"));
        QTemporaryDir dir;
        const QString pdf = dir.filePath("msp.pdf");
        QCOMPARE(run({"derive", scene, "--format", "pdf", "--out", pdf}).code, 0);
        const Run pages = run({pdf, "-"}, "pdftotext");
        for (const QString& out : {text.out, latex.out.section("\\begin{document}", 1), pages.out}) {
            QVERIFY2(!out.contains("dL/d") && !out.contains("_dot") && !QRegularExpression("(?<!\\\\)theta").match(out).hasMatch(),
                     qPrintable(out.left(3000)));
        }
    }

    void pdfOfThe2R() {
        QTemporaryDir dir;
        const QString pdf = dir.filePath("2r.pdf");
        const Run r = run({"derive", example("planar_2r.json"), "--format", "pdf", "--out", pdf});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const Run text = run({"-layout", pdf, "-"}, "pdftotext");
        QCOMPARE(text.code, 0);
        // b11 = I1 + m1 ℓc1² + I2 + m2 (a1² + ℓc2² + 2 a1 ℓc2 c2): its symbols are text.
        for (const char* s : {"B(q)", "ℓ", "I", "m", "Step 7", "Kinetic energy"}) QVERIFY2(text.out.contains(QString::fromUtf8(s)), s);
        const Run png = run({"-png", "-r", "40", "-f", "4", "-l", "4", pdf, dir.filePath("page")}, "pdftoppm");
        QCOMPARE(png.code, 0);
        const QStringList pages = QDir(dir.path()).entryList({"page*.png"});
        QCOMPARE(pages.size(), 1);
        const double ink = inked(QImage(dir.filePath(pages[0])));
        QVERIFY2(ink > 0.002 && ink < 0.5, qPrintable(QString::number(ink)));
    }

    // A PNG page is shaped as the PDF is (ten device units per point, then scaled): each
    // line of the 2R's step 8 ends where it ends in the PDF rendered by pdftoppm at the
    // same 150 dpi, within 3 px. (Shaped at the image's own pixel size, the title came
    // out 12 px short and a line of prose 27 px.)
    void pngLinesEndWhereThePdfs() {
        QTemporaryDir dir;
        const QString pdf = dir.filePath("s8.pdf"), png = dir.filePath("s8.png");
        for (const auto& [format, out] : {std::pair{"pdf", pdf}, {"png", png}})
            QCOMPARE(run({"derive", example("planar_2r.json"), "--format", format, "--out", out, "--steps", "8"}).code, 0);
        QCOMPARE(run({"-png", "-r", "150", "-f", "1", "-l", "1", pdf, dir.filePath("ref")}, "pdftoppm").code, 0);
        const QImage ref(dir.filePath(QDir(dir.path()).entryList({"ref*.png"}).value(0))), ours(png);
        QVERIFY(!ref.isNull() && !ours.isNull());
        QVERIFY(std::abs(ref.width() - ours.width()) <= 1 && std::abs(ref.height() - ours.height()) <= 1);
        const int w = std::min(ref.width(), ours.width()), h = std::min(ref.height(), ours.height());
        auto dark = [](const QImage& image, int x, int y) { return qGray(image.pixel(x, y)) < 128; };
        // Lines: runs of rows with ink in the reference, separated by blank rows.
        int lines = 0;
        for (int y = 0; y < h;) {
            auto inked = [&](int row) {
                for (int x = 0; x < w; ++x)
                    if (dark(ref, x, row)) return true;
                return false;
            };
            if (!inked(y)) {
                ++y;
                continue;
            }
            const int top = y;
            while (y < h && inked(y)) ++y;
            auto rightEnd = [&](const QImage& image) {
                int right = -1;
                for (int row = top; row < y; ++row)
                    for (int x = w - 1; x > right; --x)
                        if (dark(image, x, row)) right = x;
                return right;
            };
            const int refRight = rightEnd(ref), ourRight = rightEnd(ours);
            if (y - top < 8) continue;  // a rule or a stray dot, not a line of text
            ++lines;
            QVERIFY2(std::abs(refRight - ourRight) <= 3,
                     qPrintable(
                         QString("line at y %1..%2 ends at x %3 in the PDF, %4 in the PNG").arg(top).arg(y).arg(refRight).arg(ourRight)));
        }
        QVERIFY2(lines >= 8, qPrintable(QString::number(lines)));
    }

    // The dot of q̇ sits over the q: its ink centred over the letter's bowl (within 0.12
    // em; italic skew allows a little to the right), a small gap above the x-height,
    // not above the ascenders (it was left of the q and 0.6 em too high).
    void dotSitsOverTheLetter() {
        auto q = symbolNode("q");
        q->dots = 1;
        const MathBox box = ui::layoutMath(*q);
        const double scale = 4;  // px per unit: an em is 160 px
        const double em = ui::mathUnitsPerEm * scale;
        QImage image(int(box.width * scale) + 80, int(box.height() * scale) + 80, QImage::Format_RGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        painter.setPen(Qt::black);
        const double baseline = 40 + box.ascent * scale;
        ui::paintMath(painter, box, QPointF(40, baseline), scale);
        painter.end();
        // Rows with ink from the top: the dot, a blank gap, then the letter.
        const auto rowInk = [&](int y, int& left, int& right) {
            left = image.width(), right = -1;
            for (int x = 0; x < image.width(); ++x)
                if (qGray(image.pixel(x, y)) < 128) left = std::min(left, x), right = std::max(right, x);
            return right >= 0;
        };
        int y = 0, l = 0, r = 0;
        while (y < image.height() && !rowInk(y, l, r)) ++y;
        double dotLeft = 1e9, dotRight = -1;
        const int dotTop = y;
        for (; y < image.height() && rowInk(y, l, r); ++y) dotLeft = std::min<double>(dotLeft, l), dotRight = std::max<double>(dotRight, r);
        const int dotBottom = y;
        while (y < image.height() && !rowInk(y, l, r)) ++y;
        const int letterTop = y;
        double bowlLeft = 1e9, bowlRight = -1;  // the letter above the baseline (not q's tail)
        for (; y < baseline; ++y)
            if (rowInk(y, l, r)) bowlLeft = std::min<double>(bowlLeft, l), bowlRight = std::max<double>(bowlRight, r);
        QVERIFY2(dotTop < dotBottom && dotBottom < letterTop && bowlRight > bowlLeft, "no dot above the letter");
        const double dx = (dotLeft + dotRight) / 2 - (bowlLeft + bowlRight) / 2;
        const double gap = letterTop - dotBottom;
        QVERIFY2(dx > -0.05 * em && dx < 0.12 * em, qPrintable(QString("dot off centre by %1 em").arg(dx / em)));
        QVERIFY2(gap > 0.02 * em && gap < 0.2 * em, qPrintable(QString("gap %1 em").arg(gap / em)));
        QVERIFY2(baseline - dotTop < 0.8 * em, qPrintable(QString("dot top %1 em above the baseline").arg((baseline - dotTop) / em)));
    }

    // Prose names symbols as the LaTeX rendering sets them ($q_1$, $x_0$, $\dot q$): a
    // single letter with an index or dots is the typeset symbol, every other word text.
    void proseSetsTheSymbolsItNames() {
        const MathBox note = ui::layoutProse(QString::fromUtf8("x of axis x_0 in the frame of link 3; depends on q1, q12"));
        const MathBox alone = ui::layoutMath(*symbolNode("q", "12"), 1.0);
        // q12 drawn as the symbol q with subscript 12 (its pieces q, 1, 2), at the end of
        // the line: the same pieces at the same places as the symbol alone, shifted.
        QVERIFY(note.pieces.size() >= alone.pieces.size());
        const std::size_t first = note.pieces.size() - alone.pieces.size();
        const MathPiece& q = note.pieces[first];
        QCOMPARE(q.text, QString("q"));
        QCOMPARE(q.font, 1);  // italic
        for (std::size_t i = 0; i < alone.pieces.size(); ++i) {
            const MathPiece &a = alone.pieces[i], &n = note.pieces[first + i];
            QCOMPARE(n.text, a.text);
            QCOMPARE(n.size, a.size);
            QVERIFY(((n.at - q.at) - (a.at - alone.pieces[0].at)).manhattanLength() < 1e-9);
        }
        const MathPiece& one = note.pieces[first + 1];
        QVERIFY(one.size < q.size && one.at.y() > q.at.y() && one.at.x() > q.at.x());  // a subscript
        QVERIFY(pieceWithText(note, "0") && pieceWithText(note, "x", 0));
        // The words around them stay text, each run in the roman font at full size.
        const MathPiece* words = pieceWithText(note, " in the frame of link 3; depends on ");
        QVERIFY(words && words->font == 0 && words->size == 1.0);
        QVERIFY(pieceWithText(note, "x of axis "));  // a bare letter is a word
        // Dots: q̇ as the letter with the accent, as layoutMath sets a velocity.
        auto velocity = symbolNode("q");
        velocity->dots = 1;
        const MathBox dotted = ui::layoutProse(QString::fromUtf8("q̇ the velocities"));
        const MathBox q̇ = ui::layoutMath(*velocity);
        QCOMPARE(dotted.pieces.front().text, q̇.pieces.front().text);
        QCOMPARE(dotted.pieces.front().font, q̇.pieces.front().font);
        // Not symbols: a letter inside a word or followed by one, and words that are
        // only letters (in, on, a): one run of text, as layoutText sets it.
        for (const char* text : {"UR5 (CB3), Planar 2R, H2O, a robot in 3D", "in on a of"}) {
            const MathBox b = ui::layoutProse(QString::fromUtf8(text));
            QCOMPARE(b.pieces.size(), std::size_t(1));
            QCOMPARE(b.width, ui::layoutText(QString::fromUtf8(text)).width);
        }
        // A bare letter before a relation is a symbol too: "m = 0 < n = 2".
        const MathBox relation = ui::layoutProse("(underactuated: m = 0 < n = 2)");
        QVERIFY(pieceWithText(relation, "m") && pieceWithText(relation, "m")->font == 1);
        QVERIFY(pieceWithText(relation, "n") && pieceWithText(relation, "n")->font == 1);
        QVERIFY(pieceWithText(relation, "(underactuated: "));
        // Two-digit indices are written with commas, as the labels show them: b7,10.
        const MathBox wide = ui::layoutProse("to b7,10; depends on q10");
        const MathBox b710 = ui::layoutMath(*symbolNode("b", "7,10"));
        QCOMPARE(wide.width, ui::layoutText("to ").width + b710.width + ui::layoutText("; depends on ").width +
                                 ui::layoutMath(*symbolNode("q", "10")).width);
        // A note is as wide as its parts side by side.
        const MathBox parts[] = {ui::layoutText("depends on "), alone};
        QVERIFY(std::abs(ui::layoutProse("depends on q12").width - (parts[0].width + parts[1].width)) < 1e-9);
    }

    // A 7-joint arm typesets its structured form (it used to be refused): the names with
    // their meaning, B as sums; text stays text; no line from Qt on stderr.
    void pdfOfThePandaStructured() {
        QTemporaryDir dir;
        const QString pdf = dir.filePath("panda.pdf");
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("XDG_RUNTIME_DIR");
        p.setProcessEnvironment(env);
        p.start(LL_CLI, {"derive", example("panda.json"), "--format", "pdf", "--out", pdf});
        QVERIFY(p.waitForFinished(300000));
        QCOMPARE(p.exitCode(), 0);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.isEmpty(), qPrintable(err));
        const Run text = run({"-layout", pdf, "-"}, "pdftotext");
        QCOMPARE(text.code, 0);
        for (const char* s : {"Form: structured", "Jacobian columns", "in the frame of link 7", "depends on q", "contribution of link"})
            QVERIFY2(text.out.contains(QString::fromUtf8(s)), s);
        const Run info = run({pdf}, "pdfinfo");
        const QRegularExpressionMatch pages = QRegularExpression(R"(Pages:\s+(\d+))").match(info.out);
        QVERIFY(pages.hasMatch() && pages.captured(1).toInt() > 10);
    }

    void svgAndPng() {
        QTemporaryDir dir;
        const QString svg = dir.filePath("b.svg"), png = dir.filePath("b.png");
        QCOMPARE(run({"derive", example("planar_2r.json"), "--format", "svg", "--out", svg, "--steps", "7"}).code, 0);
        QCOMPARE(run({"derive", example("planar_2r.json"), "--format", "png", "--out", png, "--steps", "7"}).code, 0);
        QSvgRenderer renderer(svg);
        QVERIFY(renderer.isValid());
        QImage image(600, 420, QImage::Format_RGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        renderer.render(&painter);
        painter.end();
        QVERIFY(inked(image) > 0.002);
        const QImage bitmap(png);
        QVERIFY(!bitmap.isNull());
        QVERIFY(inked(bitmap) > 0.002);
    }

    // Pages of an earlier, longer export into the same name are named on stderr and left
    // as they were (nothing deletes a user's files).
    void olderPagesNamedNotDeleted() {
        QTemporaryDir dir;
        const QString svg = dir.filePath("b.svg");
        QCOMPARE(run({"derive", example("planar_2r.json"), "--format", "svg", "--out", svg}).code, 0);
        const QStringList all = QDir(dir.path()).entryList({"b*.svg"}, QDir::Files);
        QVERIFY(all.size() >= 3);
        QFile last(dir.filePath(QString("b-%1.svg").arg(all.size())));
        QVERIFY(last.open(QIODevice::ReadOnly));
        const QByteArray lastBytes = last.readAll();
        last.close();

        const Run again = run({"derive", example("planar_2r.json"), "--format", "svg", "--out", svg, "--steps", "7"});
        QCOMPARE(again.code, 0);
        const int now = static_cast<int>(again.err.count("wrote ")) > 0 ? static_cast<int>(again.err.count("wrote ")) : 1;
        QVERIFY(now < all.size());
        const QString note =
            QString("note: %1 page file%2 of an earlier, longer export remain").arg(all.size() - now).arg(all.size() - now == 1 ? "" : "s");
        QVERIFY2(again.err.contains(note), qPrintable(again.err));
        QVERIFY2(again.err.contains(QString("b-%1.svg").arg(now + 1)), qPrintable(again.err));
        QCOMPARE(QDir(dir.path()).entryList({"b*.svg"}, QDir::Files).size(), all.size());
        QVERIFY(last.open(QIODevice::ReadOnly));
        QCOMPARE(last.readAll(), lastBytes);

        // The same number of pages again: nothing to say.
        const Run same = run({"derive", example("planar_2r.json"), "--format", "svg", "--out", svg});
        QCOMPARE(same.code, 0);
        QVERIFY2(!same.err.contains("note:"), qPrintable(same.err));
    }

    void badInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("names");
        QTest::newRow("format") << QStringList{"--format", "docx", "--out", "/tmp/x.docx"} << "--format";
        QTest::newRow("steps") << QStringList{"--format", "pdf", "--out", "/tmp/x.pdf", "--steps", "3-10"} << "--steps";
        QTest::newRow("out") << QStringList{"--format", "pdf", "--out", "/nonexistent/dir/x.pdf"} << "--out";
        QTest::newRow("no out") << QStringList{"--format", "png"} << "--out";
    }
    void badInput() {
        QFETCH(QStringList, args);
        QFETCH(QString, names);
        const Run r = run(QStringList{"derive", example("planar_2r.json")} + args);
        QCOMPARE(r.code, 2);
        const QStringList lines = r.err.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1);
        QVERIFY2(lines[0].startsWith("error: ") && lines[0].contains(names), qPrintable(lines[0]));
    }
};

static int runMathTypesetter(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("DISPLAY")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    TestMathTypesetter test;
    return QTest::qExec(&test, argc, argv);
}
LL_TEST_PROGRAM(runMathTypesetter)

}  // namespace test_math_typesetter
#include "test_math_typesetter.moc"
