// The structured form as a document: its LaTeX is well formed (balanced braces and
// environments, text-mode specials escaped, no double subscripts, entry labels of 10+
// joints), and pdflatex compiles the PUMA 560's when it is installed; --steps selects
// the names of those steps and the results they give; the JSON lists only the names
// B, C, g need.
#include "test_registry.hpp"

#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <random>
#include <set>

#include <nlohmann/json.hpp>

#include "core/io/scene_file.hpp"
#include "core/pipeline/derivation_forms.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/present/structured_document.hpp"
#include "core/symbolic/structured_dynamics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_structured_document {

using namespace ll;
using namespace ll::symbolic;
using namespace ll::present;

namespace {

Scene exampleScene(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

Scene randomChain(int n, unsigned seed) {
    std::mt19937 rng(seed);
    Scene scene;
    scene.name = "random chain_" + std::to_string(n) + " & 100% {test}";  // LaTeX specials in the title
    scene.robot = test::randomRobot(rng, n, DhConvention::Standard, true);
    scene.effects.gravity = Eigen::Vector3d(0, 0, -9.81);
    return scene;
}

// What a LaTeX run would choke on, or "" when none: unbalanced braces or \begin/\end,
// an odd number of $ (inline math; \[ \] display math), _ ^ & % # outside math, a double subscript or
// superscript (x_{a}_{b}), \left without \right in one formula.
std::string latexProblem(const std::string& doc) {
    std::vector<std::string> environments;
    int depth = 0;
    bool math = false;
    int lefts = 0;
    // per brace depth: the scripts the current atom has (bit 1: _, bit 2: ^)
    std::vector<int> lastScript(1, 0);
    const auto line = [&](std::size_t at) { return std::to_string(std::count(doc.begin(), doc.begin() + at, '\n') + 1); };
    for (std::size_t i = 0; i < doc.size(); ++i) {
        const char c = doc[i];
        if (c == '\\') {
            std::size_t j = i + 1;
            while (j < doc.size() && std::isalpha(static_cast<unsigned char>(doc[j]))) ++j;
            std::string command = doc.substr(i + 1, j - i - 1);
            if (command.empty()) {  // \\, \{, \_, \$: a control symbol; \[ and \] open and close display math
                if (j < doc.size() && (doc[j] == '[' || doc[j] == ']')) {
                    if (doc[j] == ']' && lefts != 0) return "\\left without \\right in the formula ending at line " + line(i);
                    math = doc[j] == '[';
                    lefts = 0;
                }
                i = j;
                if (lastScript.size() > static_cast<std::size_t>(depth)) lastScript[depth] = 0;
                continue;
            }
            if (command == "begin" || command == "end") {
                const std::size_t close = doc.find('}', j);
                const std::string name = doc.substr(j + 1, close - j - 1);
                if (command == "begin") environments.push_back(name);
                else if (environments.empty() || environments.back() != name) return "\\end{" + name + "} unmatched at line " + line(i);
                else environments.pop_back();
            }
            if (command == "left") ++lefts;
            if (command == "right") --lefts;
            if (command == "right" || command == "left") {  // its delimiter is not a group
                i = j;
                continue;
            }
            i = j - 1;
            lastScript[depth] = 0;
            continue;
        }
        if (c == '%') return "an unescaped % at line " + line(i);
        if (c == '$') {
            if (math && lefts != 0) return "\\left without \\right in the formula ending at line " + line(i);
            math = !math;
            lefts = 0;
            continue;
        }
        if (c == '{') {
            ++depth;
            if (lastScript.size() <= static_cast<std::size_t>(depth)) lastScript.resize(depth + 1, 0);
            lastScript[depth] = 0;
            continue;
        }
        if (c == '}') {
            if (--depth < 0) return "a } without { at line " + line(i);
            continue;
        }
        if (c == '#' && i + 1 < doc.size() && std::isdigit(static_cast<unsigned char>(doc[i + 1]))) continue;  // a macro's #1
        if ((c == '_' || c == '^' || c == '&' || c == '#') && !math) return std::string("'") + c + "' outside math at line " + line(i);
        if (c == '_' || c == '^') {
            const int bit = c == '_' ? 1 : 2;
            if (lastScript[depth] & bit) return std::string("double ") + (c == '_' ? "subscript" : "superscript") + " at line " + line(i);
            // skip the script's argument: a group or one character; then it is the last script
            std::size_t j = i + 1;
            if (j < doc.size() && doc[j] == '{') {
                int d = 0;
                for (; j < doc.size(); ++j) {
                    if (doc[j] == '\\') {
                        ++j;
                        continue;
                    }
                    d += doc[j] == '{' ? 1 : doc[j] == '}' ? -1 : 0;
                    if (d == 0) break;
                }
            } else if (j < doc.size() && doc[j] == '\\') {
                while (j + 1 < doc.size() && std::isalpha(static_cast<unsigned char>(doc[j + 1]))) ++j;
            }
            i = j;
            lastScript[depth] |= bit;
            continue;
        }
        if (!std::isspace(static_cast<unsigned char>(c))) lastScript[depth] = 0;
    }
    if (depth != 0) return "unbalanced braces (" + std::to_string(depth) + " open at the end)";
    if (math) return "an odd number of $";
    if (!environments.empty()) return "\\begin{" + environments.back() + "} not ended";
    return "";
}

std::string document(const StructuredDynamics& s, DocumentFormat format, StructuredDocumentInfo info = {}) {
    if (info.formReason.empty()) info.formReason = MessageId::FormAskedFor;
    info.modeName = "parameters";
    return structuredDocument(s, format, info);
}

}  // namespace

class TestStructuredDocument : public QObject {
    Q_OBJECT
private slots:
    // The checker itself finds what pdflatex refuses.
    void checkerFindsLatexErrors_data() {
        QTest::addColumn<QString>("latex");
        QTest::addColumn<bool>("ok");
        QTest::newRow("fine") << R"($J_{P,1,x}^{(8)} = a_{1} + \left(b\right)$ and \_ text)" << true;
        QTest::newRow("double subscript") << R"($J_{P,1}^{(8)}_{x}$)" << false;
        QTest::newRow("double subscript plain") << R"($x_{1}_{2}$)" << false;
        QTest::newRow("underscore in text") << R"(sum_{i>=j} m_i)" << false;
        QTest::newRow("braces") << R"($a_{1$)" << false;
        QTest::newRow("left") << R"($\left( a$)" << false;
        QTest::newRow("environment") << R"(\begin{document} x)" << false;
        QTest::newRow("percent") << R"(100% sure)" << false;
        QTest::newRow("display math") << R"(\[ \begin{pmatrix} a_{1} & b \\[2pt] c & d \end{pmatrix} \] and \_)" << true;
        QTest::newRow("after display math") << R"(\[ a_{1} \] b_2)" << false;
    }
    void checkerFindsLatexErrors() {
        QFETCH(QString, latex);
        QFETCH(bool, ok);
        QCOMPARE(latexProblem(latex.toStdString()).empty(), ok);
    }

