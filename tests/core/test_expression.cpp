// ParameterTable: numeric fields written as expressions of named parameters.
#include "test_registry.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/symbolic/expression.hpp"
#include "core/model/diagnostics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_expression {

using namespace ll;

namespace {

// The message of the InputError `evaluate` throws (fails the test if none).
template <class Call>
std::string errorOf(Call call, bool& thrown, std::string& field) {
    thrown = false;
    try {
        call();
    } catch (const InputError& e) {
        thrown = true;
        if (e.diagnostics().size() != 1) return "expected one diagnostic";
        field = e.diagnostics().front().field;
        return e.diagnostics().front().message.english();
    }
    return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

#define EXPECT_INPUT_ERROR(call, expectedField, ...)                                                                           \
    do {                                                                                                                       \
        bool thrown_ = false;                                                                                                  \
        std::string field_;                                                                                                    \
        const std::string message_ = errorOf([&] { (void)(call); }, thrown_, field_);                                          \
        QVERIFY2(thrown_, "no InputError");                                                                                    \
        QCOMPARE(field_, std::string(expectedField));                                                                          \
        for (const char* part : {__VA_ARGS__}) QVERIFY2(contains(message_, part), (message_ + "  -- lacks: " + part).c_str()); \
    } while (false)

class TestExpression : public QObject {
    Q_OBJECT

private slots:
    void numbers() {
        ParameterTable table;
        QCOMPARE(table.evaluate("f", "2.5"), 2.5);
        QCOMPARE(table.evaluate("f", "-3"), -3.0);
        QCOMPARE(table.evaluate("f", "1/4"), 0.25);
        QCOMPARE(table.evaluate("f", "2^10"), 1024.0);
        QCOMPARE(table.evaluate("f", "1e-3"), 1e-3);
        QCOMPARE(table.evaluate("f", " 0.1 "), 0.1);
        QCOMPARE(table.evaluate("f", "sqrt(4)"), 2.0);
    }

    void parameters() {
        ParameterTable table;
        table.define("parameters.l1", "l1", 1.0);
        table.define("parameters.m2", "m2", 3.0);
        table.define("parameters.l2", "l2", 0.8);
        QCOMPARE(table.evaluate("f", "l1/2"), 0.5);
        QCOMPARE(table.evaluate("f", "m2*l2^2/12"), 3.0 * 0.8 * 0.8 / 12.0);
        QCOMPARE(table.evaluate("f", "-l1+l2"), -1.0 + 0.8);
        QVERIFY(table.contains("m2"));
        QVERIFY(!table.contains("m1"));
        QCOMPARE(table.names(), (std::vector<std::string>{"l1", "m2", "l2"}));
        QCOMPARE(table.value("l2"), 0.8);
    }

    void nestedParameters() {
        ParameterTable table;
        table.define("parameters.l1", "l1", 1.2);
        QCOMPARE(table.define("parameters.lc1", "lc1", std::string("l1/2")), 0.6);
        QCOMPARE(table.define("parameters.lc2", "lc2", std::string("lc1 + l1")), 1.8);
        QCOMPARE(table.evaluate("f", "lc2 - lc1"), 1.2);
        // The definition keeps the earlier symbol: lc1 = l1/2 symbolically.
        const GiNaC::ex definition = table.definition("lc1");
        QVERIFY(definition.has(table.symbol("l1")));
        QVERIFY((definition - table.symbol("l1") / 2).is_zero());
        // Only earlier parameters are visible.
        EXPECT_INPUT_ERROR(table.define("parameters.x", "x", std::string("y + 1")), "parameters.x", "unknown symbol 'y'");
    }

    void symbolsAreKept() {
        ParameterTable table;
        table.define("parameters.m1", "m1", 2.0);
        table.define("parameters.l1", "l1", 0.5);
        const GiNaC::ex e = table.parse("robot.joints[0].inertia.zz", "m1*l1^2/12");
        const GiNaC::ex expected = table.symbol("m1") * GiNaC::pow(table.symbol("l1"), 2) / 12;
        QVERIFY((e - expected).expand().is_zero());
        QCOMPARE(GiNaC::ex_to<GiNaC::numeric>(e.subs(table.values()).evalf()).to_double(), 2.0 * 0.25 / 12.0);
    }

    void pi() {
        ParameterTable table;
        QCOMPARE(table.evaluate("f", "pi"), std::numbers::pi);
        QCOMPARE(table.evaluate("f", "Pi"), std::numbers::pi);
        QCOMPARE(table.evaluate("f", "pi/2"), std::numbers::pi / 2);
        QCOMPARE(table.evaluate("f", "-pi/2"), -std::numbers::pi / 2);
        QVERIFY(std::abs(table.evaluate("f", "sin(pi/6)") - 0.5) < 1e-15);
        QVERIFY(table.parse("f", "pi").is_equal(GiNaC::Pi));
    }

    void unknownSymbol() {
        ParameterTable table;
        table.define("parameters.l1", "l1", 1.0);
        EXPECT_INPUT_ERROR(table.evaluate("robot.joints[1].a", "l3/2"), "robot.joints[1].a", "unknown symbol 'l3'", "at position 1",
                           "\"l3/2\"", "l1");
        EXPECT_INPUT_ERROR(table.evaluate("robot.joints[1].a", "l1 + 2*l3"), "robot.joints[1].a", "unknown symbol 'l3'", "at position 8");
        // A known name inside an unknown one is not mistaken for it.
        EXPECT_INPUT_ERROR(table.evaluate("f", "l1*xl1"), "f", "unknown symbol 'xl1'", "at position 4");
        EXPECT_INPUT_ERROR(table.evaluate("f", "foo(2)"), "f", "unknown function 'foo'", "at position 1");
    }

    void syntaxError() {
        ParameterTable table;
        table.define("parameters.l1", "l1", 1.0);
        EXPECT_INPUT_ERROR(table.evaluate("robot.joints[0].d", "l1*/2"), "robot.joints[0].d", "syntax error", "at position 4", "\"l1*/2\"");
        EXPECT_INPUT_ERROR(table.evaluate("f", "2**3"), "f", "syntax error", "at position 3");
        EXPECT_INPUT_ERROR(table.evaluate("f", "l1 l1"), "f", "syntax error", "at position 4");
        EXPECT_INPUT_ERROR(table.evaluate("f", "(l1 + 1"), "f", "syntax error at the end", "expected ')'");
        EXPECT_INPUT_ERROR(table.evaluate("f", "3 +"), "f", "syntax error at the end");
        EXPECT_INPUT_ERROR(table.evaluate("f", "2.5.3"), "f", "syntax error", "malformed number");
        EXPECT_INPUT_ERROR(table.evaluate("f", " "), "f", "empty expression");
    }

    void divisionByZero() {
        ParameterTable table;
        table.define("parameters.l1", "l1", 1.0);
        table.define("parameters.l2", "l2", 1.0);
        // Zero symbolically (GiNaC simplifies while parsing) ...
        EXPECT_INPUT_ERROR(table.evaluate("robot.joints[0].mass", "1/(l1-l1)"), "robot.joints[0].mass", "division by zero",
                           "\"1/(l1-l1)\"");
        // ... and only numerically.
        EXPECT_INPUT_ERROR(table.evaluate("f", "1/(l1-l2)"), "f", "division by zero", "\"1/(l1-l2)\"");
        EXPECT_INPUT_ERROR(table.evaluate("f", "log(0)"), "f", "\"log(0)\"");
    }

    void nonFiniteOrComplex() {
        ParameterTable table;
        EXPECT_INPUT_ERROR(table.evaluate("simulation.dt", "1e400"), "simulation.dt", "value is not finite (inf)", "\"1e400\"");
        EXPECT_INPUT_ERROR(table.evaluate("f", "-10^400"), "f", "value is not finite (-inf)");
        EXPECT_INPUT_ERROR(table.evaluate("f", "sqrt(-1)"), "f", "not a real number");
        EXPECT_INPUT_ERROR(table.define("parameters.big", "big", std::numeric_limits<double>::infinity()), "parameters.big", "not finite");
        // With double-valued parameters CLN computes in doubles: overflow is an error,
        // underflow gives 0 as in C++.
        table.define("parameters.huge", "huge", 1e300);
        table.define("parameters.tiny", "tiny", 1e-300);
        EXPECT_INPUT_ERROR(table.evaluate("f", "huge*huge"), "f", "not finite");
        QCOMPARE(table.evaluate("f", "tiny*tiny"), 0.0);
        QCOMPARE(table.evaluate("f", "huge/1e300"), 1.0);
    }

    void reservedAndDuplicateNames() {
        ParameterTable table;
        table.define("parameters.l1", "l1", 1.0);
        EXPECT_INPUT_ERROR(table.define("parameters.l1", "l1", 2.0), "parameters.l1", "defined twice");
        for (const char* name : {"pi", "Pi", "I", "t", "q1", "qd2", "qdd10", "sin", "cos", "sqrt", "exp"})
            EXPECT_INPUT_ERROR(table.define(std::string("parameters.") + name, name, 1.0), std::string("parameters.") + name, "reserved");
        EXPECT_INPUT_ERROR(table.define("parameters.2x", "2x", 1.0), "parameters.2x", "not a name");
        EXPECT_INPUT_ERROR(table.define("parameters.a b", "a b", 1.0), "parameters.a b", "not a name");
        // Names that merely look like reserved ones are fine.
        table.define("parameters.q", "q", 1.0);
        table.define("parameters.qa1", "qa1", 1.0);
        table.define("parameters.time", "time", 1.0);
        table.define("parameters.m_1", "m_1", 1.0);
        QCOMPARE(table.evaluate("f", "q + qa1 + time + m_1"), 4.0);
        QCOMPARE(table.value("l1"), 1.0);  // the refused redefinition changed nothing
    }

    void tableFromScene() {
        Scene scene;
        scene.parameters = {{"l1", 2.0}, {"lc1", 1.0}};
        scene.expressions["parameters.lc1"] = "l1/2";
        const ParameterTable table = parameterTable(scene);
        QCOMPARE(table.value("lc1"), 1.0);
        QVERIFY((table.definition("lc1") - table.symbol("l1") / 2).is_zero());
        QVERIFY(GiNaC::is_a<GiNaC::numeric>(table.definition("l1")));
    }
};

LL_TEST_APPLESS_MAIN(TestExpression)

}  // namespace test_expression
#include "test_expression.moc"
