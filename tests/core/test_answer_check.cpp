// A student's own answer checked (core/pipeline/answer_check.hpp, issue 47).
//  - The reader takes what a hand derivation writes: c2 or cos(q2), θ1, q̇1, ½, ², implicit
//    products, sin² q2, and says where it stopped when it cannot read.
//  - The identity test is exact: textbook identities are the same function, near misses
//    are not.
//  - A catalogue of typical student slips (sign, factor, a link's part, Steiner, the inertia
//    tensor not rotated, ℓ for ℓc, Christoffel indices, units, coordinates, the other DH
//    convention, an unknown name, right only at the home pose), generated from the right
//    answers of the planar 2R, a spatial 3R, the PUMA 560, the Stanford arm (prismatic)
//    and the notes' mass–spring Lagrangian: every right form is accepted, no wrong one is,
//    and each slip is named in at least 90 % of its cases.
#include "test_registry.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "core/io/scene_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/present/hidden_answers.hpp"
#include "core/present/text_document.hpp"
#include "core/pipeline/answer_key_data.hpp"
#include "core/present/message_text.hpp"
#include "core/symbolic/function_identity.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace test_answer_check {

using namespace ll;
using GiNaC::ex;

namespace {

std::shared_ptr<const AnswerKey> key(const std::string& example, symbolic::ParameterMode mode = symbolic::ParameterMode::Parametric) {
    return AnswerKey::build(loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example).scene, mode);
}

// A spatial 3R (the anthropomorphic arm's first three joints), every parameter named.
const char* kSpatial3R = R"({
  "format": "lagrangelab-scene/1", "name": "spatial 3R",
  "parameters": {"d1": 0.4, "a2": 0.5, "a3": 0.4, "m1": 3, "m2": 2, "m3": 1, "lc2": 0.25, "lc3": 0.2,
                 "Ix1": 0.02, "Iy1": 0.03, "Iz1": 0.04, "Ix2": 0.01, "Iy2": 0.05, "Iz2": 0.06, "Ix3": 0.01, "Iy3": 0.02, "Iz3": 0.025},
  "robot": {"convention": "standard", "base": {"position": [0, 0, 0], "rpy": [0, 0, 0]},
    "joints": [
      {"type": "revolute", "a": 0, "alpha": "pi/2", "d": "d1", "theta": 0, "mass": "m1", "com": [0, 0, 0],
       "inertia": {"xx": "Ix1", "yy": "Iy1", "zz": "Iz1", "xy": 0, "xz": 0, "yz": 0}},
      {"type": "revolute", "a": "a2", "alpha": 0, "d": 0, "theta": 0, "mass": "m2", "com": ["lc2-a2", 0, 0],
       "inertia": {"xx": "Ix2", "yy": "Iy2", "zz": "Iz2", "xy": 0, "xz": 0, "yz": 0}},
      {"type": "revolute", "a": "a3", "alpha": 0, "d": 0, "theta": 0, "mass": "m3", "com": ["lc3-a3", 0, 0],
       "inertia": {"xx": "Ix3", "yy": "Iy3", "zz": "Iz3", "xy": 0, "xz": 0, "yz": 0}}]},
  "effects": {"gravity": [0, 0, -9.81]},
  "initial": {"q": [0, 0, 0], "qd": [0, 0, 0]}
})";

std::string plain(const ex& e) {
    std::ostringstream s;
    s << e;
    return s.str();
}

AnswerCheck check(const AnswerKey& k, const std::string& entry, const std::string& answer) { return k.check({entry, answer}); }

bool has(const AnswerCheck& c, AnswerErrorKind kind) { return std::find(c.kinds.begin(), c.kinds.end(), kind) != c.kinds.end(); }

// ---- the catalogue -------------------------------------------------------------------------

struct Case {
    std::string entry, answer;
    std::optional<AnswerErrorKind> kind;  // nothing: a right answer
};

class Catalogue {
public:
    Catalogue(const AnswerKey& key, std::mt19937& random) : key_(key), k_(key.data()), random_(random) {}

    void entry(const std::string& id) {
        const auto it = std::find_if(k_.entries.begin(), k_.entries.end(), [&](const KeyEntry& e) { return e.id == id; });
        QVERIFY2(it != k_.entries.end(), id.c_str());
        const KeyEntry& e = *it;
        const ex v = k_.valueOf(e);
        rightForms(e);
        if (v.is_zero()) return;
        const bool equation = e.kind == EntryKind::Equation;
        if (!equation) {
            wrong(e, -v, AnswerErrorKind::Sign);
            wrong(e, v / 2, AnswerErrorKind::Factor);
            wrong(e, 2 * v, AnswerErrorKind::Factor);
        }
        perLink(e);
        christoffel(e);
        dimension(e);
        coordinates(e);
        convention(e);
        homePose(e);
        unknownName(e);
    }

    std::vector<Case> cases;

private:
    bool same(const ex& a, const ex& b) { return symbolic::sameFunction(a, b, sampler_).same; }