    // Every robot example, the parameter symbols kept, and a 10-joint chain (two-digit
    // indices, a prismatic joint, a title with LaTeX's specials).
    void latexIsWellFormed_data() {
        QTest::addColumn<QString>("scene");
        for (const char* name : {"puma560.json", "puma560_modified.json", "panda.json", "stanford_arm.json", "scara.json", "ur5.json"})
            QTest::newRow(name) << name;
        QTest::newRow("chain 10") << "";
    }
    void latexIsWellFormed() {
        QFETCH(QString, scene);
        const Scene sc = scene.isEmpty() ? randomChain(10, 5) : exampleScene(scene.toStdString());
        const StructuredDynamics s = deriveStructured(sc);
        const auto lock = lockGinac();
        const std::string latex = document(s, DocumentFormat::Latex);
        const std::string problem = latexProblem(latex);
        QVERIFY2(problem.empty(), problem.c_str());
        QVERIFY(latex.find("\\section*{Step 7}") != std::string::npos);
        if (scene.isEmpty()) {  // b_{1,10}, never b_{1_10}
            QVERIFY(latex.find("b_{1,10} =") != std::string::npos);
            QVERIFY(latex.find("b_{1_10}") == std::string::npos);
            // The names and notes index alike: β_{7,10}^{(10)}, "to b7,10", ∂b_{7,10}, never b710.
            QVERIFY(latex.find("\\beta_{7,10}^{(10)}") != std::string::npos);
            QVERIFY(latex.find("\\beta_{710}") == std::string::npos);
            const std::string text = document(s, DocumentFormat::Text);
            QVERIFY(text.find("contribution of link 10 to b7,10;") != std::string::npos);
            QVERIFY(text.find("to b710") == std::string::npos && text.find("derivative of b710") == std::string::npos);
            QVERIFY(text.find("sum_k c_7,10,k qd_k") != std::string::npos && text.find("sum_k c_23k qd_k") != std::string::npos);
            // and with an entry asked for and expanded
            StructuredDynamics copy = s;
            StructuredDocumentInfo info;
            info.entries = {parseEntry("B10_10", 10)};  // link 10 alone: cheap to expand
            info.expanded = {expandEntry(copy, info.entries[0])};
            const std::string one = latexProblem(document(copy, DocumentFormat::Latex, info));
            QVERIFY2(one.empty(), one.c_str());
        }
    }

