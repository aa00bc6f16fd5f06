// number_spelling: scene decimals (exact rationals after parsing) shown as decimals
// again, other fractions kept, checked on the textbook cases and against the rule
// written out here with GiNaC's own map (the independent implementation) on random
// sums; and how one number reads in each style (6 significant digits shown, 17 in
// Plain, powers of ten apart).
#include <QtTest>

#include <random>

#include <ginac/ginac.h>

#include "core/symbolic/ginac_lock.hpp"
#include "core/present/number_spelling.hpp"

using namespace ll::symbolic;
using namespace ll::present;
using GiNaC::ex, GiNaC::numeric;

namespace {

// The rule: when a fraction with a denominator over 8 made only of 2s and 5s occurs
// (a scene decimal), every fraction whose denominator is made only of 2s and 5s
// becomes a float, wherever it is.
bool onlyTwosAndFives(numeric d) {
    while (GiNaC::irem(d, 2).is_zero()) d = d / 2;
    while (GiNaC::irem(d, 5).is_zero()) d = d / 5;
    return d.is_equal(1);
}
bool finiteDecimal(const numeric& v) { return v.is_rational() && !v.is_integer() && onlyTwosAndFives(v.denom()); }

struct Reference : GiNaC::map_function {
    ex operator()(const ex& x) override {
        if (GiNaC::is_a<numeric>(x)) return finiteDecimal(GiNaC::ex_to<numeric>(x)) ? GiNaC::ex_to<numeric>(x).evalf() : x;
        return x.map(*this);
    }
};
bool hasSceneDecimal(const ex& e) {
    if (GiNaC::is_a<numeric>(e)) {
        const numeric& v = GiNaC::ex_to<numeric>(e);
        return finiteDecimal(v) && v.denom() > 8;
    }
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (hasSceneDecimal(e.op(i))) return true;
    return false;
}
ex reference(const ex& e) {
    Reference map;
    return hasSceneDecimal(e) ? map(e) : e;
}

std::string printed(const ex& e) { return (std::ostringstream() << e).str(); }

}  // namespace

class TestNumberSpelling : public QObject {
    Q_OBJECT
private slots:
    void textbookCases() {
        const auto lock = lockGinac();
        const GiNaC::symbol a("a"), b("b"), x("x");
        // The PUMA's a2 = 0.4318 parses as 2159/5000 and prints as 0.4318 again.
        const ex shown = readableNumbers(numeric(2159, 5000) * a);
        QVERIFY(GiNaC::is_a<GiNaC::mul>(shown) && GiNaC::is_a<numeric>(shown.op(1)));
        QVERIFY(!GiNaC::ex_to<numeric>(shown.op(1)).is_rational());
        QCOMPARE(GiNaC::ex_to<numeric>(shown.op(1)).to_double(), 0.4318);
        // Without a scene decimal a textbook fraction stays one: 1/2 m ℓ², 3/8.
        QVERIFY(readableNumbers(numeric(1, 2) * a + numeric(3, 8) * b).is_equal(numeric(1, 2) * a + numeric(3, 8) * b));
        // With one, 1/2 shows as 0.5 beside it; 1/3 has no finite decimal and stays.
        const ex mixed = readableNumbers(numeric(1, 10) * a + numeric(1, 2) * b + numeric(1, 3) * x);
        QVERIFY(mixed.is_equal(ex(numeric(1, 10)).evalf() * a + ex(numeric(1, 2)).evalf() * b + numeric(1, 3) * x));
        // Denominators past a machine word: 2^70 is a decimal fraction, 3·2^70 is not.
        const numeric big = GiNaC::ex_to<numeric>(GiNaC::pow(numeric(2), 70));
        QVERIFY(isDecimalFraction(1 / big) && !isDecimalFraction(1 / (3 * big)) && !isDecimalFraction(numeric(1, 3)));
        QVERIFY(isDecimalFraction(numeric(7, 1000)) && !isDecimalFraction(numeric(3, 8)));  // 3/8: a textbook fraction
    }

