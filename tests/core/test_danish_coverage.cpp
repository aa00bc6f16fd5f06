// Every title and heading a derivation shows has its Danish (issue 46): the step titles,
// the form's name, the structured form's sections and the fixed actuation sentence of
// every example and hard scene, in both forms where a robot has both. A step or heading
// added to the core without its Danish entry in core/present/language.cpp fails here,
// naming it. (The window's strings are checked by tests/ui/test_danish_window against
// the Qt catalogue.)
#include "test_registry.hpp"

#include <filesystem>
#include <set>
#include <string>

#include "core/io/scene_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/present/language.hpp"
#include "core/present/localized_document.hpp"

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

// The headings of `document` a reader meets, English as derived.
std::set<std::string> headings(const present::DisplayDocument& document) {
    std::set<std::string> out;
    for (const present::DisplayStep& step : document.steps) out.insert(step.title);
    if (!document.form.empty()) out.insert(document.form);
    if (!document.actuationFromInputs && !document.actuation.empty()) out.insert(document.actuation);
    return out;
}

}  // namespace

class TestDanishCoverage : public QObject {
    Q_OBJECT
private slots:
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
                for (const std::string& english : headings(*derived.display)) {
                    seen.insert(english);
                    if (present::translated(english, present::Language::Danish) == english) missing.insert(english);
                }
                // and the Danish document shows them so
                const auto danish = present::localizedDocument(*derived.display, {present::Language::Danish, present::Notation::Notes});
                QCOMPARE(danish->steps.size(), derived.display->steps.size());
                for (std::size_t i = 0; i < danish->steps.size(); ++i)
                    QCOMPARE(danish->steps[i].title, present::translated(derived.display->steps[i].title, present::Language::Danish));
            }
        }
        QVERIFY(documents >= 20);
        QVERIFY(seen.size() >= 12);
        std::string list;
        for (const std::string& m : missing) list += "\n  " + m;
        QVERIFY2(missing.empty(), ("headings without Danish (core/present/language.cpp):" + list).c_str());
    }

    // The check itself: a title the table does not know is reported.
    void anUnknownTitleIsMissing() {
        QCOMPARE(present::translated("Step 10: a title nobody translated", present::Language::Danish),
                 std::string("Step 10: a title nobody translated"));
        QVERIFY(present::translated("Kinematic model", present::Language::Danish) != "Kinematic model");
    }
};

LL_TEST_APPLESS_MAIN(TestDanishCoverage)

}  // namespace test_danish_coverage
#include "test_danish_coverage.moc"
