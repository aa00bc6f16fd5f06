// Every input under tests/fuzz/regressions/<target>/ through the same body its libFuzzer
// target runs (tests/fuzz/fuzz_*.cpp): what a fuzzer once found stays fixed. The first
// files are issue 13's defects: a subnormal parameter (CLN threw "floating point
// underflow", not InputError), a spring rest at 1e300 (E_pot = inf passed the checks), a
// subnormal typed in an expression, and a potential that overflows at the initial state.
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/io/scene_file.hpp"
#include "core/symbolic/expression.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "fuzz/fuzz_support.hpp"

class TestFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void everyReproducerPasses() {
        const std::map<std::string, int (*)(const std::uint8_t*, std::size_t)> bodies = {
            {"sceneLoader", ll::fuzz::sceneLoader},
            {"expression", ll::fuzz::expression},
            {"lagrangian", ll::fuzz::lagrangian},
            {"evalState", ll::fuzz::evalState}};
        int files = 0;
        for (const auto& folder : std::filesystem::directory_iterator(LL_SOURCE_DIR "/tests/fuzz/regressions")) {
            const auto body = bodies.find(folder.path().filename().string());
            QVERIFY2(body != bodies.end(), qPrintable("no fuzz target named " + QString::fromStdString(folder.path().string())));
            for (const auto& file : std::filesystem::directory_iterator(folder.path())) {
                std::ifstream in(file.path(), std::ios::binary);
                std::ostringstream bytes;
                bytes << in.rdbuf();
                const std::string input = bytes.str();
                try {
                    body->second(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
                } catch (const std::exception& e) {
                    QFAIL(qPrintable(QString::fromStdString(file.path().string() + ": " + e.what())));
                }
                ++files;
            }
        }
        QVERIFY(files >= 5);
    }

    // The body refuses what it must: the two defects are InputErrors naming the field now,
    // so a reproducer that still loads would mean the check went away.
    void theDefectsAreRefused() {
        std::ifstream in(LL_SOURCE_DIR "/tests/fuzz/regressions/sceneLoader/subnormal_parameter.json");
        std::ostringstream text;
        text << in.rdbuf();
        bool named = false;
        try {
            (void)ll::parseScene(text.str());
        } catch (const ll::InputError& e) {
            named = e.diagnostics().front().field == "parameters.I2";
        }
        QVERIFY(named);
    }

    // A function called with no argument ("sin()", found by fuzz_expression and
    // fuzz_lagrangian: GiNaC's parser crashed on it) is one line naming the field and
    // the function, whatever surrounds it.
    void emptyCallsAreRefused() {
        const auto lock = ll::symbolic::lockGinac();
        ll::ParameterTable table;
        table.define("parameters.m", "m", 2.0);
        for (const char* text : {"sin()", "2*cos( )", "m*exp(\t)+1", "3sin()"}) {
            QString message;
            try {
                (void)table.evaluate("robot.joints[0].a", text, ll::AngleUnits::Refused);
            } catch (const ll::InputError& e) {
                message = QString::fromStdString(e.what());
            }
            QVERIFY2(message.contains("robot.joints[0].a") && message.contains("()' has no argument"), qPrintable(text + (": " + message)));
        }
        for (const char* fine : {"sin(m)", "2*(m)", "cos(0)"}) (void)table.evaluate("robot.joints[0].a", fine, ll::AngleUnits::Refused);
    }
};

QTEST_APPLESS_MAIN(TestFuzzRegressions)
#include "test_fuzz_regressions.moc"
