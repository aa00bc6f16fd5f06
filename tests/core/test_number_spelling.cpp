// number_spelling: which rationals read as decimals (a scene's typed values and what its
// arithmetic makes of them) and which stay fractions (the formulas' ½, 1/12, 2/5),
// checked on the textbook cases and against the rule written out here again in
// machine integers (the independent implementation) on random rationals; and how one
// number reads in each style (6 significant digits shown, 17 in Plain, exact rationals in
// Plain, powers of ten apart).
#include "test_registry.hpp"

#include <numeric>
#include <random>

#include <ginac/ginac.h>

#include "core/symbolic/ginac_lock.hpp"
#include "core/present/number_spelling.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_number_spelling {

using namespace ll::symbolic;
using namespace ll::present;
using GiNaC::ex, GiNaC::numeric;

namespace {

// The rule in long long: p/q in lowest terms (q > 0) is formula made when |p| ≤ 12,
// q ≤ 240, q has no prime but 2, 3, 5, 7, at most one 5, and then p ∈ {1, 2, 4, 8}.
bool referenceFormulaMade(long long p, long long q) {
    p = std::llabs(p);
    if (p > 12 || q > 240) return false;
    long long rest = q;
    int fives = 0;
    for (long long prime : {2, 3, 5, 7})
        while (rest % prime == 0) {
            rest /= prime;
            if (prime == 5) ++fives;
        }
    if (rest != 1 || fives > 1) return false;
    return fives == 0 || p == 1 || p == 2 || p == 4 || p == 8;
}

// Decimal when not formula made, or |p/q| = k · t for a typed t = a/b and k ∈ {¼, ½, 1,
// 2, 4} (a typed ½ or ¼ only standing alone): |p| b · 4 = k·4 · a q.
bool referenceDecimal(long long p, long long q, const std::vector<std::pair<long long, long long>>& typed, bool alone) {
    if (q == 1) return false;
    if (!referenceFormulaMade(p, q)) return true;
    for (auto [a, b] : typed) {
        if (!alone && ((a == 1 && b == 2) || (a == 1 && b == 4))) continue;
        for (long long k4 : {1, 2, 4, 8, 16})
            if (std::llabs(p) * b * 4 == k4 * a * q) return true;
    }
    return false;
}

}  // namespace

class TestNumberSpelling : public QObject {
    Q_OBJECT
private slots:
    void textbookCases() {
        const auto lock = lockGinac();
        const NumberSpelling none, puma({numeric(2159, 5000)}), arm({numeric(11, 8), numeric(1, 2)});
        // The PUMA's a2 = 0.4318 parses as 2159/5000 and reads 0.4318 again; Plain keeps it exact.
        const DisplayPtr a2 = puma.node(numeric(2159, 5000));
        QCOMPARE(renderDisplay(*a2, DisplayStyle::Text), std::string("0.4318"));
        QCOMPARE(renderDisplay(*a2, DisplayStyle::Plain), std::string("(2159/5000)"));
        QCOMPARE(renderDisplay(*puma.node(numeric(-2159, 5000)), DisplayStyle::Text), std::string("−0.4318"));
        // The formulas' fractions stay: ½ of E_kin, a rod's 1/12, a sphere's 2/5, ½·⅕, ⅓·2/5.
        for (const numeric& f :
             {numeric(1, 2), numeric(1, 12), numeric(2, 5), numeric(1, 10), numeric(2, 15), numeric(3, 8), numeric(5, 3)})
            QVERIFY2(!none.decimal(f) && !puma.decimal(f), qPrintable(QString::fromStdString((std::ostringstream() << f).str())));
        // What a scene's decimals make: 9.8 = 49/5, 0.3·0.2 = 3/50, 0.7 + 0.2 = 9/10, 0.01/12 = 1/1200.
        for (const numeric& d : {numeric(49, 5), numeric(3, 50), numeric(9, 10), numeric(1, 1200), numeric(21, 100)})
            QVERIFY2(none.decimal(d), qPrintable(QString::fromStdString((std::ostringstream() << d).str())));
        // A typed 1.375 reads as typed, and so do its half and double; not 11/24.
        QVERIFY(arm.decimal(numeric(11, 8)) && arm.decimal(numeric(11, 16)) && arm.decimal(numeric(11, 4)));
        QVERIFY(!arm.decimal(numeric(11, 24)) && !none.decimal(numeric(11, 8)));
        // A typed 0.5 reads 0.5 standing alone (a DH entry), ½ inside an expression.
        QVERIFY(arm.decimal(numeric(1, 2), true) && !arm.decimal(numeric(1, 2), false));
        QCOMPARE(renderDisplay(*arm.node(numeric(1, 2), true), DisplayStyle::Text), std::string("0.5"));
        QCOMPARE(renderDisplay(*arm.node(numeric(1, 2)), DisplayStyle::Text), std::string("1/2"));
        // Integers and floats are not rationals to spell.
        QVERIFY(!none.decimal(numeric(7)) && !none.decimal(numeric(0.25)));
    }