    void wrong(const KeyEntry& e, const ex& answer, AnswerErrorKind kind) {
        if (same(answer, e.value)) return;  // not a slip for this entry
        if (e.kind == EntryKind::Equation && symbolic::constantRatio(answer, e.value, sampler_)) return;
        cases.push_back({e.id, plain(answer), kind});
    }

    void rightForms(const KeyEntry& e) {
        const ex v = e.value;
        const ex expanded = symbolic::expandedTrigonometry(v).expand();
        cases.push_back({e.id, plain(v), {}});
        cases.push_back({e.id, plain(expanded), {}});
        cases.push_back({e.id, key_.rightAnswer(e.id), {}});  // the derivation's own text: ℓc2², c2, q̇1, 1/2 m1
        // the terms in another order, each as a product written without '*'
        std::vector<ex> terms;
        if (GiNaC::is_a<GiNaC::add>(expanded))
            for (std::size_t i = 0; i < expanded.nops(); ++i) terms.push_back(expanded.op(i));
        else terms.push_back(expanded);
        std::shuffle(terms.begin(), terms.end(), random_);
        std::string shuffled;
        for (const ex& t : terms) shuffled += (shuffled.empty() ? "" : " + ") + std::string("(") + plain(t) + ")";
        cases.push_back({e.id, std::regex_replace(shuffled, std::regex(R"(\*)"), " "), {}});
        // sin² written as 1 − cos², and θ for q with superscripts
        const ex pythagoras = expanded.subs(GiNaC::pow(GiNaC::sin(GiNaC::wild(0)), 2) == 1 - GiNaC::pow(GiNaC::cos(GiNaC::wild(0)), 2));
        std::string unicode = std::regex_replace(plain(pythagoras), std::regex(R"(\bq(d?)(\d))"), "θ$1$2");
        unicode = std::regex_replace(unicode, std::regex(R"(\^2\b)"), "²");
        cases.push_back({e.id, unicode, {}});
    }

    GiNaC::exmap zeros(int except) const {
        GiNaC::exmap m;
        for (std::size_t i = 0; i < k_.links.size(); ++i)
            if (static_cast<int>(i) != except) {
                for (const auto& s : k_.links[i].mass) m[s] = 0;
                for (const auto& s : k_.links[i].inertia) m[s] = 0;
            }
        return m;
    }
    ex part(const ex& v, int link) const { return v.subs(zeros(link)) - v.subs(zeros(-1)); }

    void perLink(const KeyEntry& e) {
        if (e.kind == EntryKind::Item || e.kind == EntryKind::Force) return;
        for (std::size_t i = 0; i < k_.links.size(); ++i) {
            const LinkRoles& roles = k_.links[i];
            if (roles.mass.empty()) continue;
            const ex p = part(e.value, static_cast<int>(i));
            if (p.is_zero()) continue;
            wrong(e, e.value - p, AnswerErrorKind::Link);  // a link's terms left out
            // a parallel-axis term left out of a diagonal entry of B
            if (e.kind == EntryKind::MassMatrix && e.i == e.j)
                for (const auto& c : roles.com) wrong(e, e.value - roles.mass[0] * GiNaC::pow(c, 2), AnswerErrorKind::Steiner);
            // ℓ for ℓc, and the reverse
            for (const auto& c : roles.com)
                for (const auto& l : roles.lengths) {
                    wrong(e, e.value.subs(c == l), AnswerErrorKind::Length);
                    wrong(e, e.value.subs(l == c), AnswerErrorKind::Length);
                }
            // the inertia tensor used in the link's own frame
            if (e.kind == EntryKind::MassMatrix) {
                const ex* jw = k_.itemValue(k_.derivation, symbolic::Quantity::AngularJacobian, static_cast<int>(i));
                const ex* t = k_.itemValue(k_.derivation, symbolic::Quantity::Transform, static_cast<int>(i));
                const ex* i0 = k_.itemValue(k_.derivation, symbolic::Quantity::LinkInertia, static_cast<int>(i));
                if (jw && t && i0) {
                    const auto J = GiNaC::ex_to<GiNaC::matrix>(k_.functions(*jw));
                    const auto T = GiNaC::ex_to<GiNaC::matrix>(k_.functions(*t));
                    const auto I0 = GiNaC::ex_to<GiNaC::matrix>(k_.functions(*i0));
                    GiNaC::matrix R(3, 3);
                    for (unsigned r = 0; r < 3; ++r)
                        for (unsigned c = 0; c < 3; ++c) R(r, c) = T(r, c);
                    const GiNaC::matrix local = R.transpose().mul(I0).mul(R);
                    const ex wrongTerm = J.transpose().mul(local).mul(J)(e.i, e.j), rightTerm = J.transpose().mul(I0).mul(J)(e.i, e.j);
                    wrong(e, e.value - rightTerm + wrongTerm, AnswerErrorKind::Rotation);
                }
            }
        }
    }

