// Every title and heading a derivation shows has its Danish (issue 46): the step titles,
// the form's name, the structured form's sections, the words inside the general formulas
// (core/model/messages/formula.def) and the fixed actuation sentence of every example and
// hard scene, in both forms where a robot has both. Each is a message
// id (core/model/messages/document.def) with Danish words (core/present/danish/document.def),
// never finished English: a step or heading added to the core as a string, or with an id
// whose Danish is missing, fails here, naming it; and the Danish documents show none of
// the English step titles. (The window's strings are checked by tests/ui/test_danish_window
// against the Qt catalogue.)
#include "test_registry.hpp"

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/io/scene_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/present/derivation_document.hpp"
#include "core/present/language.hpp"
#include "core/present/latex_text.hpp"
#include "core/present/localized_document.hpp"
#include "core/present/message_text.hpp"
#include "core/present/step_formula_text.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_danish_coverage {

using namespace ll;
namespace present = ll::present;

namespace {

// The scenes: every example and hard scene the loader accepts.
std::vector<std::string> scenes() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR))
        if (e.path().extension() == ".json") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

// The headings of `document` a reader meets, as derived.
std::vector<Message> headings(const present::DisplayDocument& document) {
    std::vector<Message> out;
    for (const present::DisplayStep& step : document.steps) out.push_back(step.title);
    if (!document.form.empty()) out.push_back(document.form);
    if (!document.actuationFromInputs && !document.actuation.empty())
        out.push_back(document.actuationNote.empty() ? literal(document.actuation) : document.actuationNote);
    return out;
}

// An id with Danish words of its own; a literal is English nobody translates.
bool hasDanish(const Message& m) {
    if (m.id == MessageId::Literal) return false;
    const char* danish = present::danishWords(m.id);
    return danish && *danish && std::string(danish) != englishWords(m.id);
}

std::string named(const Message& m) { return m.id == MessageId::Literal ? "\"" + m.literal + "\"" : messageIdName(m.id); }

// The step title ids: the ids the catalogue names Title* (document.def).
std::vector<MessageId> titleIds() {
    std::vector<MessageId> ids;
    for (int k = static_cast<int>(MessageId::Literal) + 1; k < static_cast<int>(MessageId::Count); ++k)
        if (std::string(messageIdName(static_cast<MessageId>(k))).starts_with("Title")) ids.push_back(static_cast<MessageId>(k));
    return ids;
}

// The words inside a formula's pieces (a word's arguments included), each as a piece.
void wordsIn(const FormulaPieces& pieces, std::vector<FormulaPiece>& out) {
    for (const FormulaPiece& p : pieces)
        if (p.kind == FormulaPiece::Kind::Words) {
            out.push_back(p);
            for (const FormulaPieces& a : p.args) wordsIn(a, out);
        }
}

}  // namespace

class TestDanishCoverage : public QObject {
    Q_OBJECT
private slots:
    void everyTitleIdHasDanish() {
        const std::vector<MessageId> ids = titleIds();
        QVERIFY(ids.size() >= 23);  // 13 steps of the notes and the pose, 5 + 5 of the structured form
        for (MessageId id : ids) QVERIFY2(hasDanish(id), messageIdName(id));
    }

    void everyHeadingHasDanish() {
        std::set<std::string> missing, seen;
        int documents = 0;
        for (const std::string& path : scenes()) {
            Scene scene;
            try {
                scene = loadScene(path).scene;
            } catch (const InputError&) {
                continue;  // refused by design (examples/hard/massless_joint.json)
            }
            std::vector<DerivationForm> forms{DerivationForm::Auto};
            if (!scene.lagrangian && scene.robot.dof() <= 3) forms.push_back(DerivationForm::Structured);
            for (DerivationForm form : forms) {
                const auto derived = deriveDisplay(scene, DocumentRequest{}, form);
                QVERIFY2(derived.display, path.c_str());
                ++documents;
                for (const Message& heading : headings(*derived.display)) {
                    seen.insert(named(heading));
                    if (!hasDanish(heading)) missing.insert(named(heading));
                }
                // and the Danish document shows them so, with no step title in English
                const auto danish = present::localizedDocument(*derived.display, {present::Language::Danish, present::Notation::Notes});
                QCOMPARE(danish->steps.size(), derived.display->steps.size());
                const std::string text = present::renderDocument(*danish, present::DocumentFormat::Text),
                                  latex = present::renderDocument(*danish, present::DocumentFormat::Latex);
                for (std::size_t i = 0; i < danish->steps.size(); ++i) {
                    const std::string title = present::messageText(danish->steps[i].title, present::Language::Danish);
                    QVERIFY2(text.find(title) != std::string::npos, (path + ": " + title).c_str());
                }
                // the words inside every general formula: Danish words of their own, and
                // not the English in the Danish formula
                for (std::size_t i = 0; i < danish->steps.size(); ++i) {
                    const present::DisplayStep& step = danish->steps[i];
                    std::vector<FormulaPiece> words;
                    wordsIn(step.general.text, words);
                    wordsIn(step.general.latex, words);
                    for (const FormulaPiece& w : words) {
                        seen.insert(messageIdName(w.words));
                        if (!hasDanish(Message(w.words))) missing.insert(messageIdName(w.words));
                        const std::string english =
                            present::formulaText({{w}, {}}, {present::Language::English, present::Notation::Notes, derived.display->robot});
                        QVERIFY2(step.formulaText.find(english) == std::string::npos &&
                                     step.formulaLatex.find(english) == std::string::npos,
                                 (path + ": " + english).c_str());
                    }
                }
                for (MessageId id : titleIds()) {
                    const std::string english = englishWords(id);
                    QVERIFY2(text.find(english) == std::string::npos, (path + ": " + english).c_str());
                    QVERIFY2(latex.find(present::latexText(english)) == std::string::npos, (path + ": " + english).c_str());
                }
                if (!derived.display->form.empty())
                    QVERIFY(text.find(": " + present::messageText(derived.display->form, present::Language::Danish) + " (") !=
                            std::string::npos);
                if (!derived.display->actuationFromInputs)
                    QCOMPARE(danish->actuation, present::messageText(derived.display->actuationNote, present::Language::Danish));
            }
        }
        QVERIFY(documents >= 20);
        QVERIFY(seen.size() >= 30);
        std::string list;
        for (const std::string& m : missing) list += "\n  " + m;
        QVERIFY2(missing.empty(), ("headings without Danish (core/present/danish/document.def):" + list).c_str());
    }

    // The check itself: a title given as finished English, or an id without Danish words
    // of its own, is reported.
    void anUntranslatedTitleIsMissing() {
        QVERIFY(!hasDanish(literal("Step 10: a title nobody translated")));
        QVERIFY(!hasDanish(literal("Kinematic model")));
        QVERIFY(hasDanish(MessageId::TitleKinematicModel));
        QCOMPARE(present::messageText(MessageId::TitleKinematicModel, present::Language::Danish), std::string("Kinematisk model"));
    }
};

LL_TEST_APPLESS_MAIN(TestDanishCoverage)

}  // namespace test_danish_coverage
#include "test_danish_coverage.moc"
