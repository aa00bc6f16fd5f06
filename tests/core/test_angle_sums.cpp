// angle_sums: the textbook examples, planar 3R and PUMA 560 kinematics, exactness at
// random points, speed at PUMA size, and independence from symbol creation order.
#include "test_registry.hpp"

#include <chrono>
#include <random>
#include <string>

#include "core/present/angle_sums.hpp"
#include "core/present/expression_printer.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_angle_sums {

using namespace ll::symbolic;
using namespace ll::present;
using GiNaC::ex;
using GiNaC::symbol;

#define COMPARE_STR(actual, expected) QCOMPARE(QString::fromStdString(actual), QString::fromStdString(expected))

namespace {

// q_i, c_i, s_i as a TrigContext makes them, plus named parameters.
struct Joints {
    std::vector<symbol> q, c, s;
    std::map<std::string, symbol> parameters;
    explicit Joints(int n, bool reversed = false) {
        q.resize(n), c.resize(n), s.resize(n);
        for (int k = 0; k < n; ++k) {
            const int i = reversed ? n - 1 - k : k;
            const std::string idx = std::to_string(i + 1);
            s[i] = symbol("s" + idx);
            c[i] = symbol("c" + idx);
            q[i] = symbol("q" + idx);
        }
    }
    symbol p(const std::string& name) { return parameters.try_emplace(name, name).first->second; }
    GiNaC::lst toFunctions() const {
        GiNaC::lst l;
        for (std::size_t i = 0; i < q.size(); ++i) {
            l.append(c[i] == GiNaC::cos(q[i]));
            l.append(s[i] == GiNaC::sin(q[i]));
        }
        return l;
    }
    // cos and sin of q_{i1} + q_{i2} + ... written in c_i, s_i (the angle-sum formulas).
    std::pair<ex, ex> cosSin(const std::vector<int>& indices) const {
        ex cs = 1, sn = 0;
        for (int i : indices) {
            const ex ci = c[i - 1], si = s[i - 1];
            std::tie(cs, sn) = std::pair<ex, ex>{cs * ci - sn * si, sn * ci + cs * si};
        }
        return {cs, sn};
    }
};

std::string text(const ex& e, int n) {
    PrintOptions o;
    o.style = Style::Text;
    for (int i = 1; i <= n; ++i) o.coordinateNames.push_back("q" + std::to_string(i));
    return print(e, o);
}

// e at a random point: combined symbols by their definitions, then c_i, s_i, then numbers.
double valueAt(const ex& e, const GiNaC::lst& definitions, const Joints& j, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-3, 3);
    GiNaC::lst at;
    for (const symbol& q : j.q) at.append(q == u(rng));
    for (const auto& [name, p] : j.parameters) at.append(p == u(rng));
    const ex v = GiNaC::evalf(e.subs(definitions).subs(j.toFunctions()).subs(at));
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

// Standard DH link transform with exact cos α, sin α.
GiNaC::matrix dh(const ex& c, const ex& s, const ex& a, const ex& d, const ex& alpha) {
    const ex ca = GiNaC::cos(alpha), sa = GiNaC::sin(alpha);
    return {{c, -s * ca, s * sa, a * c}, {s, c * ca, -c * sa, a * s}, {0, sa, ca, d}, {0, 0, 0, 1}};
}

GiNaC::matrix expanded(const GiNaC::matrix& m) {
    GiNaC::matrix r = m;
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned k = 0; k < m.cols(); ++k) r(i, k) = m(i, k).expand();
    return r;
}

GiNaC::matrix puma560(Joints& j) {
    const ex Pi = GiNaC::Pi;
    const ex alpha[] = {Pi / 2, 0, -Pi / 2, Pi / 2, -Pi / 2, 0};
    const ex a[] = {0, j.p("a2"), j.p("a3"), 0, 0, 0};
    const ex d[] = {0, 0, j.p("d3"), j.p("d4"), 0, 0};
    GiNaC::matrix T = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(4));
    for (int i = 0; i < 6; ++i) T = expanded(T.mul(dh(j.c[i], j.s[i], a[i], d[i], alpha[i])));
    return T;
}

}  // namespace

class TestAngleSums : public QObject {
    Q_OBJECT

private slots:
    void names() {
        COMPARE_STR(trigSymbolName({'c', {1, 2}}), "c12");
        COMPARE_STR(trigSymbolName({'s', {1, 2, 3}}), "s123");
        COMPARE_STR(trigSymbolName({'c', {9, 10}}), "c9_10");
        COMPARE_STR(trigSymbolName({'c', {1, 2}}, 12), "c1_2");  // c12 would be cos q12 there
        COMPARE_STR(trigSymbolName({'s', {4}}, 12), "s4");
        QVERIFY((parseTrigName("c12") == TrigName{'c', {1, 2}}));
        QVERIFY((parseTrigName("s123", 3) == TrigName{'s', {1, 2, 3}}));
        QVERIFY((parseTrigName("c9_10") == TrigName{'c', {9, 10}}));
        QVERIFY((parseTrigName("c12", 12) == TrigName{'c', {12}}));
        QVERIFY((parseTrigName("c1_2", 12) == TrigName{'c', {1, 2}}));
        QVERIFY((parseTrigName("s7") == TrigName{'s', {7}}));
        for (const char* other : {"lc1", "c", "c0", "c21", "c1_1", "cx", "c_1", "c1a", "sd1", "Fc1"})
            QVERIFY2(!parseTrigName(other), other);
        QVERIFY(!parseTrigName("c3", 2));  // no q3: a parameter of that name
    }

