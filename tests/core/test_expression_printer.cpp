// expression_printer: golden strings for the planar 2R's B and C, every naming rule,
// Plain output that GiNaC parses back to the same value, and an order that does not
// depend on when GiNaC created the symbols.
#include "test_registry.hpp"

#include <complex>
#include <map>
#include <random>
#include <string>

#include "core/present/angle_sums.hpp"
#include "core/present/expression_printer.hpp"
#include "core/present/textbook_form.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_expression_printer {

using namespace ll::symbolic;
using namespace ll::present;
using GiNaC::ex;
using GiNaC::symbol;

#define COMPARE_STR(actual, expected) QCOMPARE(QString::fromStdString(actual), QString::fromStdString(expected))

namespace {

// Symbols by name, created on first use: the order of first use is the creation order.
struct Symbols {
    std::map<std::string, symbol> table;
    symbol operator()(const std::string& name) {
        auto it = table.find(name);
        if (it == table.end()) it = table.emplace(name, symbol(name)).first;
        return it->second;
    }
};

PrintOptions style(Style s) {
    PrintOptions o;
    o.style = s;
    o.coordinateNames = {"q1", "q2", "q3"};
    return o;
}

// The planar 2R (Siciliano §7.3.2) entries as the derivation leaves them: expanded.
struct Planar2R {
    ex b11, b12, b22, c11, c12, c21, c22, g1;
    std::vector<symbol> masses, velocities;
    explicit Planar2R(Symbols& s) {
        const ex I1 = s("I1"), I2 = s("I2"), m1 = s("m1"), m2 = s("m2"), a1 = s("a1"), lc1 = s("lc1"), lc2 = s("lc2"), c1 = s("c1"),
                 c2 = s("c2"), s1 = s("s1"), s2 = s("s2"), qd1 = s("qd1"), qd2 = s("qd2"), g = s("g");
        b11 = (I1 + m1 * pow(lc1, 2) + I2 + m2 * (pow(a1, 2) + pow(lc2, 2) + 2 * a1 * lc2 * c2)).expand();
        b12 = (I2 + m2 * (pow(lc2, 2) + a1 * lc2 * c2)).expand();
        b22 = (I2 + m2 * pow(lc2, 2)).expand();
        const ex h = -m2 * a1 * lc2 * s2;
        c11 = (h * qd2).expand();
        c12 = (h * (qd1 + qd2)).expand();
        c21 = (-h * qd1).expand();
        c22 = 0;
        g1 = ((m1 * lc1 + m2 * a1) * g * c1 + m2 * lc2 * g * (c1 * c2 - s1 * s2)).expand();
        masses = {s("m1"), s("m2")};
        velocities = {s("qd1"), s("qd2")};
    }
};

bool balancedBraces(const std::string& latex) {
    int depth = 0;
    for (std::size_t i = 0; i < latex.size(); ++i) {
        if (latex[i] == '\\' && i + 1 < latex.size() && (latex[i + 1] == '{' || latex[i + 1] == '}')) {
            ++i;
            continue;
        }
        depth += latex[i] == '{' ? 1 : latex[i] == '}' ? -1 : 0;
        if (depth < 0) return false;
    }
    int lr = 0;  // \left( ... \right) pairs
    for (std::size_t at = 0; (at = latex.find("\\left", at)) != std::string::npos; ++at) ++lr;
    for (std::size_t at = 0; (at = latex.find("\\right", at)) != std::string::npos; ++at) --lr;
    return depth == 0 && lr == 0;
}

// Random expressions over robot-like symbols; the same seed and names give the same
// expression whatever order the symbols were created in.
class RandomExpressions {
public:
    RandomExpressions(Symbols& s, unsigned seed) : s_(s), rng_(seed) {}