    void christoffel(const KeyEntry& e) {
        if (e.kind != EntryKind::Christoffel) return;
        const auto B = GiNaC::ex_to<GiNaC::matrix>(k_.functions(k_.derivation.B));
        wrong(e, ll::christoffel(B, k_.derivation.q, e.j, e.i, e.k), AnswerErrorKind::ChristoffelIndex);
        wrong(e, ll::christoffel(B, k_.derivation.q, e.i, e.j, e.k, {1, 1, 1}), AnswerErrorKind::ChristoffelIndex);
    }

    // one term of the answer with a length too many
    void dimension(const KeyEntry& e) {
        if (k_.units.empty() || e.kind == EntryKind::Equation) return;
        const ex expanded = e.value.expand();
        if (!GiNaC::is_a<GiNaC::add>(expanded)) return;
        for (std::size_t i = 0; i < k_.links.size(); ++i)
            for (const auto& l : k_.links[i].lengths) {
                const ex term = expanded.op(0);
                wrong(e, expanded - term + term * l, AnswerErrorKind::Dimension);
                return;
            }
    }

    void coordinates(const KeyEntry& e) {
        const auto& q = k_.derivation.q;
        for (std::size_t a = 0; a < q.size(); ++a) {
            if (!symbolic::dependsOn(e.value, q[a], sampler_)) continue;
            const std::size_t b = (a + 1) % q.size();
            if (b == a) return;
            wrong(e, e.value.subs(q[a] == q[b]), AnswerErrorKind::Coordinates);
            return;
        }
    }

    void convention(const KeyEntry& e) {
        if (k_.scene.lagrangian) return;
        if (!other_) {
            Scene s = k_.scene;
            s.robot.convention = s.robot.convention == DhConvention::Standard ? DhConvention::Modified : DhConvention::Standard;
            symbolic::DerivationOptions options;
            options.mode = k_.mode;
            other_ = symbolic::deriveRobot(s, options);
        }
        if (auto v = k_.entryValue(*other_, e)) wrong(e, *v, AnswerErrorKind::Convention);
    }

    // right at q = 0 only: cos q_j in place of cos 2q_j … here cos(2 q_j) for cos(q_j)
    void homePose(const KeyEntry& e) {
        if (k_.scene.lagrangian) return;
        for (const auto& q : k_.derivation.q)
            if (e.value.has(GiNaC::cos(q))) {
                wrong(e, e.value.subs(GiNaC::cos(q) == GiNaC::cos(2 * q)), AnswerErrorKind::HomePose);
                return;
            }
    }

    void unknownName(const KeyEntry& e) {
        const std::string text = plain(e.value);
        for (const auto& [name, value] : k_.vocabulary.names) {
            if (name.size() < 2 || !GiNaC::is_a<GiNaC::symbol>(value)) continue;
            const std::regex word("\\b" + name + "\\b");
            if (!std::regex_search(text, word)) continue;
            cases.push_back({e.id, std::regex_replace(text, word, name + "zz", std::regex_constants::format_first_only),
                             AnswerErrorKind::UnknownSymbol});
            return;
        }
    }

    const AnswerKey& key_;
    const AnswerKey::Data& k_;
    std::mt19937& random_;
    symbolic::IdentitySampler sampler_{0xca7a10ULL};
    std::optional<symbolic::Derivation> other_;
};

}  // namespace

