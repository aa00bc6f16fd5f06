// CompiledExpressions against GiNaC's own evalf on random expressions, the sharing of
// common subexpressions and constant folding (counted instructions), the errors, and
// the speed that is the point of it (measured, printed, and required to be large).
#include "test_registry.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "core/symbolic/compiled_expressions.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_compiled_expressions {

using namespace ll::symbolic;
using GiNaC::ex;
using ll::ExpressionTape;

namespace {

// Random expression trees over `symbols`, kept real and finite wherever evaluated:
// logarithms, roots and real powers see positive arguments, tan a bounded one.
class RandomExpressions {
public:
    RandomExpressions(std::vector<GiNaC::symbol> symbols, unsigned seed) : symbols_(std::move(symbols)), rng_(seed) {}

    ex make(int depth) {
        try {
            return tree(depth);
        } catch (const GiNaC::pole_error&) {  // 0^-2 when a subtree cancelled to 0
            return number();
        }
    }

    ex tree(int depth) {
        std::uniform_int_distribution<int> pick(0, depth <= 0 ? 1 : 17);
        switch (pick(rng_)) {
            case 0: return symbols_[std::uniform_int_distribution<std::size_t>(0, symbols_.size() - 1)(rng_)];
            case 1: return number();
            case 2:
            case 3: return make(depth - 1) + make(depth - 1);
            case 4: return make(depth - 1) - number() * make(depth - 1);
            case 5:
            case 6: return make(depth - 1) * make(depth - 1);
            case 7: return GiNaC::pow(make(depth - 1), std::uniform_int_distribution<int>(-3, 5)(rng_)) + 0;
            case 8: return make(depth - 1) / (GiNaC::pow(make(depth - 1), 2) + GiNaC::numeric(1, 2));
            case 9: return GiNaC::sin(make(depth - 1));
            case 10: return GiNaC::cos(make(depth - 1));
            case 11: return GiNaC::tan(GiNaC::tanh(make(depth - 1)));
            case 12: return GiNaC::exp(GiNaC::tanh(make(depth - 1)));
            case 13: return GiNaC::log(GiNaC::pow(make(depth - 1), 2) + 1);
            case 14: return GiNaC::sqrt(GiNaC::pow(make(depth - 1), 2) + GiNaC::numeric(1, 3));
            case 15: return GiNaC::pow(GiNaC::pow(make(depth - 1), 2) + 1, GiNaC::numeric(7, 10) + 0.05);
            case 16: return GiNaC::abs(make(depth - 1)) + GiNaC::step(make(depth - 1));
            default: return GiNaC::Pi * make(depth - 1) + GiNaC::atan(make(depth - 1));
        }
    }

    ex number() {
        std::uniform_int_distribution<int> n(1, 9), d(1, 7), sign(0, 1);
        return GiNaC::numeric(sign(rng_) ? n(rng_) : -n(rng_), d(rng_));
    }

private:
    std::vector<GiNaC::symbol> symbols_;
    std::mt19937 rng_;
};

double ginacValue(const ex& e, const std::vector<GiNaC::symbol>& symbols, const std::vector<double>& values) {
    GiNaC::exmap at;
    for (std::size_t i = 0; i < symbols.size(); ++i) at[symbols[i]] = values[i];
    const ex v = e.subs(at).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v)) return std::nan("");
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

}  // namespace

