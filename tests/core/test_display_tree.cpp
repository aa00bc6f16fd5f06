// display_tree / display_builder: the Text and LaTeX renderings of every item of the
// 2R, the SCARA and the mass–spring Lagrangian come from one tree, so reading the
// symbols and numbers back out of each string (independently: a Unicode reader and a
// small LaTeX reader) gives the same sequence; the textbook's factored forms.
#include "test_registry.hpp"

#include <QRegularExpression>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "core/present/display_builder.hpp"
#include "core/present/text_document.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/present/structured_display.hpp"
#include "core/symbolic/structured_dynamics.hpp"
#include "core/model/cancellation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_display_tree {

using namespace ll;
using namespace ll::symbolic;
using namespace ll::present;

namespace {

const char* greekNames[][2] = {{"alpha", "α"},  {"beta", "β"}, {"gamma", "γ"}, {"delta", "δ"}, {"theta", "θ"},
                               {"lambda", "λ"}, {"mu", "μ"},   {"pi", "π"},    {"rho", "ρ"},   {"sigma", "σ"},
                               {"tau", "τ"},    {"phi", "φ"},  {"omega", "ω"}, {"ell", "ℓ"},   {"Omega", "Ω"}};

// The identifiers and digits of a Text rendering, in reading order: dots as ', powers
// as digits, every operator, bracket, space and separator dropped.
QString textLeaves(const std::string& text) {
    QString s = QString::fromStdString(text);
    const QString sup = "⁰¹²³⁴⁵⁶⁷⁸⁹";
    QString out;
    for (QChar c : s) {
        if (c == QChar(0x0307)) out += "'";
        else if (c == QChar(0x0308)) out += "''";
        else if (sup.contains(c)) out += QChar(static_cast<char16_t>('0' + sup.indexOf(c)));
        else if (c.isLetterOrNumber()) out += c;
    }
    return out;
}

// The same read from LaTeX: \dot{x} → x', \theta → θ, \mathrm{kin} → kin, commands
// of layout (\frac, \left, \cdot, \begin{bmatrix}) dropped.
QString latexLeaves(const std::string& latex) {
    QString s = QString::fromStdString(latex);
    s.remove(QRegularExpression(R"(\\(begin|end)\{bmatrix\})"));
    for (const auto& g : greekNames) s.replace(QRegularExpression(QString(R"(\\%1(?![a-zA-Z]))").arg(g[0])), g[1]);
    // \dot{x}, \ddot{\theta} (already θ): the mark after the letter.
    s.replace(QRegularExpression(R"(\\ddot\{([^{}]*)\})"), "\\1''");
    s.replace(QRegularExpression(R"(\\dot\{([^{}]*)\})"), "\\1'");
    s.replace(QRegularExpression(R"(\\(sin|cos|tan|exp|ln)(?![a-zA-Z]))"), "\\1");
    s.remove(QRegularExpression(R"(\\[a-zA-Z]+)"));  // \frac \left \right \cdot \mathrm \sqrt
    QString out;
    for (QChar c : s)
        if (c == '\'' || c.isLetterOrNumber()) out += c;
    return out;
}

std::shared_ptr<const DisplayDocument> shown(const char* example, symbolic::ParameterMode mode) {
    const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example).scene;
    DocumentRequest request;
    request.mode = mode;
    request.format = DocumentFormat::Display;
    return deriveDocument(scene, request).display;
}

// Every example that loads (massless_joint is refused by design), in parameters and in
// numbers, as the window shows it (the form auto picks), with its file name.
std::vector<std::pair<std::string, std::shared_ptr<const DisplayDocument>>> exampleDocuments() {
    std::vector<std::pair<std::string, std::shared_ptr<const DisplayDocument>>> out;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        Scene scene;
        try {
            scene = loadScene(entry.path().string()).scene;
        } catch (const InputError&) {
            continue;
        }
        if (scene.dof() == 0) continue;
        for (auto mode : {symbolic::ParameterMode::Parametric, symbolic::ParameterMode::Numeric}) {
            DocumentRequest request;
            request.mode = mode;
            out.emplace_back(entry.path().filename().string(), deriveDisplay(scene, request).display);
        }
    }
    return out;
}

}  // namespace