    void textbookExamples() {
        Joints j(3);
        const ex c1 = j.c[0], c2 = j.c[1], c3 = j.c[2], s1 = j.s[0], s2 = j.s[1], s3 = j.s[2];
        const ex a1 = j.p("a1"), a2 = j.p("a2"), k = j.p("k");
        AngleSumCombiner combiner(j.q);
        COMPARE_STR(text(combiner.combine(c1 * c2 - s1 * s2), 3), "c12");
        COMPARE_STR(text(combiner.combine(s1 * c2 + c1 * s2), 3), "s12");
        COMPARE_STR(text(combiner.combine(a1 * c1 + a2 * c1 * c2 - a2 * s1 * s2), 3), "a1 c1 + a2 c12");
        COMPARE_STR(text(combiner.combine(c1 * c2 * c3 - c1 * s2 * s3 - s1 * s2 * c3 - s1 * c2 * s3), 3), "c123");
        COMPARE_STR(text(combiner.combine(-k * (c1 * c2 - s1 * s2)), 3), "−k c12");
        COMPARE_STR(text(combiner.combine(k * (c1 * c2 - s1 * s2) * c3 * c3), 3), "k c12 c3²");
        // Not rewritten: differences of angles, unequal coefficients, overlapping sets.
        COMPARE_STR(text(combiner.combine(c1 * c2 + s1 * s2), 3), "c1 c2 + s1 s2");
        COMPARE_STR(text(combiner.combine(2 * c1 * c2 - s1 * s2), 3), "2 c1 c2 − s1 s2");
        COMPARE_STR(text(combiner.combine(pow(c1, 2) - pow(s1, 2)), 3), "c1² − s1²");
        // Rewriting the result again changes nothing; the new symbols are shared.
        const ex once = combiner.combine(a1 * c1 + a2 * c1 * c2 - a2 * s1 * s2);
        QVERIFY(combiner.combine(once).is_equal(once));
        QVERIFY(combiner.combine(c1 * c2 - s1 * s2).is_equal(combiner.combine(c2 * c1 - s2 * s1)));
        const GiNaC::lst defs = combiner.definitions();
        QVERIFY(defs.nops() >= 3);
        COMPARE_STR(print(defs.op(0).lhs(), {Style::Plain, {}, false}), "c12");
        QVERIFY(defs.op(0).rhs().is_equal(GiNaC::cos(j.q[0] + j.q[1])));
        QVERIFY(defs.op(0).lhs().is_equal(combiner.combine(c1 * c2 - s1 * s2)));
        COMPARE_STR(print(defs, {Style::Plain, {}, false}), "{c12==cos(q1+q2),c123==cos(q1+q2+q3),s12==sin(q1+q2)}");
        COMPARE_STR(print(defs.op(0), {Style::Latex, {}, false}), "c_{12} = \\cos(q_{1} + q_{2})");
    }

    void tenJoints() {
        Joints j(10);
        AngleSumCombiner combiner(j.q);
        const ex r = combiner.combine(j.c[8] * j.c[9] - j.s[8] * j.s[9] + j.s[0] * j.c[1] + j.c[0] * j.s[1]);
        COMPARE_STR(print(r, {Style::Plain, {}, false}), "s1_2+c9_10");
        COMPARE_STR(text(r, 10), "s1,2 + c9,10");
    }