class TestAnswerCheck : public QObject {
    Q_OBJECT
private slots:
    void readsWhatAStudentWrites() {
        const auto k = key("planar_2r.json");
        for (const char* b11 :
             {"I1 + m1*lc1^2 + I2 + m2*(a1^2 + lc2^2 + 2*a1*lc2*cos(q2))", "I1+m1 ℓc1²+I2+m2(a1²+ℓc2²+2a1ℓc2c2)",
              "m2 a1**2 + I2 + I1 + m1 lc1^2 + m2 lc2^2 + 2 a1 lc2 m2 cos(θ2)", "I₁ + m₁ℓc₁² + I₂ + m₂(a₁² + ℓc₂² + 2 a₁ ℓc₂ cos θ₂)",
              "I1 + m1 lc1^2 + I2 + m2 (a1^2 (sin^2 q2 + cos² q2) + lc2^2 + 2 a1 lc2 cos(q2))",
              "I1 + m1 lc1^2 + I2 + m2 (a1^2 + lc2^2 + 2 a1lc2 c2)"}) {
            const AnswerCheck c = check(*k, "b11", b11);
            QVERIFY2(c.verdict == AnswerVerdict::Right, (std::string(b11) + " → " + c.readAs + " " + c.problem.english()).c_str());
        }
        QCOMPARE(check(*k, "B_{11}", "I1 + m1 lc1^2 + I2 + m2 (a1^2 + lc2^2 + 2 a1 lc2 c2)").entry, std::string("b11"));
        QVERIFY(check(*k, "c11", "-m2 a1 lc2 s2 qd2").verdict == AnswerVerdict::Right);
        QVERIFY(check(*k, "c12", "-m2 a1 ℓc2 sin(q2) (q̇1 + q̇2)").verdict == AnswerVerdict::Right);
        QVERIFY(check(*k, "g2", "m2 lc2 g c12").verdict == AnswerVerdict::Right);  // g: the magnitude of the scene's gravity
        QVERIFY(check(*k, "g2", "9.81 m2 lc2 cos(q1 + q2)").verdict == AnswerVerdict::Right);
        QVERIFY(check(*k, "E_pot", "g (m1 lc1 s1 + m2 (a1 s1 + lc2 s12))").verdict == AnswerVerdict::Right);
        const AnswerCheck kinetic =
            check(*k, "E_kin",
                  "½ (I1 + m1 lc1² + I2 + m2 (a1² + lc2² + 2 a1 lc2 c2)) q̇1² + (I2 + m2 (lc2² + a1 lc2 c2)) q̇1 q̇2 + ½ (I2 + m2 lc2²) q̇2²");
        QVERIFY2(kinetic.verdict == AnswerVerdict::Right, kinetic.readAs.c_str());
        // the equation of motion, either way round and scaled
        const AnswerCheck motion =
            check(*k, "equation2", "(I2 + m2 (lc2^2 + a1 lc2 c2)) qdd1 + (I2 + m2 lc2^2) qdd2 + m2 a1 lc2 s2 qd1^2 + 9.81 m2 lc2 c12 = 0");
        QVERIFY2(motion.verdict == AnswerVerdict::Right, motion.readAs.c_str());
        QVERIFY(
            check(*k, "eom2", "0 = -2 ((I2 + m2 (lc2^2 + a1 lc2 c2)) qdd1 + (I2 + m2 lc2^2) qdd2 + m2 a1 lc2 s2 qd1^2 + 9.81 m2 lc2 c12)")
                .verdict == AnswerVerdict::Right);
        // an entry of T_2^0 and of p_c2
        QVERIFY(check(*k, "T_2^0(1,4)", "a1 c1 + a2 c12").verdict == AnswerVerdict::Right);
        QVERIFY(check(*k, "T2(1,4)", "a1 cos(q1) + a2 cos(q1+q2)").verdict == AnswerVerdict::Right);
        QVERIFY(check(*k, "p_c2(2)", "a1 s1 + lc2 s12").verdict == AnswerVerdict::Right);
        // what was read is printed back as the derivation prints
        QCOMPARE(check(*k, "b22", "I2+m2*lc2^2").readAs, std::string("I2 + m2 ℓc2²"));
        // the parameters' values in place of their names: right, and said so
        const AnswerCheck values = check(*k, "b22", "0.08 + 1.5*0.4^2");
        QVERIFY(values.verdict == AnswerVerdict::Right && values.withValues);
    }

    // A whole matrix or vector at once, judged entry by entry.
    void readsWholeMatrices() {
        const auto k = key("planar_2r.json");
        const std::string b11 = "I1 + m1 lc1^2 + I2 + m2 (a1^2 + lc2^2 + 2 a1 lc2 c2)", b12 = "I2 + m2 (lc2^2 + a1 lc2 c2)";
        QVERIFY(check(*k, "B", "[" + b11 + ", " + b12 + "; " + b12 + ", I2 + m2 lc2^2]").verdict == AnswerVerdict::Right);
        QVERIFY(check(*k, "B", "[[" + b11 + ", " + b12 + "], [" + b12 + ", I2 + m2 lc2^2]]").verdict == AnswerVerdict::Right);
        QVERIFY(check(*k, "p_c2", "[a1 c1 + lc2 c12; a1 s1 + lc2 s12; 0]").verdict == AnswerVerdict::Right);
        const AnswerCheck wrong = check(*k, "B", "[" + b11 + ", " + b12 + "; " + b12 + ", I2 + m2 a2^2]");
        QVERIFY(wrong.verdict == AnswerVerdict::Wrong && has(wrong, AnswerErrorKind::Length));
        QCOMPARE(wrong.hints.at(0).english(), std::string("3 of 4 entries are right."));
        QVERIFY2(wrong.hints.at(1).english().rfind("Entry (2,2): ", 0) == 0, wrong.hints.at(1).english().c_str());
        const AnswerCheck shape = check(*k, "B", "[1, 2]");
        QVERIFY(shape.verdict == AnswerVerdict::Unreadable && shape.problem.id == MessageId::AnswerShape);
        QVERIFY(check(*k, "B", b11).problem.id == MessageId::AnswerMatrixNeeded);
        QVERIFY(check(*k, "b11", "[1, 2]").problem.id == MessageId::AnswerOneEntry);
        QCOMPARE(check(*k, "B", "[1, 2; 3]").problem.english(), std::string("character 9: row 2 has 1 entries, row 1 has 2"));
        QVERIFY(check(*k, "b22", "[I2 + m2 lc2^2]").verdict == AnswerVerdict::Right);  // brackets around one expression group it
        QVERIFY(check(*k, "b22", "I2 + m2 [lc2]^2").verdict == AnswerVerdict::Right);
    }