class TestDisplayTree : public QObject {
    Q_OBJECT

private slots:
    void textAndLatexShowTheSameLeaves_data() {
        QTest::addColumn<QString>("example");
        QTest::addColumn<int>("mode");
        for (const char* e : {"planar_2r.json", "scara.json", "mass_spring_pair_lagrangian.json"})
            for (int mode : {0, 1, 2}) QTest::newRow((std::string(e) + " mode " + std::to_string(mode)).c_str()) << QString(e) << mode;
    }
    void textAndLatexShowTheSameLeaves() {
        QFETCH(QString, example);
        QFETCH(int, mode);
        const auto doc = shown(example.toStdString().c_str(), static_cast<symbolic::ParameterMode>(mode));
        QVERIFY(doc);
        int items = 0;
        for (const DisplayStep& step : doc->steps)
            for (const DisplayItem& item : step.items) {
                const std::string text = renderDisplay(*item.value, DisplayStyle::Text);
                const std::string latex = renderDisplay(*item.value, DisplayStyle::Latex);
                const QString a = textLeaves(text), b = latexLeaves(latex);
                QVERIFY2(!a.isEmpty(), item.name.c_str());
                QVERIFY2(a == b,
                         (item.name + "\n text:  " + text + "\n latex: " + latex + "\n " + a.toStdString() + "\n " + b.toStdString())
                             .c_str());
                ++items;
            }
        QVERIFY(items >= 5);
    }