    ex next(int depth = 3) {
        std::uniform_int_distribution<int> pick(0, depth <= 0 ? 1 : 8);
        switch (pick(rng_)) {
            case 0: return leafSymbol();
            case 1: return number();
            case 2:
            case 3: {
                ex sum = 0;
                for (int k = uniform(2, 4); k > 0; --k) sum += next(depth - 1);
                return sum;
            }
            case 4:
            case 5: {
                ex product = 1;
                for (int k = uniform(2, 3); k > 0; --k) product *= next(depth - 1);
                return product;
            }
            case 6: {
                static const int powers[] = {-2, -1, 2, 3};
                const ex base = next(depth - 1);
                const int k = powers[uniform(0, 3)];
                return base.is_zero() ? base : pow(base, k);  // GiNaC throws on 0^-k
            }
            case 7: {  // a moderate argument: cos(1e15/x) would test the arithmetic, not us
                const ex arg = leafSymbol() + GiNaC::numeric(uniform(-9, 9), uniform(1, 4)) * leafSymbol();
                return uniform(0, 1) ? GiNaC::sin(arg) : GiNaC::cos(arg);
            }
            default:  // roots of something positive
                return uniform(0, 1) ? pow(pow(next(depth - 1), 2) + 1, GiNaC::numeric(1, 2)) : pow(s_("m2"), GiNaC::numeric(1, 3));
        }
    }

    int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

private:
    Symbols& s_;
    std::mt19937 rng_;

    ex leafSymbol() {
        static const char* names[] = {"a1",  "lc2", "m1", "m2", "Ixx1", "theta1", "theta1_dot", "q1", "q2",
                                      "qd1", "qd2", "c1", "s2", "c12",  "s123",   "g",          "tau"};
        return s_(names[uniform(0, 16)]);
    }
    ex number() {
        switch (uniform(0, 3)) {
            case 0: return uniform(-5, 5);
            case 1: return GiNaC::numeric(uniform(-7, 7), uniform(1, 6));
            case 2: return GiNaC::numeric(std::uniform_real_distribution<double>(-3, 3)(rng_));
            default: return GiNaC::numeric(std::uniform_real_distribution<double>(-1, 1)(rng_) * 1e-7);
        }
    }
};

// c/s symbols as the functions they stand for.
GiNaC::lst trigFunctions(Symbols& s) {
    const ex q1 = s("q1"), q2 = s("q2"), q3 = s("q3");
    return {s("c1") == GiNaC::cos(q1), s("s2") == GiNaC::sin(q2), s("c12") == GiNaC::cos(q1 + q2), s("s123") == GiNaC::sin(q1 + q2 + q3),
            s("c2") == GiNaC::cos(q2), s("s1") == GiNaC::sin(q1)};
}

std::complex<double> value(const ex& e, const GiNaC::lst& at) {
    const ex v = GiNaC::evalf(e.subs(at));
    if (!GiNaC::is_a<GiNaC::numeric>(v)) throw std::runtime_error("not a number: " + print(v, {Style::Plain, {}, true}));
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
    return {GiNaC::real(n).to_double(), GiNaC::imag(n).to_double()};
}

}  // namespace

class TestExpressionPrinter : public QObject {
    Q_OBJECT

private slots:
    void planar2RText() {
        Symbols s;
        const Planar2R r(s);
        const PrintOptions text = style(Style::Text);
        COMPARE_STR(print(collectForDisplay(r.b11, r.masses), text), "I1 + m1 ℓc1² + I2 + m2 (a1² + ℓc2² + 2 a1 ℓc2 c2)");
        COMPARE_STR(print(collectForDisplay(r.b12, r.masses), text), "I2 + m2 (ℓc2² + a1 ℓc2 c2)");
        COMPARE_STR(print(collectForDisplay(r.b22, r.masses), text), "I2 + m2 ℓc2²");
        COMPARE_STR(print(collectForDisplay(r.c11, r.velocities), text), "−m2 a1 ℓc2 s2 q̇2");
        COMPARE_STR(print(collectForDisplay(r.c12, r.velocities), text), "−m2 a1 ℓc2 s2 q̇1 − m2 a1 ℓc2 s2 q̇2");
        COMPARE_STR(print(collectForDisplay(r.c21, r.velocities), text), "m2 a1 ℓc2 s2 q̇1");
        COMPARE_STR(print(collectForDisplay(r.c22, r.velocities), text), "0");
        // Without grouping the sum stays flat, in the same order.
        COMPARE_STR(print(r.b22, text), "I2 + m2 ℓc2²");
        COMPARE_STR(print(r.b12, text), "I2 + m2 ℓc2² + m2 a1 ℓc2 c2");
    }