    void saysWhereItCannotRead() {
        const auto k = key("planar_2r.json");
        const AnswerCheck dangling = check(*k, "b22", "I2 + m2 *");
        QVERIFY(dangling.verdict == AnswerVerdict::Unreadable);
        QCOMPARE(dangling.position, std::size_t(10));
        QCOMPARE(dangling.problem.english(), std::string("character 10: expected a number, a name or '(', found the end"));
        const AnswerCheck unknown = check(*k, "b22", "I2 + m3 lc2^2");
        QVERIFY(unknown.verdict == AnswerVerdict::Unreadable && has(unknown, AnswerErrorKind::UnknownSymbol));
        QCOMPARE(unknown.position, std::size_t(6));
        QVERIFY2(unknown.problem.english().find("closest: m1, m2") != std::string::npos, unknown.problem.english().c_str());
        const AnswerCheck open = check(*k, "b22", "m2 (lc2^2 + I2");
        QCOMPARE(open.problem.english(), std::string("character 15: expected ')', found the end"));
        const AnswerCheck character = check(*k, "b22", "I2 + m2 lc2² ∫");
        QVERIFY(character.verdict == AnswerVerdict::Unreadable);
        QCOMPARE(character.position, std::size_t(14));
        QVERIFY(check(*k, "b22", "").verdict == AnswerVerdict::Unreadable);
        QVERIFY(check(*k, "b22", "I2 / 0").verdict == AnswerVerdict::Unreadable);
        QVERIFY(check(*k, "b22", "sqrt(-1 - m2^2)").verdict == AnswerVerdict::Unreadable);  // not real anywhere: refused, not guessed
        const AnswerCheck entry = check(*k, "b33", "0");
        QVERIFY(entry.verdict == AnswerVerdict::Unreadable && entry.problem.id == MessageId::AnswerUnknownEntry);
    }

    void identityTestIsExact() {
        const auto lock = symbolic::lockGinac();
        const GiNaC::symbol x("x"), y("y"), a("a");
        symbolic::IdentitySampler s;
        QVERIFY(symbolic::sameFunction(GiNaC::sin(2 * x), 2 * GiNaC::sin(x) * GiNaC::cos(x), s).same);
        QVERIFY(symbolic::sameFunction(GiNaC::cos(x + y), GiNaC::cos(x) * GiNaC::cos(y) - GiNaC::sin(x) * GiNaC::sin(y), s).same);
        QVERIFY(symbolic::sameFunction(GiNaC::pow(GiNaC::sin(x), 2), 1 - GiNaC::pow(GiNaC::cos(x), 2), s).same);
        QVERIFY(symbolic::sameFunction(GiNaC::cos(3 * x), 4 * GiNaC::pow(GiNaC::cos(x), 3) - 3 * GiNaC::cos(x), s).same);
        QVERIFY(symbolic::sameFunction(GiNaC::tan(x) * GiNaC::cos(x), GiNaC::sin(x), s).same);
        QVERIFY(symbolic::sameFunction(a / (1 + a * a) * (1 + a * a), a, s).same);
        // near misses: a truncated series, a coefficient off by 10⁻⁹, an angle on its own
        QVERIFY(!symbolic::sameFunction(GiNaC::cos(x), 1 - x * x / 2, s).same);
        QVERIFY(!symbolic::sameFunction(GiNaC::sin(x) * a, GiNaC::sin(x) * a * GiNaC::numeric(1000000001, 1000000000), s).same);
        QVERIFY(!symbolic::sameFunction(x * GiNaC::sin(x), GiNaC::sin(x), s).same);
        const symbolic::IdentityResult r = symbolic::sameFunction(GiNaC::pow(GiNaC::sin(x), 2) + GiNaC::pow(GiNaC::cos(x), 2), 1, s);
        QVERIFY(r.same && r.exactness == symbolic::Exactness::Exact && r.points >= 6);
        // values that are not rational (e^a): compared to 60 digits, and said so
        const ex square = a * a;
        const symbolic::IdentityResult power =
            symbolic::sameFunction(GiNaC::pow(GiNaC::sin(square), 2) + GiNaC::pow(GiNaC::cos(square), 2), 1, s);
        QVERIFY(power.same && power.exactness == symbolic::Exactness::SixtyDigits);
        QVERIFY(!symbolic::sameFunction(GiNaC::exp(a), 1 + a, s).same);
    }