    // The expanded form's LaTeX (core/present/derivation_document) too, as `derive
    // --format latex` makes it (with its "Form:" line): with a scene named with LaTeX's
    // specials it is well-formed, the name escaped in the title; the form's reason
    // ("asked for with --form", a Lagrangian's "E_kin and E_pot") escaped as well.
    void expandedLatexIsWellFormed_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("form");
        for (const char* name : {"planar_2r.json", "scara.json", "cart_pole.json", "mass_spring_pair_lagrangian.json"})
            QTest::newRow(name) << name << int(DerivationForm::Auto);
        QTest::newRow("planar_2r.json, --form expanded") << "planar_2r.json" << int(DerivationForm::Expanded);
    }
    void expandedLatexIsWellFormed() {
        QFETCH(QString, scene);
        QFETCH(int, form);
        Scene sc = exampleScene(scene.toStdString());
        sc.name = "my_robot #2 & 50% {x} ~^ $";
        FormRequest request;
        request.document.format = DocumentFormat::Latex;
        request.form = DerivationForm(form);
        const FormDocument out = deriveInForm(sc, request);
        QCOMPARE(int(out.form), int(DerivationForm::Expanded));
        const std::string& latex = out.derived.document;
        const std::string problem = latexProblem(latex);
        QVERIFY2(problem.empty(), problem.c_str());
        QVERIFY(latex.find("\\title{Euler--Lagrange model: my\\_robot \\#2 \\& 50\\% \\{x\\} \\textasciitilde{}\\^{} \\$}") !=
                std::string::npos);
        QVERIFY(latex.find("Form: expanded (") != std::string::npos);
        if (form == int(DerivationForm::Expanded)) QVERIFY(latex.find("asked for with -{}-form") != std::string::npos);
    }