class TestCompiledExpressions : public QObject {
    Q_OBJECT
private slots:
    void agreesWithGinacOnRandomExpressions() {
        const GiNaC::symbol x("x"), y("y"), z("z");
        const std::vector<GiNaC::symbol> inputs{x, y, z};
        RandomExpressions random(inputs, 2024);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-2.0, 2.0);
        int compared = 0;
        for (int k = 0; k < 300; ++k) {
            std::vector<ex> outputs;
            for (int j = 0; j < 4; ++j) outputs.push_back(random.make(5));
            const ExpressionTape compiled = compileExpressions(outputs, inputs);
            std::vector<double> out(outputs.size());
            for (int s = 0; s < 5; ++s) {
                const std::vector<double> at{u(rng), u(rng), u(rng)};
                compiled.evaluate(at.data(), out.data());
                for (std::size_t j = 0; j < outputs.size(); ++j) {
                    const double expected = ginacValue(outputs[j], inputs, at);
                    if (!std::isfinite(expected) || std::abs(expected) > 1e12) continue;  // a pole hit by chance
                    // Ill-conditioned here (cos of 1e16): a relative nudge of 1e-14 to the
                    // inputs changes the value, so no double evaluation can agree.
                    const std::vector<double> nudged{at[0] * (1 + 1e-14), at[1] * (1 - 1e-14), at[2] * (1 + 1e-14)};
                    if (std::abs(ginacValue(outputs[j], inputs, nudged) - expected) > 1e-11 * std::max(1.0, std::abs(expected))) continue;
                    ++compared;
                    const double error = std::abs(out[j] - expected) / std::max(1.0, std::abs(expected));
                    QVERIFY2(error < 1e-10, qPrintable(QString("%1 at (%2, %3, %4): compiled %5, GiNaC %6")
                                                           .arg(QString::fromStdString([&] {
                                                               std::ostringstream s;
                                                               s << outputs[j];
                                                               return s.str();
                                                           }()))
                                                           .arg(at[0])
                                                           .arg(at[1])
                                                           .arg(at[2])
                                                           .arg(out[j], 0, 'g', 17)
                                                           .arg(expected, 0, 'g', 17)));
                }
            }
        }
        QVERIFY(compared > 5000);
    }

    void sharesCommonSubexpressions() {
        const GiNaC::symbol x("x"), y("y");
        // x + y, sin, cos, the product, + 1: five instructions for both outputs.
        const ex s = GiNaC::sin(x + y);
        const ExpressionTape c = compileExpressions({s * GiNaC::cos(x + y), s + 1}, {x, y});
        QCOMPARE(c.instructionCount(), 5);
        // Equal subtrees built separately are one computation too.
        const ExpressionTape d = compileExpressions({GiNaC::exp(x * y) + GiNaC::exp(y * x), GiNaC::exp(x * y) * 3}, {x, y});
        QVERIFY(d.instructionCount() <= 5);
        // x^8 by squaring: three instructions; x^-8 one more.
        QCOMPARE(compileExpressions({GiNaC::pow(x, 8)}, {x}).instructionCount(), 3);
        QCOMPARE(compileExpressions({GiNaC::pow(x, -8)}, {x}).instructionCount(), 4);
        double in = 1.5, out = 0;
        compileExpressions({GiNaC::pow(x, -8)}, {x}).evaluate(&in, &out);
        QCOMPARE(out, std::pow(1.5, -8));
    }

    void foldsConstants() {
        const GiNaC::symbol x("x");
        // sin(π/7) · √2 is computed once, at compile time: one multiplication is left.
        const ExpressionTape c = compileExpressions({GiNaC::sin(GiNaC::Pi / 7) * GiNaC::sqrt(ex(2)) * x}, {x});
        QCOMPARE(c.instructionCount(), 1);
        double in = 2.0, out = 0;
        c.evaluate(&in, &out);
        QVERIFY(std::abs(out - std::sin(std::numbers::pi / 7) * std::sqrt(2.0) * 2.0) < 1e-15);
        // A constant output needs no instruction at all.
        const ExpressionTape k = compileExpressions({GiNaC::cos(ex(1)) + 2}, {x});
        QCOMPARE(k.instructionCount(), 0);
        k.evaluate(&in, &out);
        QCOMPARE(out, std::cos(1.0) + 2);
    }

    void stepAndAbsAsGinac() {
        const GiNaC::symbol x("x");
        const ExpressionTape c = compileExpressions({GiNaC::step(x), GiNaC::abs(x), GiNaC::step(x - 1) * x}, {x});
        for (double v : {-1.0, 0.0, 0.5, 1.0, 2.0}) {
            double out[3];
            c.evaluate(&v, out);
            QCOMPARE(out[0], ginacValue(GiNaC::step(x), {x}, {v}));
            QCOMPARE(out[1], std::abs(v));
            QCOMPARE(out[2], ginacValue(GiNaC::step(x - 1) * x, {x}, {v}));
        }
    }

    void refusesWhatItCannotCompile() {
        const GiNaC::symbol x("x"), stranger("k");
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, compileExpressions({x * stranger}, {x}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, compileExpressions({GiNaC::zeta(x)}, {x}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, compileExpressions({x + GiNaC::I}, {x}));
    }

    // The reason it exists: a double-pendulum-sized set of outputs, compiled vs GiNaC.
    void fasterThanGinacByOrdersOfMagnitude() {
        const GiNaC::symbol a("a"), b("b"), ad("ad"), bd("bd");
        const ex c = GiNaC::cos(a - b), s = GiNaC::sin(a - b);
        const std::vector<ex>
            outputs{3 + 2 * c, 1 + c, 2, -s * bd * (2 * ad + bd), s * ad * ad, 20 * GiNaC::sin(a) + 10 * GiNaC::sin(b), 10 * GiNaC::sin(b)};
        const std::vector<GiNaC::symbol> inputs{a, b, ad, bd};
        const ExpressionTape compiled = compileExpressions(outputs, inputs);
        std::vector<double> in{0.3, -0.2, 1.0, 0.5}, out(outputs.size());
        const auto seconds = [](auto&& f, int times) {
            const auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < times; ++i) f(i);
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / times;
        };
        double sink = 0;
        const double tape = seconds(
            [&](int i) {
                in[0] = 1e-6 * i;
                compiled.evaluate(in.data(), out.data());
                sink += out[0];
            },
            200000);
        const double ginac = seconds(
            [&](int i) {
                in[0] = 1e-6 * i;
                for (const ex& e : outputs) sink += ginacValue(e, inputs, in);
            },
            300);
        qInfo("%d outputs, %d instructions: compiled %.3g us, GiNaC subs+evalf %.3g us per evaluation (%.0fx) [%g]", int(outputs.size()),
              compiled.instructionCount(), 1e6 * tape, 1e6 * ginac, ginac / tape, sink * 0);
        QVERIFY(ginac > 100 * tape);
    }
};

LL_TEST_APPLESS_MAIN(TestCompiledExpressions)

}  // namespace test_compiled_expressions
#include "test_compiled_expressions.moc"