    void planar3R() {
        Joints j(3);
        const ex a[] = {j.p("a1"), j.p("a2"), j.p("a3")};
        GiNaC::matrix T = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(4));
        for (int i = 0; i < 3; ++i) T = expanded(T.mul(dh(j.c[i], j.s[i], a[i], 0, 0)));
        AngleSumCombiner combiner(j.q);
        const GiNaC::matrix R = combiner.combine(T);
        COMPARE_STR(text(R(0, 3), 3), "a1 c1 + a2 c12 + a3 c123");
        COMPARE_STR(text(R(1, 3), 3), "a1 s1 + a2 s12 + a3 s123");
        COMPARE_STR(text(R(0, 0), 3), "c123");
        COMPARE_STR(text(R(0, 1), 3), "−s123");
        PrintOptions latex{Style::Latex, {"q1", "q2", "q3"}, true};
        COMPARE_STR(print(R(0, 3), latex), "a_{1} c_{1} + a_{2} c_{12} + a_{3} c_{123}");
        PrintOptions plain{Style::Plain, {"q1", "q2", "q3"}, true};
        COMPARE_STR(print(R(1, 3), plain), "a1*sin(q1)+a2*sin(q1+q2)+a3*sin(q1+q2+q3)");
    }

    // PUMA 560 forward kinematics: the textbook's c23, s23, and a few hundred terms fast.
    void puma560Kinematics() {
        Joints j(6);
        const GiNaC::matrix T = puma560(j);
        AngleSumCombiner combiner(j.q);
        const GiNaC::matrix R = combiner.combine(T);
        COMPARE_STR(text(R(0, 3), 6), "a2 c1 c2 + d3 s1 + a3 c1 c23 − d4 c1 s23");
        COMPARE_STR(text(R(2, 3), 6), "a2 s2 + a3 s23 + d4 c23");
        // Products of rotation and position entries, like the J^T J terms of B: ~300 terms.
        ex big = 0;
        for (unsigned r = 0; r < 3; ++r)
            for (unsigned c = 0; c < 3; ++c) big += j.p("w" + std::to_string(r) + std::to_string(c)) * T(r, c) * T(r, 3);
        big = big.expand();
        const std::size_t before = big.nops();
        QVERIFY2(before > 250, std::to_string(before).c_str());
        const auto start = std::chrono::steady_clock::now();
        const ex combined = combiner.combine(big);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        qInfo("PUMA 560: %zu terms → %zu in %.3f s", before, combined.nops(), seconds);
        QVERIFY(combined.nops() < before);
        QVERIFY2(seconds < 2.0, std::to_string(seconds).c_str());
        std::mt19937 rng(5);
        for (int trial = 0; trial < 5; ++trial) {
            std::mt19937 same = rng;
            const double x = valueAt(big, {}, j, rng), y = valueAt(combined, combiner.definitions(), j, same);
            QVERIFY2(std::abs(x - y) <= 1e-10 * std::max(1.0, std::abs(x)), (std::to_string(x) + " vs " + std::to_string(y)).c_str());
        }
    }

    // Exact by construction: before and after agree at random points.
    void exactAtRandomPoints() {
        Joints j(4);
        std::mt19937 rng(20240611);
        auto uniform = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        std::size_t termsBefore = 0, termsAfter = 0;
        for (int trial = 0; trial < 150; ++trial) {
            ex e = 0;
            for (int t = uniform(1, 6); t > 0; --t) {
                ex term = GiNaC::numeric(uniform(-4, 4), uniform(1, 3)) * j.p(std::string(1, char('a' + uniform(0, 3))));
                for (int f = uniform(1, 3); f > 0; --f) {
                    std::vector<int> set;
                    for (int i = 1; i <= 4; ++i)
                        if (uniform(0, 1)) set.push_back(i);
                    if (set.empty()) set.push_back(uniform(1, 4));
                    const auto [cs, sn] = j.cosSin(set);
                    term *= uniform(0, 1) ? cs : sn;
                }
                if (uniform(0, 3) == 0) term *= j.c[uniform(0, 3)] + 2 * j.s[uniform(0, 3)];  // noise
                e += term;
            }
            e = e.expand();
            const AngleSumForm r = combineAngleSums(e, j.q);
            termsBefore += GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
            termsAfter += GiNaC::is_a<GiNaC::add>(r.value) ? r.value.nops() : 1;
            for (int k = 0; k < 3; ++k) {
                std::mt19937 same = rng;
                const double x = valueAt(e, {}, j, rng), y = valueAt(r.value, r.definitions, j, same);
                QVERIFY2(std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(x)), (text(e, 4) + "  →  " + text(r.value, 4)).c_str());
            }
        }
        qInfo("random sums: %zu terms → %zu", termsBefore, termsAfter);
        QVERIFY(termsAfter * 2 < termsBefore);  // it did rewrite, not just stay exact
    }

    // Another symbol creation order: the same rewriting, the same text.
    void independentOfCreationOrder() {
        std::vector<std::string> out[2];
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<symbol> padding;  // other serial numbers
            for (int k = 0; k < pass * 23; ++k) padding.emplace_back("pad");
            Joints j(6, pass == 1);
            if (pass == 1)
                for (const char* n : {"k23", "k22", "k21", "k20", "k13", "d4", "d3", "a3", "a2"}) j.p(n);
            const GiNaC::matrix T = puma560(j);
            AngleSumCombiner combiner(j.q);
            const GiNaC::matrix R = combiner.combine(T);
            for (unsigned r = 0; r < 3; ++r)
                for (unsigned c = 0; c < 4; ++c) out[pass].push_back(text(R(r, c), 6));
            ex big = 0;
            for (unsigned c = 0; c < 4; ++c) big += j.p("k2" + std::to_string(c)) * T(2, c) + j.p("k1" + std::to_string(c)) * T(1, c);
            out[pass].push_back(text(combiner.combine(big.expand()), 6));
            out[pass].push_back(print(combiner.definitions(), {Style::Plain, {}, false}));
        }
        for (std::size_t i = 0; i < out[0].size(); ++i) COMPARE_STR(out[1][i], out[0][i]);
    }
};

LL_TEST_APPLESS_MAIN(TestAngleSums)

}  // namespace test_angle_sums
#include "test_angle_sums.moc"