    // The rule against its re-statement in machine integers, on random rationals and
    // random typed values (a scene's 0.15, 1.375, 9.81 and the like).
    void sameAsTheReferenceOnRandomRationals() {
        const auto lock = lockGinac();
        std::mt19937 rng(20261127);
        std::uniform_int_distribution<long long> numer(-300, 300), denom(1, 2400), typedDigits(1, 2000);
        int decimals = 0, fractions = 0;
        for (int scene = 0; scene < 40; ++scene) {
            std::vector<std::pair<long long, long long>> typed;
            std::vector<numeric> typedExact;
            for (int k = std::uniform_int_distribution<int>(0, 4)(rng); k > 0; --k) {
                const long long a = typedDigits(rng), b = std::vector<long long>{2, 4, 5, 10, 100, 1000}[rng() % 6];
                const long long g = std::gcd(a, b);
                if (b / g == 1) continue;  // an integer is not a typed decimal
                typed.emplace_back(a / g, b / g);
                typedExact.push_back(numeric(a / g, b / g));
            }
            if (scene % 5 == 0) {  // a typed 0.5 now and then
                typed.emplace_back(1, 2);
                typedExact.push_back(numeric(1, 2));
            }
            const NumberSpelling spelling(typedExact);
            for (int k = 0; k < 500; ++k) {
                long long p = numer(rng), q = denom(rng);
                if (p == 0) continue;
                if (k % 3 == 0 && !typed.empty()) {  // near a typed value: k · t
                    const auto [a, b] = typed[rng() % typed.size()];
                    const long long mul[] = {1, 1, 2, 1, 4, 3}, div[] = {1, 2, 1, 4, 1, 1};
                    const int pick = static_cast<int>(rng() % 6);
                    p = a * mul[pick];
                    q = b * div[pick];
                }
                const long long g = std::gcd(std::llabs(p), q);
                p /= g;
                q /= g;
                const bool alone = k % 2 == 0;
                const bool expected = referenceDecimal(p, q, typed, alone);
                QVERIFY2(spelling.decimal(numeric(p, q), alone) == expected,
                         qPrintable(QString("%1/%2 alone=%3: expected %4").arg(p).arg(q).arg(alone).arg(expected)));
                QCOMPARE(formulaMade(numeric(p, q)), q != 1 && referenceFormulaMade(p, q) || (q == 1 && std::llabs(p) <= 12));
                (expected ? decimals : fractions) += 1;
            }
        }
        QVERIFY2(decimals > 1000 && fractions > 100, qPrintable(QString("%1 decimals, %2 fractions").arg(decimals).arg(fractions)));
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

LL_TEST_GUILESS_MAIN(TestNumberSpelling)

}  // namespace test_number_spelling
#include "test_number_spelling.moc"
