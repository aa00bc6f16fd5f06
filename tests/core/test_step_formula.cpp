// A step's general formula is data (core/model/step_formula.hpp): math, letters a textbook
// names its own way, and words in the reader's language (issue 46). Checked here: the
// marks read as typed letters; each notation's letters (the notes' B q̈ + C q̇ + g = Q,
// Spong's D q̈ + C q̇ + g = τ, Craig's M Θ̈ + … + G = τ) in text and LaTeX; words with math
// between them in LaTeX; and on every step of every example, in every notation, no letter
// of the notes' own left where the notation has another.
#include "test_registry.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/scene_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/present/localized_document.hpp"
#include "core/present/step_formula_text.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_step_formula {

using namespace ll;
namespace present = ll::present;
using present::Language;
using present::Notation;

namespace {

std::string text(const StepFormula& f, Notation notation, bool robot, Language language = Language::English) {
    return present::formulaText(f, {language, notation, robot});
}
std::string latex(const StepFormula& f, Notation notation, bool robot, Language language = Language::English) {
    return present::formulaLatex(f, {language, notation, robot});
}

const StepFormula motion = stepFormula("«B» «q''» + C «q'» + «g» = «Q»", R"(«B»«q''» + C«q'» + «g» = «Q»)");

}  // namespace

// Every example that loads (massless_joint is refused by design) with its file name.
std::vector<std::pair<std::string, Scene>> examples() {
    std::vector<std::pair<std::string, Scene>> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR)) {
        if (e.path().extension() != ".json") continue;
        try {
            Scene scene = loadScene(e.path().string()).scene;
            if (scene.dof() > 0) out.emplace_back(e.path().filename().string(), std::move(scene));
        } catch (const InputError&) {
        }
    }
    return out;
}