    // pdflatex, when installed, compiles the PUMA 560's structured LaTeX without an error.
    void pumaLatexCompiles() {
        if (QStandardPaths::findExecutable("pdflatex").isEmpty())
            QSKIP("pdflatex is not installed (texlive-latex-base): the well-formedness check above still ran");
        const StructuredDynamics s = deriveStructured(exampleScene("puma560.json"));
        std::string latex;
        {
            const auto lock = lockGinac();
            latex = document(s, DocumentFormat::Latex);
        }
        QTemporaryDir dir;
        QFile f(dir.filePath("puma.tex"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(latex.data(), static_cast<qint64>(latex.size()));
        f.close();
        QProcess p;
        p.setWorkingDirectory(dir.path());
        p.start("pdflatex", {"-interaction=nonstopmode", "-halt-on-error", "puma.tex"});
        QVERIFY(p.waitForFinished(240000));
        const QByteArray log = p.readAllStandardOutput();
        QVERIFY2(p.exitCode() == 0, log.right(3000).constData());
        QVERIFY(QFileInfo(dir.filePath("puma.pdf")).size() > 10000);
        QVERIFY2(!log.contains("Overfull \\hbox"), "a line runs off the page");
    }

    // --steps 7-7: the beta names and b_jk; no frames, no C, no checks. 1-4: frames and
    // Jacobian columns only. JSON likewise, and B only with step 7, C and g with step 8.
    void stepsSelectNamesAndResults() {
        const StructuredDynamics s = deriveStructured(exampleScene("puma560.json"));
        const auto lock = lockGinac();
        StructuredDocumentInfo seven;
        seven.firstStep = seven.lastStep = 7;
        const std::string text = document(s, DocumentFormat::Text, seven);
        QVERIFY(text.find("Step 7.") != std::string::npos);
        QVERIFY(text.find("Step 1.") == std::string::npos && text.find("Step 8.") == std::string::npos);
        QVERIFY(text.find("    b11 = ") != std::string::npos);
        QVERIFY(text.find("    c11 = ") == std::string::npos && text.find("    g1 = ") == std::string::npos);
        QVERIFY(text.find("Zero pattern") == std::string::npos);
        // Each b_jk sums the links from max(j, k) to the last: "links 2–6", "link 6" alone
        // (an en dash; LaTeX's -- in its document).
        const std::string latex = document(s, DocumentFormat::Latex, seven);
        for (int j = 1; j <= 6; ++j)
            for (int k = j; k <= 6; ++k) {
                const std::size_t at = text.find("    b" + std::to_string(j) + std::to_string(k) + " = ");
                QVERIFY(at != std::string::npos);
                const std::string line = text.substr(at, text.find('\n', at) - at);
                const std::string links = k == 6 ? "link 6;" : "links " + std::to_string(k) + "–6;";
                QVERIFY2(line.find("(sum of the contributions of " + links) != std::string::npos, line.c_str());
                const std::string latexLinks = k == 6 ? "link 6;" : "links " + std::to_string(k) + "--6;";
                QVERIFY2(latex.find("sum of the contributions of " + latexLinks) != std::string::npos, latexLinks.c_str());
            }

        StructuredDocumentInfo early;
        early.firstStep = 1;
        early.lastStep = 4;
        const nlohmann::json j = nlohmann::json::parse(document(s, DocumentFormat::Json, early));
        QVERIFY(!j["definitions"].empty());
        for (const auto& d : j["definitions"]) QVERIFY(d["step"] == 1 || d["step"] == 4);
        QVERIFY(!j.contains("B") && !j.contains("C") && !j.contains("g"));

        const nlohmann::json all = nlohmann::json::parse(document(s, DocumentFormat::Json));
        QVERIFY(all.contains("B") && all.contains("C") && all.contains("g"));
        QVERIFY(all["definitions"].size() > j["definitions"].size());
        std::set<int> steps;
        for (const auto& d : all["definitions"]) steps.insert(d["step"].get<int>());
        QCOMPARE(steps, (std::set<int>{1, 4, 6, 7, 8}));
    }

    // The JSON lists a name only when B, C or g needs it, directly or through other names;
    // every name an expression uses is listed before it.
    void jsonListsOnlyNeededNamesInOrder() {
        const StructuredDynamics s = deriveStructured(randomChain(6, 11));
        const auto lock = lockGinac();
        const nlohmann::json j = nlohmann::json::parse(document(s, DocumentFormat::Json));
        std::set<std::string> listed, used;
        const auto namesIn = [&](const std::string& expr) {
            std::set<std::string> out;
            for (const NamedDefinition& d : s.table->entries()) {
                const std::string& name = d.name;
                for (std::size_t at = expr.find(name); at != std::string::npos; at = expr.find(name, at + 1)) {
                    const auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
                    if ((at == 0 || !ident(expr[at - 1])) && (at + name.size() == expr.size() || !ident(expr[at + name.size()])))
                        out.insert(name);
                }
            }
            return out;
        };
        for (const auto& d : j["definitions"]) {
            for (const std::string& n : namesIn(d["expr"].get<std::string>())) {
                QVERIFY2(listed.count(n), n.c_str());
                used.insert(n);
            }
            listed.insert(d["name"].get<std::string>());
            QVERIFY(d["depends_on"].is_array());
            for (const auto& k : d["depends_on"]) QVERIFY(k.get<int>() >= 1 && k.get<int>() <= 6);
        }
        for (const char* m : {"B", "C", "g"})
            for (const std::string& n : namesIn(j[m].dump())) used.insert(n);
        for (const std::string& n : listed) QVERIFY2(used.count(n), (n + " is listed but nothing uses it").c_str());
        QVERIFY(static_cast<int>(listed.size()) <= s.table->size());
    }

    // An entry expanded on demand has the value of the structured entry (itself checked
    // against the numeric core in test_structured_dynamics) at random states: C_ij from
    // the B entries that depend on the coordinate, c_ii from b_ii alone.
    void expandedEntriesEqualTheStructuredOnes() {
        StructuredDynamics s = deriveStructured(exampleScene("stanford_arm.json"));  // a prismatic joint; cheap to expand
        const auto lock = lockGinac();
        std::mt19937 rng(9);
        int nonzero = 0;
        for (const char* label : {"C11", "C23", "C32", "C55", "C16", "B12", "B44", "g3"}) {
            const EntryRef ref = parseEntry(label, 6);
            const ExpandedEntry e = expandEntry(s, ref);
            QCOMPARE(e.terms == 0, e.value.is_zero());
            const GiNaC::ex& structured = ref.matrix == 'B'   ? s.B(ref.row, ref.col)
                                          : ref.matrix == 'C' ? s.C(ref.row, ref.col)
                                                              : s.g(ref.row, 0);
            for (int k = 0; k < 3; ++k) {
                const Eigen::VectorXd q = test::randomVector(rng, 6, 2.0), qd = test::randomVector(rng, 6, 2.0);
                const DefinitionValues v(*s.table, structuredInputs(s, {q.data(), q.data() + 6}, {qd.data(), qd.data() + 6}));
                const double a = v(e.value), b = v(structured);
                QVERIFY2(std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)),
                         qPrintable(QString("%1: %2 vs %3").arg(label).arg(a).arg(b)));
                nonzero += std::abs(b) > 1e-6 ? 1 : 0;
            }
        }
        QVERIFY(nonzero >= 15);  // most of them are not identically zero
    }
};

LL_TEST_GUILESS_MAIN(TestStructuredDocument)

}  // namespace test_structured_document
#include "test_structured_document.moc"