    void namesTheSlip() {
        const auto k = key("planar_2r.json");
        auto kinds = [&](const char* entry, const char* answer) { return check(*k, entry, answer); };
        QVERIFY(has(kinds("b22", "-(I2 + m2 lc2^2)"), AnswerErrorKind::Sign));
        const AnswerCheck half = kinds("b22", "(I2 + m2 lc2^2)/2");
        QVERIFY(has(half, AnswerErrorKind::Factor));
        QCOMPARE(half.hints.at(0).english(), std::string("Right up to a constant factor: yours is 1/2 times the right b22."));
        const AnswerCheck steiner = kinds("b11", "I1 + I2 + m2 (a1^2 + lc2^2 + 2 a1 lc2 c2)");
        QVERIFY(has(steiner, AnswerErrorKind::Steiner) && has(steiner, AnswerErrorKind::Link));
        QCOMPARE(steiner.links, std::vector<int>{1});
        QCOMPARE(steiner.hints.at(0).english(),
                 std::string("The terms of link 1 (its mass and inertia) are wrong; those of link 2 are right."));
        const AnswerCheck length = kinds("b22", "I2 + m2 a2^2");
        QVERIFY2(has(length, AnswerErrorKind::Length), length.hints.empty() ? "" : length.hints[0].english().c_str());
        const AnswerCheck units = kinds("b12", "I2 + m2 (lc2^2 + a1 c2)");
        QVERIFY(has(units, AnswerErrorKind::Dimension));
        QCOMPARE(units.hints.at(0).english(), std::string("m2 a1 c2 is kg·m; b12 is kg·m²."));
        const AnswerCheck coordinates = kinds("b11", "I1 + m1 lc1^2 + I2 + m2 (a1^2 + lc2^2 + 2 a1 lc2)");
        QVERIFY(has(coordinates, AnswerErrorKind::Coordinates));
        QVERIFY(has(coordinates, AnswerErrorKind::HomePose));
        const AnswerCheck index = kinds("c112", "1/2 (0 + 0 - (-2 m2 a1 lc2 s2))");  // c_112 with −∂b_12/∂q_1's sign the other way
        QVERIFY(index.verdict == AnswerVerdict::Wrong);
        // Danish, from the same data
        QVERIFY(present::messageText(half.hints.at(0), present::Language::Danish).find("Rigtigt på nær en konstant faktor") == 0);
    }

    // Exercise mode hides the entries asked (core/present/hidden_answers): each at its
    // place in the derivation the key names, the symmetric b_ji with b_ij, nothing else.
    void hidesTheEntriesAsked() {
        const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/planar_2r.json").scene;
        const auto k = AnswerKey::build(scene);
        QCOMPARE(k->practiceEntries(7), (std::vector<std::string>{"b11", "b12", "b22", "E_kin"}));
        const std::vector<std::string> step8 = k->practiceEntries(8);  // c_ij, g_i, Q_i, the equations; no c_ijk
        for (const char* id : {"c12", "g2", "equation1"}) QVERIFY2(std::count(step8.begin(), step8.end(), id) == 1, id);
        QVERIFY(std::count(step8.begin(), step8.end(), "c121") == 0);
        QCOMPARE(k->entriesOf("p_c2").size(), std::size_t(3));
        QCOMPARE(k->entriesOf("B"), (std::vector<std::string>{"b11", "b12", "b21", "b22"}));
        QVERIFY(k->entriesOf("zz").empty());
        QCOMPARE(k->place("c121").step, -1);  // Christoffel symbols are not shown
        DocumentRequest request;
        request.format = present::DocumentFormat::Display;
        const auto shown = deriveDisplay(scene, request).display;
        std::vector<present::EntryPlace> places;
        for (const char* id : {"b12", "g2", "T_2^0(1,4)", "E_kin"}) {
            places.push_back(k->place(id));
            QVERIFY2(places.back().step >= 0, id);
        }
        QCOMPARE(places[0].step, 7);
        QCOMPARE(places[2].step, 1);
        const present::DisplayDocument hidden = present::withAnswersHidden(*shown, places);
        const auto cell = [](const present::DisplayDocument& d, int step, present::Quantity q, int index, int r, int c) {
            for (const present::DisplayItem& item : d.step(step)->items)
                if (item.quantity == q && (index < 0 || item.row == index)) return item.value->rows[r][c];
            return present::DisplayPtr();
        };
        using Q = present::Quantity;
        QCOMPARE(cell(hidden, 7, Q::MassMatrix, -1, 0, 1), present::hiddenAnswer());
        QCOMPARE(cell(hidden, 7, Q::MassMatrix, -1, 1, 0), present::hiddenAnswer());
        QVERIFY(cell(hidden, 7, Q::MassMatrix, -1, 0, 0) != present::hiddenAnswer());
        QCOMPARE(cell(hidden, 8, Q::GravityVector, -1, 1, 0), present::hiddenAnswer());
        QVERIFY(cell(hidden, 8, Q::GravityVector, -1, 0, 0) != present::hiddenAnswer());
        QCOMPARE(cell(hidden, 1, Q::Transform, 1, 0, 3), present::hiddenAnswer());
        QVERIFY(cell(hidden, 1, Q::Transform, 0, 0, 3) != present::hiddenAnswer());  // T_1^0 shown
        // the text: E_kin's value gone, the '?' in its place; every other step as before
        const std::string before = present::textDocument(*shown), after = present::textDocument(hidden);
        QVERIFY(after.find("E_kin = ?") != std::string::npos);
        QVERIFY(before.find("E_kin = ?") == std::string::npos);
        for (int step : {0, 2, 3, 4, 5, 6}) {
            present::DisplayDocument a, b;
            a.steps = {*shown->step(step)};
            b.steps = {*hidden.step(step)};
            QCOMPARE(present::textDocument(b), present::textDocument(a));
        }
    }