    void planar2RLatexAndPlain() {
        Symbols s;
        const Planar2R r(s);
        const ex b11 = collectForDisplay(r.b11, r.masses);
        COMPARE_STR(print(b11, style(Style::Latex)),
                    "I_{1} + m_{1} \\ell_{c1}^{2} + I_{2} + m_{2} \\left(a_{1}^{2} + \\ell_{c2}^{2} + 2 a_{1} "
                    "\\ell_{c2} c_{2}\\right)");
        COMPARE_STR(print(b11, style(Style::Plain)), "I1+m1*lc1^2+I2+m2*(a1^2+lc2^2+2*a1*lc2*cos(q2))");
        COMPARE_STR(print(r.c11, style(Style::Latex)), "-m_{2} a_{1} \\ell_{c2} s_{2} \\dot{q}_{2}");
        COMPARE_STR(print(r.c11, style(Style::Plain)), "-m2*a1*lc2*sin(q2)*qd2");
    }

    void gravityWithAngleSums() {
        Symbols s;
        const Planar2R r(s);
        AngleSumCombiner combiner({s("q1"), s("q2")});
        const ex g1 = collectForDisplay(combiner.combine(r.g1), r.masses);
        COMPARE_STR(print(g1, style(Style::Text)), "m1 ℓc1 g c1 + m2 (a1 g c1 + ℓc2 g c12)");
        COMPARE_STR(print(g1, style(Style::Latex)), "m_{1} \\ell_{c1} g c_{1} + m_{2} \\left(a_{1} g c_{1} + \\ell_{c2} g c_{12}\\right)");
        COMPARE_STR(print(g1, style(Style::Plain)), "m1*lc1*g*cos(q1)+m2*(a1*g*cos(q1)+lc2*g*cos(q1+q2))");
    }