    // Random sums as the printers meet them: monomials with integer powers, and with a
    // square root, a number inside a function or a nested sum.
    void sameAsTheMapOnRandomSums() {
        const auto lock = lockGinac();
        const GiNaC::symbol s[] = {GiNaC::symbol("m2"), GiNaC::symbol("c2"), GiNaC::symbol("s3"), GiNaC::symbol("qd1"),
                                   GiNaC::symbol("qd2"), GiNaC::symbol("Ixx4")};
        const numeric big = GiNaC::ex_to<numeric>(GiNaC::pow(numeric(2), 70));
        const numeric coefficients[] = {1, -1, 2, numeric(1, 2), numeric(1, 3), numeric(2159, 5000), numeric(3, 8),
                                        numeric(-7, 1000), numeric(-1, 5), 1 / big, 1 / (3 * big), numeric(1, 12)};
        std::mt19937 rng(20261124);
        std::uniform_int_distribution<int> pick(0, 5), coefficient(0, static_cast<int>(std::size(coefficients)) - 1),
            factors(0, 4), odd(0, 9), power(1, 3);
        int plain = 0, others = 0;
        for (int k = 0; k < 400; ++k) {
            ex sum = 0;
            const bool mayBeUnusual = odd(rng) < 5;
            bool unusual = false;
            for (int t = std::uniform_int_distribution<int>(1, 40)(rng); t > 0; --t) {
                ex term = coefficients[coefficient(rng)];
                for (int f = factors(rng); f > 0; --f) term *= GiNaC::pow(s[pick(rng)], power(rng));
                switch (mayBeUnusual ? odd(rng) : 9) {
                case 0: term *= GiNaC::sqrt(s[pick(rng)]); unusual = true; break;
                case 1: term *= GiNaC::sin(s[pick(rng)] + coefficients[coefficient(rng)]); unusual = true; break;
                case 2: term *= s[pick(rng)] + coefficients[coefficient(rng)] * s[pick(rng)]; unusual = true; break;
                default: break;
                }
                sum += term;
            }
            if (odd(rng) < 3) sum += coefficients[coefficient(rng)];  // a number term
            const ex expected = reference(sum), got = readableNumbers(sum);
            QVERIFY2(got.is_equal(expected), (printed(sum) + "\n  gave " + printed(got) + "\n  not  " + printed(expected)).c_str());
            QCOMPARE(QString::fromStdString(printed(got)), QString::fromStdString(printed(expected)));
            (unusual ? others : plain) += hasSceneDecimal(sum) && GiNaC::is_a<GiNaC::add>(sum);
        }
        QVERIFY2(plain >= 50 && others >= 50, qPrintable(QString("%1 plain sums, %2 others").arg(plain).arg(others)));
    }

    // One number in the three styles: at most 6 significant digits shown (a scene's
    // 0.15005 whole, a product of identified inertials rounded), every digit in Plain
    // (re-parsable to the same double), a power of ten apart, fractions and negatives.
    void oneNumberInEachStyle() {
        const auto lock = lockGinac();
        const auto styles = [](const numeric& n) {
            const DisplayPtr node = numberNode(n);
            return QStringList{QString::fromStdString(renderDisplay(*node, DisplayStyle::Text)),
                               QString::fromStdString(renderDisplay(*node, DisplayStyle::Latex)),
                               QString::fromStdString(renderDisplay(*node, DisplayStyle::Plain))};
        };
        QCOMPARE(styles(numeric(0.15005)), (QStringList{"0.15005", "0.15005", "0.15004999999999999"}));
        QCOMPARE(styles(numeric(0.00796990221726315)), (QStringList{"0.0079699", "0.0079699", "0.0079699022172631494"}));
        QCOMPARE(styles(numeric(1.5e-7)), (QStringList{"1.5·10⁻⁷", "1.5 \\cdot 10^{-7}", "1.4999999999999999e-07"}));
        QCOMPARE(styles(numeric(2.0)), (QStringList{"2", "2", "2.0"}));
        QCOMPARE(styles(numeric(-3, 8)), (QStringList{"−3/8", "-\\frac{3}{8}", "-3/8"}));
        QCOMPARE(styles(numeric(42)), (QStringList{"42", "42", "42"}));
        // Plain reads back as the same double.
        for (double v : {0.1, 0.15005, 0.00796990221726315, 1.5e-7, 9.81, 123456.789})
            QCOMPARE(std::stod(renderDisplay(*numberNode(numeric(v)), DisplayStyle::Plain)), v);
    }
};

QTEST_GUILESS_MAIN(TestNumberSpelling)
#include "test_number_spelling.moc"