    // The structured form's names as entries: β_jk⁽ⁱ⁾ and γ_j⁽ⁱ⁾ from the expanded
    // derivation equal the structured derivation's own (written in the links' frames, an
    // independent construction), sum to b_jk and −g_j as the notes say, and are checked
    // like any entry.
    void structuredNamesAreEntries() {
        for (const char* which : {"spatial 3R", "stanford_arm.json"}) {
            Scene scene = std::string(which) == "spatial 3R" ? parseScene(kSpatial3R) : loadScene(std::string(LL_EXAMPLES_DIR) + "/" + which).scene;
            scene.effects.springs.clear();  // g_j is then gravity's alone
            const auto k = AnswerKey::build(scene);
            const AnswerKey::Data& d = k->data();
            const auto lock = symbolic::lockGinac();
            const auto value = [&](const std::string& id) {
                for (const KeyEntry& e : d.entries)
                    if (e.id == id) return d.valueOf(e);
                qFatal("no entry %s", id.c_str());
            };
            const symbolic::StructuredDynamics s = symbolic::deriveStructured(scene);
            GiNaC::exmap toFunctions;
            for (const ex& r : s.trigToFunctions) toFunctions[r.lhs()] = r.rhs();
            const auto adopt = [&](ex e) {  // the structured derivation's symbols are the key's, by name
                e = s.table->unfold(e).subs(toFunctions, GiNaC::subs_options::no_pattern);
                GiNaC::exmap byName;
                std::map<std::string, ex> found;
                std::function<void(const ex&)> collect = [&](const ex& x) {
                    if (GiNaC::is_a<GiNaC::symbol>(x)) found.emplace(GiNaC::ex_to<GiNaC::symbol>(x).get_name(), x);
                    for (std::size_t i = 0; i < x.nops(); ++i) collect(x.op(i));
                };
                collect(e);
                for (const auto& [name, symbol] : found)
                    if (auto it = d.vocabulary.names.find(name); it != d.vocabulary.names.end()) byName[symbol] = it->second;
                return e.subs(byName, GiNaC::subs_options::no_pattern);
            };
            const int n = scene.dof();
            symbolic::IdentitySampler sampler(77);
            for (int j = 0; j < n; ++j) {
                ex gamma = 0;
                for (int i = j; i < n; ++i) gamma -= d.masses[i] * value("gamma" + std::to_string(j + 1) + "_" + std::to_string(i + 1));
                QVERIFY2(symbolic::sameFunction(gamma, value("g" + std::to_string(j + 1)), sampler).same, which);
                for (int kk = j; kk < n; ++kk) {
                    ex b = 0;
                    for (int i = kk; i < n; ++i) {
                        const std::string id = "beta" + std::to_string(j + 1) + "_" + std::to_string(kk + 1) + "_" + std::to_string(i + 1);
                        const ex beta = value(id);
                        b += beta;
                        QVERIFY2(symbolic::sameFunction(beta, adopt(s.beta[j][kk][i - kk]), sampler).same, (std::string(which) + " " + id).c_str());
                    }
                    const std::string bid = "b" + std::to_string(j + 1) + std::to_string(kk + 1);
                    QVERIFY2(symbolic::sameFunction(b, value(bid), sampler).same, (std::string(which) + " " + bid).c_str());
                }
            }
        }
        const auto k = AnswerKey::build(parseScene(kSpatial3R));
        QCOMPARE(k->entryId("β23(3)"), std::string("beta2_3_3"));
        QCOMPARE(k->entryId("gamma_2^(3)"), std::string("gamma2_3"));
        QCOMPARE(int(check(*k, "beta3_3_3", "Iz3 + m3 lc3^2").verdict), int(AnswerVerdict::Right));
        const AnswerCheck slip = check(*k, "beta3_3_3", "Iz3");
        QCOMPARE(int(slip.verdict), int(AnswerVerdict::Wrong));
        QVERIFY(has(slip, AnswerErrorKind::Steiner) || has(slip, AnswerErrorKind::Link));
    }