class TestStepFormula : public QObject {
    Q_OBJECT
private slots:
    void marksAreTypedLetters() {
        const FormulaPieces p = formulaPieces("«g» = d«q'_»k «1»", {formulaWords(MessageId::FormulaNonConservativeOnly)});
        QCOMPARE(p.size(), std::size_t(5));
        QVERIFY(p[0].kind == FormulaPiece::Kind::Letter && p[0].letter == FormulaLetter::Gravity);
        QCOMPARE(p[1].math, std::string(" = d"));
        QVERIFY(p[2].kind == FormulaPiece::Kind::Letter && p[2].letter == FormulaLetter::JointVariable && p[2].dots == 1);
        QCOMPARE(p[3].math, std::string("k "));
        QVERIFY(p[4].kind == FormulaPiece::Kind::Words && p[4].words == MessageId::FormulaNonConservativeOnly);
        QVERIFY_THROWS_EXCEPTION(std::logic_error, formulaPieces("«x» = 1"));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, formulaPieces("«2»", {formulaMath("one insert")}));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, formulaPieces("«B = 1"));
    }

    // The equations of motion as each textbook prints them.
    void eachNotationsLetters() {
        QCOMPARE(latex(motion, Notation::Notes, true), std::string(R"(B\ddot{q} + C\dot{q} + g = Q)"));
        QCOMPARE(latex(motion, Notation::Siciliano, true), std::string(R"(B\ddot{q} + C\dot{q} + g = \tau)"));
        QCOMPARE(latex(motion, Notation::Spong, true), std::string(R"(D\ddot{q} + C\dot{q} + g = \tau)"));
        QCOMPARE(latex(motion, Notation::Craig, true), std::string(R"(M\ddot{\Theta} + C\dot{\Theta} + G = \tau)"));
        // the text in the entries' alphabet: dots and Greek as characters, never qd or theta
        QCOMPARE(text(motion, Notation::Craig, true), std::string("M Θ\u0308 + C Θ\u0307 + G = τ"));
        QCOMPARE(text(motion, Notation::Notes, true), std::string("B q\u0308 + C q\u0307 + g = Q"));
        // a typed Lagrangian's coordinates are its own: only the matrices' letters change
        QCOMPARE(latex(motion, Notation::Craig, false), std::string(R"(M\ddot{q} + C\dot{q} + G = \tau)"));
        // a joint variable keeps its index
        const StepFormula joint = stepFormula("∂«q_»k «q'_»k", R"(\partial «q_»k «q'_»k)");
        QCOMPARE(text(joint, Notation::Craig, true), std::string("∂θ_k θ\u0307_k"));
        QCOMPARE(latex(joint, Notation::Craig, true), std::string(R"(\partial \theta_k \dot{\theta}_k)"));
    }

    // Words in the reader's language; in LaTeX the words in text mode, the math between
    // them, a space where the words have one.
    void wordsAroundMath() {
        const StepFormula rotor = stepFormula("«1»", "«1»", {formulaWords(MessageId::FormulaRotorTurnsAt, {"j", "G_j «q'_»j"})},
                                              {formulaWords(MessageId::FormulaRotorTurnsAt, {"j", "G_j «q'_»j"})});
        QCOMPARE(latex(rotor, Notation::Notes, true), std::string(R"(\text{(rotor } j \text{ turns at } G_j \dot{q}_j\text{)})"));
        QCOMPARE(latex(rotor, Notation::Craig, true, Language::Danish),
                 std::string(R"(\text{(rotor } j \text{ drejer med } G_j \dot{\theta}_j\text{)})"));
        QCOMPARE(text(rotor, Notation::Notes, true, Language::Danish), std::string("(rotor j drejer med G_j q\u0307_j)"));
        const StepFormula row =
            stepFormula("«1»:", "«1»:", {formulaWords(MessageId::FormulaDhRow, {"i"})}, {formulaWords(MessageId::FormulaDhRow, {"i"})});
        QCOMPARE(latex(row, Notation::Notes, true), std::string(R"(\text{row } i:)"));
        QCOMPARE(text(row, Notation::Notes, true, Language::Danish), std::string("række i:"));
    }

    // Every step of every example, in each notation: the formula's letters are the
    // notation's (a robot's joint variables too), none of the notes' own left over.
    void everyStepInEveryNotation() {
        int formulas = 0;
        for (const auto& [e, scene] : examples()) {
            const auto derived = deriveDisplay(scene, DocumentRequest{}, DerivationForm::Auto);
            QVERIFY(derived.display);
            for (Notation notation : {Notation::Spong, Notation::Craig}) {
                const auto shown = present::localizedDocument(*derived.display, {Language::English, notation});
                for (const present::DisplayStep& step : shown->steps) {
                    const std::string where = e + " step " + std::to_string(step.number) + ": ";
                    ++formulas;
                    for (const char* notes : {"B(", "B\\ddot", "B^{-1}", "b_{", "B_{\\mathrm{links}}", "= Q"})
                        QVERIFY2(step.formulaLatex.find(notes) == std::string::npos, (where + step.formulaLatex).c_str());
                    for (const char* notes : {"B(", "B^-1", "B⁻¹", "b_ij", "b_jj", "= Q", "B_links"})
                        QVERIFY2(step.formulaText.find(notes) == std::string::npos, (where + step.formulaText).c_str());
                    if (notation == Notation::Craig && shown->robot) {
                        for (const char* q : {"\\dot{q}", "\\ddot{q}", "\\partial q"})
                            QVERIFY2(step.formulaLatex.find(q) == std::string::npos, (where + step.formulaLatex).c_str());
                        for (const char* q : {" qd", "/dq", "qdd"})
                            QVERIFY2(step.formulaText.find(q) == std::string::npos, (where + step.formulaText).c_str());
                    }
                }
            }
        }
        QVERIFY(formulas > 300);
    }

    // One alphabet per page (issue 51): the text format's general formulas are written in
    // the entries' Unicode (α_i, θ_i, ω_i, Σ, ½, q̇, ∂²E_kin/(∂q̇_i ∂q̇_j)), in every
    // example, both forms, every notation and both languages; no ASCII spelling left.
    void formulasInTheEntriesAlphabet() {
        int formulas = 0;
        for (const auto& [e, scene] : examples()) {
            std::vector<DerivationForm> forms{DerivationForm::Auto};
            if (!scene.lagrangian) forms.push_back(DerivationForm::Structured);
            for (DerivationForm form : forms) {
                const auto derived = deriveDisplay(scene, DocumentRequest{}, form);
                for (Language language : {Language::English, Language::Danish})
                    for (Notation notation : {Notation::Notes, Notation::Siciliano, Notation::Spong, Notation::Craig}) {
                        const auto shown = present::localizedDocument(*derived.display, {language, notation});
                        for (const present::DisplayStep& step : shown->steps) {
                            ++formulas;
                            const std::string where = e + " step " + std::to_string(step.number) + ": ";
                            for (const char* ascii : {"alpha", "theta", "omega", "gamma_", "beta_", "sum_", "qd", "d^2", "^T", "1/2", "Bdot",
                                                      "<=", ">=", "^-1", "Theta", "tau"})
                                QVERIFY2(step.formulaText.find(ascii) == std::string::npos, (where + step.formulaText).c_str());
                        }
                    }
            }
        }
        QVERIFY(formulas > 500);
    }
};

LL_TEST_APPLESS_MAIN(TestStepFormula)

}  // namespace test_step_formula
#include "test_step_formula.moc"
