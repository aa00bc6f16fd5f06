// Every input under tests/fuzz/regressions/<target>/ through the same body its libFuzzer
// target runs (tests/fuzz/fuzz_*.cpp): what a fuzzer once found stays fixed. The first
// files are issue 13's defects: a subnormal parameter (CLN threw "floating point
// underflow", not InputError), a spring rest at 1e300 (E_pot = inf passed the checks), a
// subnormal typed in an expression, and a potential that overflows at the initial state;
// then what `scripts/lab fuzz` found: "sin()" (a crash) and "4e55555555555" (a hang), and
// its computed cousins found by hand, "10^(10^10)", "((9^999)^999)^999" and
// "factorial(10^8)" (hangs), an empty key and "tau*sin(I)" (each refused naming no
// field).
#include "test_registry.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/io/scene_file.hpp"
#include "core/symbolic/expression.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "fuzz/fuzz_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_fuzz_regressions {

// The one line `text` is refused with in a DH cell (empty when it is accepted).
QString refusal(const ll::ParameterTable& table, const char* text) {
    try {
        (void)table.evaluate("robot.joints[-1].a", text, ll::AngleUnits::Refused);
    } catch (const ll::InputError& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

class TestFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void everyReproducerPasses() {
        const std::map<std::string, int (*)(const std::uint8_t*, std::size_t)> bodies = {{"sceneLoader", ll::fuzz::sceneLoader},
                                                                                         {"expression", ll::fuzz::expression},
                                                                                         {"lagrangian", ll::fuzz::lagrangian},
                                                                                         {"evalState", ll::fuzz::evalState},
                                                                                         {"answer", ll::fuzz::answer},
                                                                                         {"urdf", ll::fuzz::urdf}};
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

    // An empty key ("": …, found by fuzz_scene_loader after this stop's corpus grew) was
    // reported with an empty field (": unknown key"); it is named as typed, "", at the top
    // and inside an object.
    void anEmptyKeyIsNamed() {
        std::ifstream in(LL_SOURCE_DIR "/tests/fuzz/regressions/sceneLoader/empty_key.json");
        std::ostringstream text;
        text << in.rdbuf();
        QStringList fields;
        try {
            (void)ll::parseScene(text.str());
        } catch (const ll::InputError& e) {
            for (const ll::Diagnostic& d : e.diagnostics()) {
                QVERIFY2(!d.field.empty(), d.message.english().c_str());
                fields << QString::fromStdString(d.field);
            }
        }
        QVERIFY2(fields.contains("\"\"") && fields.contains("lagrangian.\"\""), qPrintable(fields.join(" | ")));
    }

    // A function called with no argument ("sin()", found by fuzz_expression and
    // fuzz_lagrangian: GiNaC's parser crashed on it) is one line naming the field and
    // the function, whatever surrounds it.
    void emptyCallsAreRefused() {
        const auto lock = ll::symbolic::lockGinac();
        ll::ParameterTable table;
        table.define("parameters.m", "m", 2.0);
        for (const char* text : {"sin()", "2*cos( )", "m*exp(\t)+1", "3sin()"}) {
            const QString message = refusal(table, text);
            QVERIFY2(message.contains("robot.joints[-1].a") && message.contains("()' has no argument"),
                     qPrintable(text + (": " + message)));
        }
        for (const char* fine : {"sin(m)", "2*(m)", "cos(0)"}) (void)table.evaluate("robot.joints[-1].a", fine, ll::AngleUnits::Refused);
    }

    // A literal whose exponent is far beyond a double's ("4e55555555555", found by
    // fuzz_expression as a 36 s timeout: CLN computed the power of ten exactly) is one
    // line naming the field and the number; exponents a double holds still parse.
    void hugeExponentsAreRefused() {
        const auto lock = ll::symbolic::lockGinac();
        ll::ParameterTable table;
        for (const char* text : {"4e55555555555", "2*1e-9999", "1E+0401"}) {
            const QString message = refusal(table, text);
            QVERIFY2(message.contains("robot.joints[-1].a") && message.contains("exponent is beyond"), qPrintable(text + (": " + message)));
        }
        QCOMPARE(table.evaluate("robot.joints[-1].a", "1e308", ll::AngleUnits::Refused), 1e308);
        QCOMPARE(table.evaluate("robot.joints[-1].a", "2.5e-3", ll::AngleUnits::Refused), 2.5e-3);
    }

    // A computed exponent as large ("10^(10^10)", or a^n with the parameter n = 1e10; found
    // by hand after the fuzzer's literal: GiNaC computed the power exactly, for hours) is
    // one line naming the field and the exponent's value, before GiNaC computes anything.
    // Without the check each of these would not return.
    void computedHugeExponentsAreRefused() {
        const auto lock = ll::symbolic::lockGinac();
        ll::ParameterTable table;
        table.define("parameters.n", "n", 1e10);
        table.define("parameters.k", "k", 3.0);
        for (const char* text : {"10^(10^10)", "2^10000000000", "10^n", "(10^10)^(10^10)", "pow(10, 10^10)", "1 + 3^(-n)",
                                 "2^(2^(2^(2^(2^2))))", "k^(1000*k)"}) {
            const QString message = refusal(table, text);
            QVERIFY2(message.contains("robot.joints[-1].a") && message.contains("is beyond ±1000") && message.contains("exponent "),
                     qPrintable(text + (": " + message)));
        }
        QVERIFY2(refusal(table, "10^n").contains("exponent 1e+10 after the '^' at position 3"), qPrintable(refusal(table, "10^n")));
        // Each exponent within ±1000, but nested: ((9^999)^999)^999 has about 10^9 digits.
        for (const char* text :
             {"((9^999)^999)^999", "(9^999)^999", "pow(pow(9, 999), 999)", "(12345678901234567/1000)^999", "(10^300)^(999/2)"}) {
            const QString message = refusal(table, text);
            QVERIFY2(message.contains("robot.joints[-1].a") && message.contains("digits"), qPrintable(text + (": " + message)));
        }
        QVERIFY2(refusal(table, "(9^999)^999").contains("the power after the '^' at position 8") &&
                     refusal(table, "(9^999)^999").contains("about 9.524e+05 digits"),
                 qPrintable(refusal(table, "(9^999)^999")));
        QCOMPARE(table.evaluate("robot.joints[-1].a", "(9^999)^3/(9^999*9^999*9^999)", ll::AngleUnits::Refused),
                 1.0);  // 2,860 digits: fine
        // Every power's operands are read again alone: nested 3,000 deep (12 KB) that took
        // 1.8 s; such nesting is refused by the length of its operands, 200 deep still reads.
        std::string deep = "1", shallow = "1";
        for (int i = 0; i < 3000; ++i) deep = "(1^" + deep + ")";
        for (int i = 0; i < 200; ++i) shallow = "(1^" + shallow + ")";
        QVERIFY2(refusal(table, deep.c_str()).contains("are nested too deeply to check"),
                 qPrintable(refusal(table, deep.c_str()).left(200)));
        QCOMPARE(table.evaluate("robot.joints[-1].a", shallow, ll::AngleUnits::Refused), 1.0);
        // Exponents a scene uses still evaluate, to their closed values.
        QCOMPARE(table.evaluate("robot.joints[-1].a", "2^10", ll::AngleUnits::Refused), 1024.0);
        QCOMPARE(table.evaluate("robot.joints[-1].a", "k^(k-1)", ll::AngleUnits::Refused), 9.0);
        QCOMPARE(table.evaluate("robot.joints[-1].a", "pow(2, -k)", ll::AngleUnits::Refused), 0.125);
        QCOMPARE(table.evaluate("robot.joints[-1].a", "(1/2)^3*8", ll::AngleUnits::Refused), 1.0);
        QCOMPARE(table.evaluate("robot.joints[-1].a", "2^(2^(2^2))/65536", ll::AngleUnits::Refused), 1.0);
    }

    // The derivation expands what is typed: (θ1 + θ2 + 1)^1000 in a potential is half a
    // million terms (found by hand: `derive` ran past 20 s and 1.8 GB). The terms an
    // expression would expand to are counted on GiNaC's tree; beyond 10,000 it is refused
    // naming the field. Expansions a scene uses still parse, coordinates and all.
    void hugeExpansionsAreRefused() {
        const auto lock = ll::symbolic::lockGinac();
        ll::ParameterTable table;
        table.define("parameters.K", "K", 2.0);
        const GiNaC::symbol x("x"), y("y"), z("z");
        const auto refusedAs = [&](const char* text) {
            try {
                (void)table.parse("lagrangian.potential", text, {x, y, z});
            } catch (const ll::InputError& e) {
                return QString::fromStdString(e.what());
            }
            return QString();
        };
        for (const char* text : {"(x+y+1)^1000", "K*(x+y+z)^200/2", "sin((x-y+z)^300)", "(x+y)^100*(x+z)^100", "((x+y+z)^20)^10"}) {
            const QString message = refusedAs(text);
            QVERIFY2(message.contains("lagrangian.potential") && message.contains("terms (more than 10000"),
                     qPrintable(text + (": " + message)));
        }
        QVERIFY2(refusedAs("(x+y+1)^1000").contains("about 5.02e+05 terms"), qPrintable(refusedAs("(x+y+1)^1000")));  // C(1002, 2) = 501501
        for (const char* fine : {"K*(x-y)^2/2 + K*x^2/2", "(x+y)^1000", "(x+y+z)^100", "x^1000*y^1000", "(sin(x)+cos(y))^20"})
            QVERIFY2(refusedAs(fine).isEmpty(), qPrintable(fine + (": " + refusedAs(fine))));
    }

    // A Lagrangian's force "tau*sin(I)" (found by fuzz_lagrangian: GiNaC reads I as the
    // imaginary unit) could not be compiled and was refused naming no field ("cannot
    // compile the non-real number I"). A complex number in any expression is one line
    // naming the field; real constants (Euler, Catalan, pi) still read.
    void complexNumbersAreRefused() {
        const auto lock = ll::symbolic::lockGinac();
        ll::ParameterTable table;
        table.define("parameters.tau", "tau", 1.0);
        const GiNaC::symbol x("theta1");
        for (const char* text : {"tau*sin(I)", "sqrt(-1)*theta1", "log(-2)", "I"}) {
            QString message;
            try {
                (void)table.parse("lagrangian.forces[1]", text, {x});
            } catch (const ll::InputError& e) {
                message = QString::fromStdString(e.what());
            }
            QVERIFY2(message.contains("lagrangian.forces[1]") && message.contains("is not a real number"),
                     qPrintable(text + (": " + message)));
        }
        for (const char* fine : {"tau*sin(theta1)", "Euler*theta1 + Catalan", "sqrt(2)*pi", "asin(1/2)"})
            (void)table.parse("lagrangian.forces[1]", fine, {x});
        std::ifstream in(LL_SOURCE_DIR "/tests/fuzz/regressions/lagrangian/imaginary_unit");
        QVERIFY(in.good());
    }

    // GiNaC's parser knows functions that compute exactly and without end on a large
    // argument (factorial(10^8) ran for minutes, found by hand with the nested powers):
    // only the functions the simulation compiles (and pow) may be called; the others are
    // one line naming the field, the function and its position.
    void unavailableFunctionsAreRefused() {
        const auto lock = ll::symbolic::lockGinac();
        ll::ParameterTable table;
        table.define("parameters.m", "m", 2.0);
        for (const char* text : {"factorial(100000000)", "1 + tgamma(10^8)", "binomial(10^9, 10^8)", "zeta (100000)", "m*lgamma(m)",
                                 "Li2(m)", "EllipticK(m)", "EllipticE(m)"}) {
            const QString message = refusal(table, text);
            QVERIFY2(message.contains("robot.joints[-1].a") && message.contains("is not available (available: sin"),
                     qPrintable(text + (": " + message)));
        }
        QVERIFY2(refusal(table, "1 + tgamma(10^8)").contains("function 'tgamma' at position 5"),
                 qPrintable(refusal(table, "1 + tgamma(10^8)")));
        QCOMPARE(table.evaluate("robot.joints[-1].a", "sqrt(m^2)*abs(-1)+atan2(0, 1)+step(m)", ll::AngleUnits::Refused), 3.0);
        QCOMPARE(table.evaluate("robot.joints[-1].a", "cosh(0) + tanh(0) + exp(0) + log(1) + csgn(m)", ll::AngleUnits::Refused), 3.0);
    }
};

LL_TEST_APPLESS_MAIN(TestFuzzRegressions)

}  // namespace test_fuzz_regressions
#include "test_fuzz_regressions.moc"
