// ginac_kind: the exact class of an expression without a dynamic_cast. Checked against
// GiNaC's own is_a on every kind of node the derivation and the display builder meet,
// on the subclasses is_a also accepts (realsymbol, possymbol, fderivative), and on every
// node of a derived model's expressions.
#include "test_registry.hpp"

#include <ginac/ginac.h>

#include "core/io/scene_file.hpp"
#include "core/symbolic/ginac_kind.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/structured_dynamics.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_ginac_kind {

using namespace ll::symbolic;
using GiNaC::ex;

namespace {

// The kind is_a gives (the reference).
GinacKind byIsA(const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return GinacKind::Numeric;
    if (GiNaC::is_a<GiNaC::symbol>(e)) return GinacKind::Symbol;
    if (GiNaC::is_a<GiNaC::constant>(e)) return GinacKind::Constant;
    if (GiNaC::is_a<GiNaC::add>(e)) return GinacKind::Add;
    if (GiNaC::is_a<GiNaC::mul>(e)) return GinacKind::Mul;
    if (GiNaC::is_a<GiNaC::power>(e)) return GinacKind::Power;
    if (GiNaC::is_a<GiNaC::function>(e)) return GinacKind::Function;
    return GinacKind::Other;
}

// Every node of e agrees; returns how many were compared.
int compareAll(const ex& e) {
    int nodes = 0;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it, ++nodes)
        if (ginacKind(*it) != byIsA(*it)) {
            std::ostringstream s;
            s << *it;
            qWarning("kind differs for %s", s.str().c_str());
            return -1;
        }
    return nodes;
}

}  // namespace

class TestGinacKind : public QObject {
    Q_OBJECT

private slots:
    void eachKind() {
        const auto lock = lockGinac();
        const GiNaC::symbol x("x"), y("y");
        const GiNaC::realsymbol r("r");
        const GiNaC::possymbol p("p");
        const struct {
            ex e;
            GinacKind kind;
        } cases[] = {
            {ex(3), GinacKind::Numeric},
            {ex(GiNaC::numeric(1, 3)), GinacKind::Numeric},
            {ex(2.5), GinacKind::Numeric},
            {x, GinacKind::Symbol},
            {r, GinacKind::Symbol},
            {p, GinacKind::Symbol},
            {GiNaC::Pi, GinacKind::Constant},
            {x + y, GinacKind::Add},
            {2 * x * y, GinacKind::Mul},
            {GiNaC::pow(x, 2), GinacKind::Power},
            {GiNaC::sqrt(x), GinacKind::Power},
            {GiNaC::cos(x), GinacKind::Function},
            {GiNaC::fderivative(GiNaC::sin_SERIAL::serial, GiNaC::paramset{0}, GiNaC::exvector{x}), GinacKind::Function},
            {x == y, GinacKind::Other},
            {GiNaC::lst{x, y}, GinacKind::Other},
            {GiNaC::matrix{{x, y}}, GinacKind::Other},
        };
        for (const auto& c : cases) {
            std::ostringstream s;
            s << c.e;
            QVERIFY2(ginacKind(c.e) == c.kind, s.str().c_str());
            QVERIFY2(ginacKind(c.e) == byIsA(c.e), s.str().c_str());
            QVERIFY(isKind(c.e, c.kind));
        }
    }

    // The Panda's structured model: every node of every name and of B, C, g.
    void everyNodeOfAModel() {
        const ll::Scene scene = ll::loadScene(LL_EXAMPLES_DIR "/panda.json").scene;
        const auto lock = lockGinac();
        const StructuredDynamics s = deriveStructured(scene, {});
        long nodes = 0;
        for (const NamedDefinition& d : s.table->entries()) {
            const int n = compareAll(d.value);
            QVERIFY(n > 0);
            nodes += n;
        }
        for (const GiNaC::matrix* m : {&s.B, &s.C, &s.g})
            for (unsigned i = 0; i < m->nops(); ++i) {
                const int n = compareAll(m->op(i));
                QVERIFY(n > 0);
                nodes += n;
            }
        qInfo("%ld nodes", nodes);
        QVERIFY(nodes > 10000);
    }
};

LL_TEST_GUILESS_MAIN(TestGinacKind)

}  // namespace test_ginac_kind
#include "test_ginac_kind.moc"