    // The structured form (named link quantities, B, g, C as sums over them) is one tree
    // too: every definition and entry of the PUMA 560 (structured on request) and the
    // Franka Panda (structured by auto) reads the same in Text and LaTeX, and the names
    // are written in textbook notation.
    void structuredTextAndLatexShowTheSameLeaves_data() {
        QTest::addColumn<QString>("example");
        QTest::addColumn<int>("mode");
        for (const char* e : {"puma560.json", "panda.json"})
            for (int mode : {0, 1, 2}) QTest::newRow((std::string(e) + " mode " + std::to_string(mode)).c_str()) << QString(e) << mode;
    }
    void structuredTextAndLatexShowTheSameLeaves() {
        QFETCH(QString, example);
        QFETCH(int, mode);
        const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example.toStdString()).scene;
        DocumentRequest request;
        request.mode = static_cast<symbolic::ParameterMode>(mode);
        const auto doc = deriveDisplay(scene, request, DerivationForm::Structured).display;
        QCOMPARE(QString::fromStdString(doc->form.english()), QString("structured"));
        int items = 0, sums = 0;
        std::set<std::string> names;
        for (const DisplayStep& step : doc->steps) {
            QVERIFY(step.formula);
            for (const DisplayItem& item : step.items) {
                const std::string text = renderDisplay(*item.equation, DisplayStyle::Text);
                const std::string latex = renderDisplay(*item.equation, DisplayStyle::Latex);
                const QString a = textLeaves(text), b = latexLeaves(latex);
                QVERIFY2(!a.isEmpty() && a == b, (item.name + "\n text:  " + text + "\n latex: " + latex).c_str());
                names.insert(item.name);
                if (item.name == "b11") sums = item.value->kind == DisplayKind::Sum ? int(item.value->children.size()) : 0;
                ++items;
            }
        }
        const int n = scene.robot.dof();
        QVERIFY(items > n * n);  // names, then b_jk, g_j, c_ij
        QVERIFY(names.count("b11") && names.count("g2") && names.count("c23"));
        QVERIFY2(sums >= 3, std::to_string(sums).c_str());  // b11 = Σ_i β11^(i) (+ armature), not expanded
    }

    // A builder that has built many expressions (and keeps their symbols and ordered
    // sums: the structured documents' printer) shows each expression as a fresh builder
    // does: every name and entry of the Panda's and the PUMA 560's structured models, in
    // the three styles.
    void symbolSharingBuilderAgreesWithFreshOnes() {
        for (const char* example : {"puma560.json", "panda.json"}) {
            const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example).scene;
            const auto lock = lockGinac();
            const StructuredDynamics s = deriveStructured(scene, {});
            DisplayOptions options;
            for (int i = 0; i < s.n; ++i) options.names.coordinateNames.push_back("q" + std::to_string(i + 1));
            DisplayBuilder shared(options);
            std::vector<GiNaC::ex> all;
            for (const NamedDefinition& d : s.table->entries()) all.push_back(d.value);
            for (const GiNaC::matrix* m : {&s.B, &s.C, &s.g})
                for (unsigned i = 0; i < m->nops(); ++i) all.push_back(m->op(i));
            all.push_back(s.B);  // a matrix, after its entries
            int compared = 0;
            for (const GiNaC::ex& e : all) {
                const DisplayPtr a = shared(e), b = buildDisplay(e, options);
                for (DisplayStyle style : {DisplayStyle::Plain, DisplayStyle::Text, DisplayStyle::Latex}) {
                    const std::string x = renderDisplay(*a, style), y = renderDisplay(*b, style);
                    QVERIFY2(x == y, (x + "\n" + y).c_str());
                }
                ++compared;
            }
            QVERIFY(compared > 300);
        }
    }

    void structuredNamesInTextbookNotation() {
        const auto latex = [](const char* name) { return renderDisplay(*structuredNameNode(name), DisplayStyle::Latex); };
        QCOMPARE(QString::fromStdString(latex("Jx2_4")), QString("J_{P2,x}^{(4)}"));
        QCOMPARE(QString::fromStdString(latex("beta2_3_4")), QString("\\beta_{23}^{(4)}"));
        QCOMPARE(QString::fromStdString(latex("beta2_10_10")), QString("\\beta_{2,10}^{(10)}"));
        QCOMPARE(QString::fromStdString(latex("zy1_3")), QString("z_{1,y}^{(3)}"));
        QCOMPARE(QString::fromStdString(latex("Db2_3_3")), QString("\\partial_{q_{3}} b_{23}"));
        QCOMPARE(QString::fromStdString(renderDisplay(*structuredNameNode("gamma2_4"), DisplayStyle::Text)), QString("γ2(4)"));
    }

    // One number style per entry: the double pendulum's E_kin had 0.1 (…) beside 1/5 (…);
    // and no decimal is pulled out of a sum (issue 40): 0.5 m1 l1² inside the parenthesis.
    // Fractions where the formulas make them, decimals where the scene typed them (issue
    // 40): the double pendulum's E_kin has no typed decimal, so its ½ and ⅕ stay
    // fractions (it read 0.5 m1 l1² + 0.2 m1 r²); the simple pendulum's bob reads as the
    // textbook's point mass plus the sphere's own 2/5 m r².
    void fractionsFromFormulasDecimalsAsTyped() {
        const auto item = [](const char* example, const std::string& name) {
            const auto doc = shown(example, symbolic::ParameterMode::Parametric);
            for (const DisplayStep& step : doc->steps)
                for (const DisplayItem& it : step.items)
                    if (it.name == name) return it;
            return DisplayItem{};
        };
        const std::string ekin = renderDisplay(*item("double_pendulum.json", "E_kin").value, DisplayStyle::Text);
        QVERIFY2(ekin.find("(1/2 m1 l1² + 1/5 m1 r²") != std::string::npos, ekin.c_str());
        QVERIFY2(ekin.find('.') == std::string::npos, ekin.c_str());
        const DisplayItem b = item("simple_pendulum.json", "B"), eq = item("simple_pendulum.json", "equation_1");
        QVERIFY(b.value && b.value->kind == DisplayKind::Matrix);
        QCOMPARE(QString::fromStdString(renderDisplay(*b.value->rows[0][0], DisplayStyle::Text)), QString("m (l² + 2/5 r²)"));
        QCOMPARE(QString::fromStdString(renderDisplay(*eq.equation, DisplayStyle::Text)), QString("m (l² + 2/5 r²) q̈1 + 9.81 m l s1 = 0"));
    }

    // One style per matrix (issue 40): a 3-joint arm typed in decimals shows each value
    // of C one way in every entry (it had c22 = −0.06 s3 q̇3 beside c23 = −3/50 s3 …),
    // and every value made of its decimals as a decimal. Read from the tree: a Number
    // shown as a decimal carries its exact value in Plain, a Fraction its digits.
    void oneStylePerMatrix() {
        const Scene scene = parseScene(R"json({"format": "lagrangelab-scene/1", "name": "3R in decimals",
            "robot": {"convention": "standard", "joints": [
            {"type": "revolute", "a": 0.3, "alpha": 0, "d": 0, "theta": 0, "mass": 1.5, "com": [-0.15, 0, 0], "inertia": {"xx": 0, "yy": 0.01, "zz": 0.01}},
            {"type": "revolute", "a": 0.2, "alpha": 0, "d": 0, "theta": 0, "mass": 1.2, "com": [-0.1, 0, 0], "inertia": {"xx": 0, "yy": 0.004, "zz": 0.004}},
            {"type": "revolute", "a": 0.1, "alpha": 0, "d": 0, "theta": 0, "mass": 0.6, "com": [-0.05, 0, 0], "inertia": {"xx": 0, "yy": 0.0005, "zz": 0.0005}}]},
            "effects": {"gravity": [0, -9.81, 0]}})json");
        DocumentRequest request;
        request.format = DocumentFormat::Display;
        const auto doc = deriveDocument(scene, request).display;
        for (const char* name : {"B", "C", "g"}) {
            std::map<std::string, std::set<std::string>> spellings;  // exact value → how it reads
            int numbers = 0;
            const std::function<void(const DisplayNode&)> walk = [&](const DisplayNode& n) {
                if (n.kind == DisplayKind::Number && n.plain.size() > 2 && n.plain.front() == '(') {
                    spellings[n.plain.substr(1, n.plain.size() - 2)].insert("decimal");
                    ++numbers;
                }
                if (n.kind == DisplayKind::Fraction && n.children[0]->kind == DisplayKind::Number &&
                    n.children[1]->kind == DisplayKind::Number) {
                    spellings[n.children[0]->plain + "/" + n.children[1]->plain].insert("fraction");
                    ++numbers;
                    return;
                }
                for (const auto& c : n.children) walk(*c);
                for (const auto& row : n.rows)
                    for (const auto& c : row) walk(*c);
            };
            for (const DisplayStep& step : doc->steps)
                for (const DisplayItem& item : step.items)
                    if (item.name == name) walk(*item.value);
            QVERIFY2(numbers > 3, name);
            for (const auto& [value, styles] : spellings)
                QVERIFY2(styles == std::set<std::string>{"decimal"},
                         qPrintable(QString("%1: %2 reads as a fraction").arg(name, value.c_str())));
        }
    }

    // Numbers as a student writes them (issue 40), on every example in parameters and in
    // numbers, in the form the window picks: no decimal or power of ten in front of a
    // parenthesis (5·10⁻¹⁰ (8347998 + …), 0.1 (…)), no integer of seven digits or more.
    void noDecimalFactorsPulledOutOfSums() {
        static const QRegularExpression pulled(R"((^|[ (=−+])(\d+\.\d+|\d+(\.\d+)?·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+) \()");
        static const QRegularExpression longInteger(R"((?<![\d.])\d{7,}(?![\d.]))");
        for (const auto& [file, doc] : exampleDocuments()) {
            for (const DisplayStep& step : doc->steps)
                for (const DisplayItem& item : step.items) {
                    const QString text = QString::fromStdString(renderDisplay(*item.equation, DisplayStyle::Text));
                    const QString where = QString::fromStdString(file + " " + item.name + ": ");
                    QVERIFY2(!pulled.match(text).hasMatch(),
                             qPrintable(where + pulled.match(text).captured(0) + " in " + text.left(300)));
                    QVERIFY2(!longInteger.match(text).hasMatch(), qPrintable(where + longInteger.match(text).captured(0)));
                }
        }
    }

    // One number style per entry (issue 51), on every example in parameters and in
    // numbers, in the form the window picks: an entry (a scalar, an equation, each entry
    // of a matrix) has its decimals below 1 all plain (0.0005) or all in powers of ten
    // (5.00861·10⁻⁵), never both; plain while every one fits in eight places after the
    // point; never "1·10".
    void oneNumberStylePerEntry() {
        static const QRegularExpression plainSmall(R"((?<![\d.])0\.(\d+))");
        static const QRegularExpression powerOfTen(R"(10⁻)");
        static const QRegularExpression oneTimes(R"((?<![\d.])1·10)");
        int plainEntries = 0, scientificEntries = 0;
        for (const auto& [file, doc] : exampleDocuments()) {
            std::vector<std::pair<std::string, const DisplayNode*>> entries;  // a matrix's cells each, else the equation
            for (const DisplayStep& step : doc->steps)
                for (const DisplayItem& item : step.items)
                    if (item.value->kind == DisplayKind::Matrix) {
                        for (const auto& row : item.value->rows)
                            for (const DisplayPtr& cell : row) entries.emplace_back(item.name, cell.get());
                    } else {
                        entries.emplace_back(item.name, item.equation.get());
                    }
            for (const auto& [name, node] : entries) {
                const QString text = QString::fromStdString(renderDisplay(*node, DisplayStyle::Text));
                const QString where = QString::fromStdString(file + " " + name + ": ");
                const bool plain = plainSmall.match(text).hasMatch(), scientific = powerOfTen.match(text).hasMatch();
                QVERIFY2(!(plain && scientific), qPrintable(where + text.left(400)));
                QVERIFY2(!oneTimes.match(text).hasMatch(), qPrintable(where + text.left(400)));
                for (auto m = plainSmall.globalMatch(text); m.hasNext();) {
                    const QString fraction = m.next().captured(1);
                    QVERIFY2(fraction.size() <= 8, qPrintable(where + "0." + fraction));
                }
                plainEntries += plain;
                scientificEntries += scientific;
                // and every number still reads as its exact value (to its six digits)
                const std::function<void(const DisplayNode&)> sameValue = [&](const DisplayNode& n) {
                    if (n.kind == DisplayKind::Number && (n.text.find('.') != std::string::npos || !n.exponent.empty())) {
                        std::string exact = n.plain;
                        if (!exact.empty() && exact.front() == '(') exact = exact.substr(1, exact.size() - 2);
                        const auto slash = exact.find('/');
                        const double value =
                            slash == std::string::npos ? std::stod(exact) : std::stod(exact.substr(0, slash)) / std::stod(exact.substr(slash + 1));
                        const double shown =
                            (n.text.empty() ? 1.0 : std::stod(n.text)) * std::pow(10.0, n.exponent.empty() ? 0 : std::stoi(n.exponent));
                        QVERIFY2(std::abs(shown - value) <= 5e-6 * std::abs(value),
                                 qPrintable(where + QString::fromStdString(n.text + "e" + n.exponent + " for " + n.plain)));
                    }
                    for (const auto& c : n.children) sameValue(*c);
                    for (const auto& row : n.rows)
                        for (const auto& c : row) sameValue(*c);
                };
                sameValue(*node);
            }
        }
        qInfo("%d entries with plain decimals, %d in powers of ten", plainEntries, scientificEntries);
        QVERIFY(plainEntries > 50 && scientificEntries > 5);  // both styles are met
    }

    // The readers are not blind: a different symbol in LaTeX is seen.
    void readersSeeADifference() {
        QCOMPARE(textLeaves("m2 a1 ℓc2 s2 q̇1²"), latexLeaves("m_{2} a_{1} \\ell_{c2} s_{2} \\dot{q}_{1}^{2}"));
        QVERIFY(textLeaves("m2 a1 ℓc2 s2 q̇1²") != latexLeaves("m_{2} a_{1} \\ell_{c2} s_{2} q_{1}^{2}"));
        QVERIFY(textLeaves("θ̈1") == latexLeaves("\\ddot{\\theta}_{1}"));
    }

    // The 2R in the textbook's factored form (Siciliano §7.3.2).
    void planar2RFactored() {
        const auto doc = shown("planar_2r.json", symbolic::ParameterMode::Parametric);
        std::string C, eq1;
        for (const DisplayStep& step : doc->steps)
            for (const DisplayItem& item : step.items) {
                if (item.name == "C") C = renderDisplay(*item.value, DisplayStyle::Text);
                if (item.name == "equation_1") eq1 = renderDisplay(*item.equation, DisplayStyle::Text);
            }
        QVERIFY2(C.find("−m2 a1 ℓc2 s2 (q̇1 + q̇2)") != std::string::npos, C.c_str());
        // Entry by entry as the scene's description and the textbook write them.
        const DisplayPtr B = [&] {
            for (const DisplayStep& step : doc->steps)
                for (const DisplayItem& item : step.items)
                    if (item.name == "B") return item.value;
            return DisplayPtr{};
        }();
        QVERIFY(B && B->kind == DisplayKind::Matrix);
        const auto entry = [&](int i, int j) { return QString::fromStdString(renderDisplay(*B->rows[i][j], DisplayStyle::Text)); };
        QCOMPARE(entry(0, 0), QString("I1 + m1 ℓc1² + I2 + m2 (a1² + ℓc2² + 2 a1 ℓc2 c2)"));
        QCOMPARE(entry(0, 1), QString("I2 + m2 (ℓc2² + a1 ℓc2 c2)"));
        QCOMPARE(entry(1, 0), entry(0, 1));
        QCOMPARE(entry(1, 1), QString("I2 + m2 ℓc2²"));
        QVERIFY2(eq1.find("− m2 a1 ℓc2 s2 (2 q̇1 q̇2 + q̇2²)") != std::string::npos, eq1.c_str());
    }

    // A square stays a square: a₁ typed as 1.2 in the 2R's DH table while link 1's COM
    // still says lc1-a1 puts link 1's COM at 1.2 − a1 + ℓc1 from joint 1, and b11 and
    // equation 1 show m1 (1.2 − a1 + ℓc1)², not its six expanded terms. Its value is
    // unchanged: the entry with a1 = ℓc1 = 0 is I1 + 1.44 m1 + ….
    void squaresKeptAsSquares() {
        std::ifstream file(std::string(LL_EXAMPLES_DIR) + "/planar_2r.json");
        std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        const std::string typed = R"("a": "a1")";
        QVERIFY(text.find(typed) != std::string::npos);
        text.replace(text.find(typed), typed.size(), R"("a": 1.2)");
        DocumentRequest request;
        request.mode = symbolic::ParameterMode::Parametric;
        const auto doc = deriveDisplay(parseScene(text), request).display;
        std::string b11, eq1;
        for (const DisplayStep& step : doc->steps)
            for (const DisplayItem& item : step.items) {
                if (item.name == "B") b11 = renderDisplay(*item.value->rows[0][0], DisplayStyle::Text);
                if (item.name == "equation_1") eq1 = renderDisplay(*item.equation, DisplayStyle::Text);
            }
        QVERIFY2(b11.find("m1 (1.2 − a1 + ℓc1)²") != std::string::npos, b11.c_str());
        QVERIFY2(eq1.find("m1 (1.2 − a1 + ℓc1)²") != std::string::npos, eq1.c_str());
        QVERIFY2(b11.find("1.44") == std::string::npos || b11.find("1.44 + ℓc2²") != std::string::npos, b11.c_str());
        // The shaped entry is still b11 (Siciliano's, with the COM 1.2 − a1 + ℓc1 from joint 1):
        // its Plain spelling parses back to the expanded closed form.
        std::string plain;
        for (const DisplayStep& step : doc->steps)
            for (const DisplayItem& item : step.items)
                if (item.name == "B") plain = renderDisplay(*item.value->rows[0][0], DisplayStyle::Plain);
        const auto lock = symbolic::lockGinac();
        GiNaC::parser reader;
        const GiNaC::ex parsed = reader(plain);
        GiNaC::symtab s = reader.get_syms();
        const GiNaC::ex lc = GiNaC::numeric(6, 5) - s["a1"] + s["lc1"];
        const GiNaC::ex expected = s["I1"] + s["m1"] * lc * lc + s["I2"] +
                                   s["m2"] * (GiNaC::numeric(36, 25) + s["lc2"] * s["lc2"] + 2 * GiNaC::numeric(6, 5) * s["lc2"] * GiNaC::cos(s["q2"]));
        QVERIFY2((parsed - expected).expand().is_zero(), plain.c_str());
    }

    // Decimals with more than 6 significant digits (products of identified inertials)
    // read rounded in Text and LaTeX; a scene's own short decimals stay as typed; Plain,
    // which is parsed back, keeps every digit.
    void longDecimalsReadWithSixDigits() {
        const auto lock = symbolic::lockGinac();
        const GiNaC::symbol x("x"), y("y");
        const DisplayPtr d = buildDisplay(GiNaC::numeric(0.00796990221726315) * x + GiNaC::numeric(0.15005) * y, {});
        const std::string text = renderDisplay(*d, DisplayStyle::Text), latex = renderDisplay(*d, DisplayStyle::Latex),
                          plain = renderDisplay(*d, DisplayStyle::Plain);
        QVERIFY2(text.find("0.0079699 x") != std::string::npos && text.find("0.15005 y") != std::string::npos, text.c_str());
        QVERIFY2(latex.find("0.0079699") != std::string::npos && latex.find("0.00796990221") == std::string::npos, latex.c_str());
        QVERIFY2(plain.find("0.0079699022172631") != std::string::npos, plain.c_str());
    }

    // Building the display trees stops at a set cancel flag (between items, under the
    // GiNaC lock a newer edit's check waits for), in both forms; unset, it finishes.
    void displayBuildingStopsWhenCancelled() {
        const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/scara.json").scene;
        const auto lock = symbolic::lockGinac();
        symbolic::DerivationOptions options;
        const symbolic::Derivation d = symbolic::deriveRobot(scene, options);
        std::atomic<bool> stop{true};
        QVERIFY_THROWS_EXCEPTION(Cancelled, present::displayDocument(d, &stop));
        const symbolic::StructuredDynamics s = symbolic::deriveStructured(scene, options);
        QVERIFY_THROWS_EXCEPTION(Cancelled, present::structuredDisplayDocument(s, literal("test"), 0, 8, &stop));
        stop = false;
        QVERIFY(!present::displayDocument(d, &stop)->steps.empty());
        QVERIFY(!present::structuredDisplayDocument(s, literal("test"), 0, 8, &stop)->steps.empty());
    }

    // A matrix too wide for a line is listed entry by entry without its zeros: the PUMA
    // 560's motor inertia B_m = diag(G_j² Jm_j) lists its 6 diagonal entries, not 36.
    void wideMatricesListNoZeroEntries() {
        const auto doc = shown("puma560.json", symbolic::ParameterMode::Parametric);
        std::string listing;
        for (const DisplayStep& step : doc->steps)
            for (const DisplayItem& item : step.items)
                if (item.name == "B_m") {
                    const auto& rows = item.value->rows;
                    QCOMPARE(int(rows.size()), 6);
                    QVERIFY(isZeroNumber(*rows[0][1]) && !isZeroNumber(*rows[0][0]));
                    // Narrowed below 160 characters by hand: as the window's dock would.
                    DisplayItem wide = item;
                    auto padded = std::make_shared<DisplayNode>(*item.value);
                    for (std::size_t i = 0; i < padded->rows.size(); ++i)
                        padded->rows[i][i] = displayEquation(padded->rows[i][i], displayRaw(std::string(30, 'x'), "x", "x"));
                    wide.value = padded;
                    wide.equation = displayEquation(displayRaw("B_m", "B_m", "B_m"), padded);
                    listing = itemText(wide);
                }
        QVERIFY2(listing.find("entry by entry, the zeros left out:") != std::string::npos, listing.c_str());
        int lines = 0;
        for (char c : listing) lines += c == '\n';
        QCOMPARE(lines, 6);  // one line per diagonal entry under the heading
        QVERIFY2(listing.find("= 0\n") == std::string::npos && listing.find("= 0", listing.size() - 3) == std::string::npos,
                 listing.c_str());
    }

    // itemText decides block or listing without writing the block when an entry alone
    // is too wide (a lower bound of its columns). Around the 160-column edge, with sums
    // of n one-column terms (4n − 3 columns) bare, negated and inside a product's
    // parentheses, the decision is the one the written block gives.
    void wideEntryShortcutAgreesWithTheBlock() {
        auto columns = [](const std::string& s) {
            int widest = 0;
            for (const QString& line : QString::fromStdString(s).split('\n')) {
                int n = 0;
                for (QChar c : line) n += !(c.unicode() >= 0x0300 && c.unicode() <= 0x036F) && !c.isLowSurrogate();
                widest = std::max(widest, n);
            }
            return widest;
        };
        const DisplayPtr zero = displayNumber("0", "0", "0"), x = displaySymbolName("x");
        int blocks = 0, listings = 0;
        for (int n = 36; n <= 46; ++n)
            for (int shape = 0; shape < 3; ++shape) {
                std::vector<DisplayPtr> terms;
                for (int k = 0; k < n; ++k) terms.push_back(displayNumber(std::to_string(k % 10), "d", "d"));
                DisplayPtr entry = displaySumOf(terms);
                if (shape == 1) {  // −0 − 1 + 2 − 3 …: a leading minus, minus signs between
                    auto signs = std::make_shared<DisplayNode>(*entry);
                    for (std::size_t k = 0; k < signs->negative.size(); ++k) signs->negative[k] = k % 2 == 0;
                    entry = signs;
                }
                if (shape == 2) entry = displayNode(DisplayKind::Product, {x, displayNode(DisplayKind::Fence, {entry})});
                auto matrix = std::make_shared<DisplayNode>();
                matrix->kind = DisplayKind::Matrix;
                matrix->rows = {{entry, zero}, {zero, x}};
                DisplayItem item;
                item.name = "B";
                item.latexName = "B";
                item.quantity = Quantity::MassMatrix;
                item.equation = displayEquation(displayRaw("B", "B", "B"), matrix);
                item.value = matrix;
                const std::string block = renderDisplay(*item.equation, DisplayStyle::Text), text = itemText(item);
                if (columns(block) <= int(maxTextMatrixRow)) {
                    QCOMPARE(QString::fromStdString(text), QString::fromStdString(block));
                    ++blocks;
                } else {
                    const std::string expected =
                        "B (2×2), entry by entry, the zeros left out:\n  b11 = " + renderDisplay(*entry, DisplayStyle::Text) +
                        "\n  b22 = x";
                    QCOMPARE(QString::fromStdString(text), QString::fromStdString(expected));
                    ++listings;
                }
            }
        QVERIFY(blocks >= 6 && listings >= 6);  // both sides of the edge were reached
    }

    // Plain from the display tree parses back to the same value (the whole document's
    // `expr` comes from it).
    void plainOfDisplayedReparses() {
        const auto lock = lockGinac();
        const GiNaC::symbol m2("m2"), qd1("qd1"), qd2("qd2"), s2("s2"), a1("a1");
        const GiNaC::ex e = -m2 * a1 * s2 * (qd1 + qd2);
        const DisplayPtr tree = buildDisplay(e, {{{"q1", "q2"}, true}});
        QCOMPARE(QString::fromStdString(renderDisplay(*tree, DisplayStyle::Text)), QString("−m2 a1 s2 (q̇1 + q̇2)"));
        GiNaC::symtab table{{"m2", m2}, {"qd1", qd1}, {"qd2", qd2}, {"a1", a1}, {"q2", GiNaC::symbol("q2")}};
        GiNaC::parser reader(table);
        const GiNaC::ex parsed = reader(renderDisplay(*tree, DisplayStyle::Plain));
        const GiNaC::ex difference = (parsed - e.subs(s2 == GiNaC::sin(table["q2"]))).expand();
        QVERIFY2(difference.is_zero(), renderDisplay(*tree, DisplayStyle::Plain).c_str());
    }
};

LL_TEST_APPLESS_MAIN(TestDisplayTree)

}  // namespace test_display_tree
#include "test_display_tree.moc"