    void names_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("latex");
        auto row = [](const char* n, const char* t, const char* l) { QTest::newRow(n) << QString(n) << QString(t) << QString(l); };
        row("qd1", "q̇1", "\\dot{q}_{1}");
        row("qdd2", "q̈2", "\\ddot{q}_{2}");
        row("q1", "q1", "q_{1}");
        row("theta1", "θ1", "\\theta_{1}");
        row("theta1_dot", "θ̇1", "\\dot{\\theta}_{1}");
        row("x_dot", "x\u0307", "\\dot{x}");
        row("phi_ddot", "φ̈", "\\ddot{\\phi}");
        row("lc2", "ℓc2", "\\ell_{c2}");
        row("l1", "l1", "l_{1}");
        row("I1", "I1", "I_{1}");
        row("K2", "K2", "K_{2}");
        row("m2", "m2", "m_{2}");
        row("a1", "a1", "a_{1}");
        row("Ixx1", "Ixx1", "I_{xx,1}");
        row("Iyz3", "Iyz3", "I_{yz,3}");
        row("xc1", "xc1", "x_{c1}");
        row("Fc2", "Fc2", "F_{c2}");
        row("alpha1", "α1", "\\alpha_{1}");
        row("tau", "τ", "\\tau");
        row("tau2", "τ2", "\\tau_{2}");
        row("Omega", "Ω", "\\Omega");
        row("theta_1", "θ_1", "\\theta_{1}");
        row("m_cart", "m_cart", "m_{\\mathrm{cart}}");
        row("mass", "mass", "\\mathrm{mass}");
        row("c1", "c1", "c_{1}");
        row("s12", "s12", "s_{12}");
        row("c123", "c123", "c_{123}");
        row("c9_10", "c9,10", "c_{9,10}");
        row("g", "g", "g");
    }
    void names() {
        QFETCH(QString, name);
        QFETCH(QString, text);
        QFETCH(QString, latex);
        const symbol x(name.toStdString());
        PrintOptions o;  // default coordinates: any q<i>, so c9_10 is trig
        o.style = Style::Text;
        QCOMPARE(QString::fromStdString(print(x, o)), text);
        o.style = Style::Latex;
        QCOMPARE(QString::fromStdString(print(x, o)), latex);
        o.style = Style::Plain;
        if (!name.startsWith('c') && !name.startsWith('s')) QCOMPARE(QString::fromStdString(print(x, o)), name);
    }

    void trigOnlyWhereMeant() {
        const symbol c1("c1"), theta1("theta1");
        PrintOptions o{Style::Plain, {"theta1"}, true};
        COMPARE_STR(print(c1 * theta1, o), "theta1*cos(theta1)");
        o.trigSymbols = false;  // a Lagrangian system's damping coefficient c1
        COMPARE_STR(print(c1 * theta1, o), "c1*theta1");
        o = {Style::Plain, {"q1", "q2"}, true};
        COMPARE_STR(print(symbol("c3"), o), "c3");  // no q3: a parameter
        COMPARE_STR(print(symbol("s12"), o), "sin(q1+q2)");
    }

    void numbersAndDivision() {
        Symbols s;
        const ex m1 = s("m1"), m2 = s("m2"), g = s("g"), x = s("x"), qd1 = s("qd1"), lc1 = s("lc1");
        const PrintOptions plain = style(Style::Plain), text = style(Style::Text), latex = style(Style::Latex);
        const ex kinetic = GiNaC::numeric(1, 2) * m1 * pow(lc1, 2) * pow(qd1, 2);
        COMPARE_STR(print(kinetic, text), "1/2 m1 ℓc1² q̇1²");
        COMPARE_STR(print(kinetic, latex), "\\frac{1}{2} m_{1} \\ell_{c1}^{2} \\dot{q}_{1}^{2}");
        COMPARE_STR(print(kinetic, plain), "1/2*m1*lc1^2*qd1^2");
        const ex ratio = m2 * g / (m1 + m2);
        COMPARE_STR(print(ratio, text), "m2 g/(m1 + m2)");
        COMPARE_STR(print(ratio, latex), "\\frac{m_{2} g}{m_{1} + m_{2}}");
        COMPARE_STR(print(ratio, plain), "m2*g/(m1+m2)");
        COMPARE_STR(print(-3 * x / (2 * m1 * pow(m2, 2)), text), "−3 x/(2 m1 m2²)");
        COMPARE_STR(print(-3 * x / (2 * m1 * pow(m2, 2)), latex), "-\\frac{3 x}{2 m_{1} m_{2}^{2}}");
        COMPARE_STR(print(-3 * x / (2 * m1 * pow(m2, 2)), plain), "-3*x/(2*m1*m2^2)");
        COMPARE_STR(print(1 / x, plain), "1/x");
        COMPARE_STR(print(GiNaC::numeric(-1, 2), latex), "-\\frac{1}{2}");
        COMPARE_STR(print(0.1 * x, plain), "0.10000000000000001*x");
        COMPARE_STR(print(0.1 * x, text), "0.1 x");
        COMPARE_STR(print(ex(2.0), plain), "2.0");
        COMPARE_STR(print(1.5e-7 * x, text), "1.5·10⁻⁷ x");
        COMPARE_STR(print(1.5e-7 * x, latex), "1.5 \\cdot 10^{-7} x");
        COMPARE_STR(print(GiNaC::Pi * 2 * x, text), "2 π x");
        COMPARE_STR(print(pow(GiNaC::sin(s("q1")), 2), text), "sin²(q1)");
        COMPARE_STR(print(pow(GiNaC::sin(s("q1")), 2), latex), "\\sin^{2}(q_{1})");
        COMPARE_STR(print(pow(GiNaC::sin(s("q1")), 2), plain), "sin(q1)^2");
        COMPARE_STR(print(GiNaC::sqrt(x), text), "√x");
        COMPARE_STR(print(GiNaC::sqrt(m1 + m2), latex), "\\sqrt{m_{1} + m_{2}}");
        COMPARE_STR(print(pow(m1 + m2, 2), text), "(m1 + m2)²");
        COMPARE_STR(print(pow(m1 + m2, 2), latex), "{\\left(m_{1} + m_{2}\\right)}^{2}");
        COMPARE_STR(print(x - m1, text), "x − m1");     // no index before index 1
        COMPARE_STR(print(m2 - m1, text), "−m1 + m2");  // the order is the key's; the sign follows
        COMPARE_STR(print(ex(0), latex), "0");
    }

    void lagrangianSystem() {
        // The notes' mass–spring pair: user-named coordinates, no trig symbols.
        Symbols s;
        const ex t1 = s("theta1"), t2 = s("theta2"), d1 = s("theta1_dot"), d2 = s("theta2_dot");
        const ex I1 = s("I1"), I2 = s("I2"), K1 = s("K1"), K2 = s("K2");
        const ex L = GiNaC::numeric(1, 2) * I1 * pow(d1, 2) + GiNaC::numeric(1, 2) * I2 * pow(d2, 2) -
                     GiNaC::numeric(1, 2) * K1 * pow(t1, 2) - GiNaC::numeric(1, 2) * K2 * pow(t1 - t2, 2);
        PrintOptions o{Style::Text, {"theta1", "theta2"}, false};
        COMPARE_STR(print(L, o), "−1/2 K1 θ1² − 1/2 K2 (θ1 − θ2)² + 1/2 I1 θ̇1² + 1/2 I2 θ̇2²");
        o.style = Style::Latex;
        COMPARE_STR(print(L, o), "-\\frac{1}{2} K_{1} \\theta_{1}^{2} - \\frac{1}{2} K_{2} {\\left(\\theta_{1} - \\theta_{2}\\right)}^{2} "
                                 "+ \\frac{1}{2} I_{1} \\dot{\\theta}_{1}^{2} + \\frac{1}{2} I_{2} \\dot{\\theta}_{2}^{2}");
    }

    void grouping() {
        Symbols s;
        const ex m1 = s("m1"), qd1 = s("qd1"), qd2 = s("qd2"), lc1 = s("lc1"), I1 = s("I1");
        // A common rational factor of a group goes in front.
        const ex ekin = (GiNaC::numeric(1, 2) * (m1 * pow(lc1, 2) + I1) * pow(qd1, 2) + m1 * qd1 * qd2).expand();
        COMPARE_STR(print(collectForDisplay(ekin, {s("qd1"), s("qd2")}), style(Style::Text)), "1/2 (I1 + m1 ℓc1²) q̇1² + m1 q̇1 q̇2");
        const ex negative = (-m1 * (lc1 + I1) * qd1).expand();
        COMPARE_STR(print(collectForDisplay(negative, {s("m1")}), style(Style::Text)), "−m1 (I1 q̇1 + ℓc1 q̇1)");
        QVERIFY(collectForDisplay(ex(0), {s("m1")}).is_zero());
        // Grouping never changes the value.
        const ex b = collectForDisplay(ekin, {s("qd1"), s("qd2")});
        QVERIFY((b - ekin).expand().is_zero());
        const auto masses = massSymbols(s("m2") * s("x") + s("m1") + s("m_cart") + s("mu"));
        QCOMPARE(masses.size(), std::size_t(3));
        COMPARE_STR(masses[0].get_name(), "m_cart");
        COMPARE_STR(masses[1].get_name(), "m1");
    }

    void matricesAndEquations() {
        Symbols s;
        const Planar2R r(s);
        GiNaC::matrix B = {{r.b11, r.b12}, {r.b12, r.b22}};
        const ex Bd = collectForDisplay(B, r.masses);
        COMPARE_STR(print(Bd, style(Style::Plain)), "[[I1+m1*lc1^2+I2+m2*(a1^2+lc2^2+2*a1*lc2*cos(q2)),I2+m2*(lc2^2+a1*lc2*cos(q2))],"
                                                    "[I2+m2*(lc2^2+a1*lc2*cos(q2)),I2+m2*lc2^2]]");
        const std::string latex = print(Bd, style(Style::Latex));
        QVERIFY(latex.starts_with("\\begin{bmatrix} I_{1} + m_{1}"));
        QVERIFY(latex.find(" & I_{2} + m_{2} \\left(") != std::string::npos);
        QVERIFY(latex.find(" \\\\ I_{2} + m_{2}") != std::string::npos);
        QVERIFY(latex.ends_with("I_{2} + m_{2} \\ell_{c2}^{2} \\end{bmatrix}"));
        QVERIFY(balancedBraces(latex));
        const GiNaC::matrix C = {{r.c11, r.c12}, {r.c21, r.c22}};
        const std::string text = print(collectForDisplay(C, r.velocities), style(Style::Text));
        COMPARE_STR(text, "⎡ −m2 a1 ℓc2 s2 q̇2  −m2 a1 ℓc2 s2 q̇1 − m2 a1 ℓc2 s2 q̇2 ⎤\n"
                          "⎣ m2 a1 ℓc2 s2 q̇1   0                                  ⎦");
        const GiNaC::matrix g = {{s("x")}, {s("y")}, {s("z")}};
        COMPARE_STR(printEquation("g", g, style(Style::Text)), "    ⎡ x ⎤\ng = ⎢ y ⎥\n    ⎣ z ⎦");
        COMPARE_STR(printEquation("b_{11}", r.b22, style(Style::Latex)), "b_{11} = I_{2} + m_{2} \\ell_{c2}^{2}");
        COMPARE_STR(printEquation(s("tau"), s("x") + 1, style(Style::Text)), "τ = 1 + x");
        COMPARE_STR(print(GiNaC::matrix{{s("x"), 2}}, style(Style::Text)), "[ x  2 ]");
    }

    // The key test: Plain output parses back (GiNaC's parser) to the same value.
    void plainReparses() {
        Symbols s;
        RandomExpressions random(s, 20240611);
        const GiNaC::lst functions = trigFunctions(s);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> uniform(0.3, 1.7);
        for (int i = 0; i < 600; ++i) {
            const ex e = random.next(i % 5);
            for (const ex& shown : {e, collectForDisplay(e.expand(), {s("m1"), s("m2"), s("qd1"), s("qd2")})}) {
                const std::string plain = print(shown, style(Style::Plain));
                GiNaC::symtab table;
                for (const auto& [name, sym] : s.table)
                    if (!parseTrigName(name, 3)) table[name] = sym;
                GiNaC::parser reader(table, true);  // strict: an unknown name is an error
                ex parsed;
                try {
                    parsed = reader(plain);
                } catch (const std::exception& error) {
                    QFAIL((plain + "  -- " + error.what()).c_str());
                }
                GiNaC::lst at;
                for (const auto& [name, sym] : s.table) at.append(sym == uniform(rng));
                const ex original = e.subs(functions);
                std::complex<double> a, b;
                try {
                    a = value(original, at);
                } catch (const std::exception&) {
                    continue;  // division by zero at this point: nothing to compare
                }
                b = value(parsed, at);
                QVERIFY2(std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a)),
                         (plain + "  " + std::to_string(a.real()) + " vs " + std::to_string(b.real())).c_str());
                QVERIFY2(balancedBraces(print(shown, style(Style::Latex))), print(shown, style(Style::Latex)).c_str());
            }
        }
    }

    // Another creation order changes GiNaC's internal order, never the output.
    void independentOfCreationOrder() {
        std::vector<std::string> out[2];
        for (int pass = 0; pass < 2; ++pass) {
            Symbols s;
            std::vector<symbol> padding;
            if (pass == 1) {  // other serial numbers, reverse creation order
                for (int k = 0; k < 37; ++k) padding.emplace_back("pad");
                for (const char* n : {"tau",    "g",    "s123", "c12", "s2",  "c1", "qd2", "qd1", "q2",  "q1", "theta1_dot",
                                      "theta1", "Ixx1", "m2",   "m1",  "lc2", "a1", "s1",  "c2",  "lc1", "I2", "I1"})
                    s(n);
            }
            const Planar2R r(s);
            for (const ex& e : {collectForDisplay(r.b11, r.masses), collectForDisplay(r.b12, r.masses), r.b11, r.g1,
                                collectForDisplay(r.c12, r.velocities)})
                for (Style st : {Style::Plain, Style::Text, Style::Latex}) out[pass].push_back(print(e, style(st)));
            RandomExpressions random(s, 99);
            for (int i = 0; i < 200; ++i) {
                const ex e = random.next(3);
                for (Style st : {Style::Plain, Style::Text, Style::Latex}) out[pass].push_back(print(e, style(st)));
                out[pass].push_back(print(e.expand(), style(Style::Text)));
                const ex grouped = collectForDisplay(e.expand(), {s("m1"), s("m2"), s("qd1"), s("qd2")});
                out[pass].push_back(print(grouped, style(Style::Text)));
            }
        }
        QCOMPARE(out[0].size(), out[1].size());
        for (std::size_t i = 0; i < out[0].size(); ++i) COMPARE_STR(out[1][i], out[0][i]);
    }
};

LL_TEST_APPLESS_MAIN(TestExpressionPrinter)

}  // namespace test_expression_printer
#include "test_expression_printer.moc"