    // The right answer as --reveal and the window print it, copied back, is right: every
    // digit of the scene's decimal arithmetic is printed (the PUMA 560's 1.553523243625),
    // not 6 rounded ones, and endless decimals stay fractions.
    void revealedAnswersReadBackRight() {
        for (const char* example : {"puma560.json", "planar_2r.json", "stanford_arm.json"}) {
            const auto k = key(example);
            int checked = 0;
            for (const std::string& id : k->entries()) {
                if (id.rfind("b", 0) != 0 && id.rfind("g", 0) != 0 && id.rfind("E_", 0) != 0 && id.rfind("T_", 0) != 0) continue;
                const std::string right = k->rightAnswer(id);
                QVERIFY2(right.find("·10") == std::string::npos, (id + ": " + right).c_str());  // no rounded mantissas
                const AnswerCheck c = check(*k, id, right);
                QVERIFY2(c.verdict == AnswerVerdict::Right, (std::string(example) + " " + id + ": " + right).c_str());
                ++checked;
            }
            QVERIFY(checked >= 10);
        }
    }

    void catalogueOfSlips() {
        struct Scene_ {
            std::shared_ptr<const AnswerKey> key;
            std::vector<std::string> entries;
        };
        std::vector<Scene_> scenes;
        scenes.push_back(
            {key("planar_2r.json"), {"b11",     "b12",        "b21",        "b22",        "c111",      "c112",      "c121",    "c122",
                                     "c211",    "c212",       "c221",       "c222",       "c11",       "c12",       "c21",     "c22",
                                     "g1",      "g2",         "E_kin",      "E_pot",      "equation1", "equation2", "p_c1(1)", "p_c2(1)",
                                     "p_c2(2)", "T_2^0(1,4)", "T_2^0(2,4)", "T_2^0(1,1)", "v_c2(1)",   "v_c2(2)",   "w_2(3)"}});
        scenes.push_back({AnswerKey::build(parseScene(kSpatial3R)),
                          {"b11",  "b12", "b13", "b22", "b23", "b33",   "c112",    "c113",    "c123",   "c223",
                           "c233", "c21", "c31", "g2",  "g3",  "E_pot", "p_c3(1)", "p_c3(3)", "w_3(1)", "T_3^0(3,4)"}});
        scenes.push_back({key("puma560.json", symbolic::ParameterMode::Textbook), {"b33", "b23", "g3"}});
        scenes.push_back({key("stanford_arm.json", symbolic::ParameterMode::Textbook), {"b22", "b33", "b23", "g2", "g3", "c233", "c322"}});
        scenes.push_back(
            {key("mass_spring_pair_lagrangian.json"),
             {"b11", "b22", "g1", "g2", "E_pot", "E_kin", "equation1", "equation2", "L", "dL/dtheta1_dot", "dL/dtheta2", "Q2"}});
        std::mt19937 random(47);
        std::vector<Case> cases;
        std::vector<const AnswerKey*> keys;
        for (const Scene_& s : scenes) {
            const auto lock = symbolic::lockGinac();
            Catalogue c(*s.key, random);
            for (const std::string& e : s.entries) c.entry(e);
            for (const Case& x : c.cases) keys.push_back(s.key.get());
            cases.insert(cases.end(), c.cases.begin(), c.cases.end());
        }
        std::map<AnswerErrorKind, std::pair<int, int>> named;  // kind → (named, cases)
        int right = 0, wrong = 0;
        std::map<const AnswerKey*, double> seconds;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const Case& c = cases[i];
            const auto start = std::chrono::steady_clock::now();
            const AnswerCheck r = keys[i]->check({c.entry, c.answer});
            seconds[keys[i]] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (!c.kind) {
                ++right;
                QVERIFY2(r.verdict == AnswerVerdict::Right,
                         (c.entry + ": a right answer rejected: " + c.answer + " (" + r.problem.english() + ")").c_str());
                continue;
            }
            ++wrong;
            QVERIFY2(r.verdict != AnswerVerdict::Right, (c.entry + ": a wrong answer accepted: " + c.answer).c_str());
            auto& [hits, all] = named[*c.kind];
            ++all;
            if (has(r, *c.kind)) ++hits;
            else
                qDebug("%s %s not named: %s → %s", answerErrorKindName(*c.kind), c.entry.c_str(), c.answer.c_str(),
                       r.hints.empty() ? r.problem.english().c_str() : r.hints[0].english().c_str());
        }
        qInfo("%d right forms accepted, %d wrong answers refused", right, wrong);
        for (const Scene_& s : scenes)
            qInfo("%s: %d cases, %.2f s of checks", s.key->data().scene.name.c_str(),
                  int(std::count(keys.begin(), keys.end(), s.key.get())), seconds[s.key.get()]);
        QVERIFY(right + wrong >= 1000);
        for (const auto& [kind, counts] : named) {
            const double rate = double(counts.first) / counts.second;
            qInfo("%-18s named in %3d of %3d cases (%.0f %%)", answerErrorKindName(kind), counts.first, counts.second, 100 * rate);
            QVERIFY2(rate >= 0.9, answerErrorKindName(kind));
        }
        QVERIFY(named.size() >= 12);
    }
};

LL_TEST_APPLESS_MAIN(TestAnswerCheck)

}  // namespace test_answer_check
#include "test_answer_check.moc"
