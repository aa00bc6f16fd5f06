// Why an answer is wrong, found from the difference between it and the right one and
// from the robot's structure — never from how the answer is spelled:
//  - a constant ratio to the right answer: only the sign, or a factor (½, 2);
//  - the right answer of the other DH convention, of mixed-up Christoffel indices or signs,
//    of a link length swapped with a centre-of-mass distance, of an inertia tensor left in
//    its link's frame;
//  - the difference split by link (the dynamics are linear in each link's inertial
//    parameters: setting the other links' masses and inertias to zero leaves one link's
//    part), and within a link into its m v_cᵀv_c and ωᵀIω terms; a constant difference
//    in the translational term is a parallel-axis (Steiner) slip;
//  - the units of each term, the coordinates and velocities it depends on, the home pose.
#include <cstdio>
#include <algorithm>
#include <optional>
#include <set>
#include <sstream>

#include "core/pipeline/answer_key_data.hpp"
#include "core/present/expression_printer.hpp"
#include "core/symbolic/function_identity.hpp"
#include "core/symbolic/robot_derivation.hpp"

namespace ll {

using GiNaC::ex;

namespace {

std::string superscript(int n) {
    static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
    if (n >= 0 && n <= 9) return n == 1 ? "" : digits[n];
    return "^" + std::to_string(n);
}

std::string unitText(const Dimension& d) {
    static const char* names[] = {"kg", "m", "s"};
    std::string top, bottom;
    for (int a = 0; a < 3; ++a) {
        if (d[a] > 0) top += (top.empty() ? "" : "·") + std::string(names[a]) + superscript(d[a]);
        if (d[a] < 0) bottom += (bottom.empty() ? "" : "·") + std::string(names[a]) + superscript(-d[a]);
    }
    if (top.empty()) top = "1";
    return bottom.empty() ? top : top + "/" + bottom;
}

class Explainer {
public:
    Explainer(const AnswerKey::Data& k, const KeyEntry& e, const ex& answer, AnswerCheck& out)
        : k_(k),
          e_(e),
          answer_(answer),
          right_(k.valueOf(e)),
          A_(answer),
          R_(right_),
          out_(out),
          sampler_(0x5eed0000ULL + e.i * 131 + e.j * 17 + e.k) {}

    void explain() {
        const bool christoffel = christoffelIndices();  // a Christoffel sign slip is also "only the sign"
        if (ratio() || christoffel) return;
        dimension();
        if (convention()) return;
        links();
        coordinates();
        homePose();
        if (out_.hints.empty()) hint(message(MessageId::HintDiffers, e_.id));
    }

private:
    void hint(Message m, std::optional<AnswerErrorKind> kind = std::nullopt) {
        if (out_.hints.size() < 3) out_.hints.push_back(std::move(m));
        if (kind && std::find(out_.kinds.begin(), out_.kinds.end(), *kind) == out_.kinds.end()) out_.kinds.push_back(*kind);
    }
    // the answer (A_) or the right answer (R_) against a variant of the right answer
    // (the feedback's comparisons may conclude "the same" modulo the prime: function_identity.hpp)
    bool same(const symbolic::SampledFunction& a, const ex& variant) { return same(a, symbolic::SampledFunction(variant)); }
    bool same(const symbolic::SampledFunction& a, const symbolic::SampledFunction& b, const symbolic::Combination& c = {}) {
        return symbolic::sameFunction(a, c, b, c, sampler_, false).same;
    }
    bool same(const symbolic::SampledFunction& a, const symbolic::Combination& ofA, const symbolic::SampledFunction& b,
              const symbolic::Combination& ofB) {
        return symbolic::sameFunction(a, ofA, b, ofB, sampler_, false).same;
    }
    std::string text(const ex& e) const {
        return present::print(e.subs(k_.toShorthand, GiNaC::subs_options::no_pattern),
                              present::printOptionsFor(k_.derivation, present::Style::Text));
    }

    bool ratio() {
        const auto k = symbolic::constantRatio(A_, R_, sampler_);
        if (!k || k->is_zero()) return false;
        if (*k == -1) {
            hint(message(MessageId::HintSign), AnswerErrorKind::Sign);
            return true;
        }
        // a factor a student slips in is a small fraction (½, 2, 4/3); between two numbers any
        // ratio is "a factor", which says nothing: they are simply different
        const bool small = abs(k->numer()) <= 64 && k->denom() <= 64;
        if (!small && GiNaC::is_a<GiNaC::numeric>(answer_) && GiNaC::is_a<GiNaC::numeric>(right_)) return false;
        std::ostringstream s;
        if (small) {
            s << *k;
        } else {
            char decimal[32];
            std::snprintf(decimal, sizeof decimal, "≈ %.4g", k->to_double());
            s << decimal;
        }
        hint(message(MessageId::HintFactor, s.str(), e_.id), AnswerErrorKind::Factor);
        return true;
    }

    // ---- units --------------------------------------------------------------------------

    // e's units as powers of kg, m, s: nothing when a symbol's are not known (a motor's Jm G²
    // or a spring's K, which a sum then leaves out) or a sum's terms disagree.
    std::optional<Dimension> unitsOf(const ex& e) const {
        if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return Dimension{0, 0, 0};
        if (GiNaC::is_a<GiNaC::symbol>(e)) {
            auto it = k_.units.find(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
            if (it == k_.units.end()) return std::nullopt;
            return it->second;
        }
        if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(e)) return Dimension{0, 0, 0};
        if (GiNaC::is_a<GiNaC::power>(e)) {
            const ex n = e.op(1);
            const auto base = unitsOf(e.op(0));
            if (!base || !GiNaC::is_a<GiNaC::numeric>(n) || !GiNaC::ex_to<GiNaC::numeric>(n).is_integer()) return std::nullopt;
            const int k = GiNaC::ex_to<GiNaC::numeric>(n).to_int();
            return Dimension{k * (*base)[0], k * (*base)[1], k * (*base)[2]};
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            Dimension d{0, 0, 0};
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const auto f = unitsOf(e.op(i));
                if (!f) return std::nullopt;
                for (int a = 0; a < 3; ++a) d[a] += (*f)[a];
            }
            return d;
        }
        if (GiNaC::is_a<GiNaC::add>(e)) {
            std::optional<Dimension> common;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const auto t = unitsOf(e.op(i));
                if (!t) continue;
                if (common && *common != *t) return std::nullopt;
                common = t;
            }
            return common;
        }
        return std::nullopt;
    }

    // The first term of e (with `factor`, what multiplies it from outside) whose units are not
    // `expected`; a sum inside a product is searched with the other factors' units taken off.
    std::optional<ex> offending(const ex& e, const Dimension& expected, const ex& factor) const {
        if (GiNaC::is_a<GiNaC::add>(e)) {
            for (std::size_t i = 0; i < e.nops(); ++i)
                if (auto o = offending(e.op(i), expected, factor)) return o;
            return std::nullopt;
        }
        if (GiNaC::is_a<GiNaC::mul>(e)) {
            Dimension others{0, 0, 0};
            int unknown = -1;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const auto f = unitsOf(e.op(i));
                if (f) {
                    for (int a = 0; a < 3; ++a) others[a] += (*f)[a];
                } else if (unknown < 0 && GiNaC::is_a<GiNaC::add>(e.op(i))) {
                    unknown = static_cast<int>(i);
                } else {
                    return std::nullopt;
                }
            }
            if (unknown < 0) return others == expected ? std::nullopt : std::optional<ex>(factor * e);
            const Dimension inner{expected[0] - others[0], expected[1] - others[1], expected[2] - others[2]};
            return offending(e.op(unknown), inner, factor * (e / e.op(unknown)));
        }
        const auto u = unitsOf(e);
        if (u && *u != expected) return factor * e;
        return std::nullopt;
    }

    void dimension() {
        if (k_.units.empty()) return;
        const auto reference = unitsOf(right_);
        if (!reference) return;  // the derivation's own form mixes units, or none are known
        if (const auto term = offending(answer_, *reference, 1)) {
            const auto units = unitsOf(*term);
            if (units)
                hint(message(MessageId::HintDimension, text(*term), unitText(*units), e_.id, unitText(*reference)),
                     AnswerErrorKind::Dimension);
        }
    }

    // ---- a right answer to another question -----------------------------------------------

    bool convention() {
        if (k_.scene.lagrangian || k_.scene.robot.joints.size() > 6) return false;
        if (!k_.otherConvention) {
            Scene other = k_.scene;
            const bool modified = other.robot.convention == DhConvention::Modified;
            other.robot.convention = modified ? DhConvention::Standard : DhConvention::Modified;
            symbolic::DerivationOptions options;
            options.mode = k_.mode;
            try {
                k_.otherConvention = symbolic::deriveRobot(other, options);
            } catch (const std::exception&) {
                return false;
            }
        }
        const auto value = k_.entryValue(*k_.otherConvention, e_);
        if (!value) return false;
        const symbolic::SampledFunction other(*value);
        if (same(R_, other) || !same(A_, other)) return false;
        const bool modified = k_.scene.robot.convention == DhConvention::Modified;
        const Message standard = message(MessageId::HintConventionStandard), craig = message(MessageId::HintConventionModified);
        hint(Message(MessageId::HintConvention, {modified ? standard : craig, modified ? craig : standard}), AnswerErrorKind::Convention);
        return true;
    }

    bool christoffelIndices() {
        if (e_.kind != EntryKind::Christoffel && e_.kind != EntryKind::Coriolis) return false;
        const GiNaC::matrix B = GiNaC::ex_to<GiNaC::matrix>(k_.functions(k_.derivation.B));
        const std::vector<GiNaC::symbol>& q = k_.derivation.q;
        const int n = static_cast<int>(q.size());
        std::array<int, 3> order{0, 1, 2};
        do {
            for (int signs = 0; signs < 8; ++signs) {
                const std::array<int, 3> s{signs & 1 ? -1 : 1, signs & 2 ? -1 : 1, signs & 4 ? 1 : -1};
                auto symbol = [&](int i, int j, int k) {
                    const std::array<int, 3> idx{i, j, k};
                    return christoffel(B, q, idx[order[0]], idx[order[1]], idx[order[2]], s);
                };
                ex variant;
                if (e_.kind == EntryKind::Christoffel) {
                    variant = symbol(e_.i, e_.j, e_.k);
                } else {
                    variant = 0;
                    for (int k = 0; k < n; ++k) variant += symbol(e_.i, e_.j, k) * k_.derivation.qd[k];
                }
                const symbolic::SampledFunction v(variant);
                if (same(R_, v)) continue;
                if (same(A_, v)) {
                    hint(message(MessageId::HintChristoffelIndex), AnswerErrorKind::ChristoffelIndex);
                    return true;
                }
            }
        } while (std::next_permutation(order.begin(), order.end()));
        return false;
    }

    // ---- by link ------------------------------------------------------------------------------

    std::vector<GiNaC::symbol> inertial(int except = -1) const {
        std::vector<GiNaC::symbol> all;
        for (std::size_t i = 0; i < k_.links.size(); ++i)
            if (static_cast<int>(i) != except) {
                all.insert(all.end(), k_.links[i].mass.begin(), k_.links[i].mass.end());
                all.insert(all.end(), k_.links[i].inertia.begin(), k_.links[i].inertia.end());
            }
        return all;
    }
    // Link i's part of a sum over links: with the other links' masses and inertias zero,
    // less what is left with every link's zero (a motor's armature, numbers); `alsoZero`
    // takes one kind of its own terms away (its inertia: the translational term).
    symbolic::Combination part(int link, const std::vector<GiNaC::symbol>& alsoZero = {}) const {
        symbolic::MaskedValue with{1, inertial(link), {}}, without{-1, inertial(), {}};
        with.zeros.insert(with.zeros.end(), alsoZero.begin(), alsoZero.end());
        return {with, without};
    }
    symbolic::Combination rest() const { return {symbolic::MaskedValue{1, inertial(), {}}}; }

    bool perLinkSum() const {
        switch (e_.kind) {
            case EntryKind::MassMatrix:
            case EntryKind::Coriolis:
            case EntryKind::Christoffel:
            case EntryKind::Gravity:
            case EntryKind::KineticEnergy:
            case EntryKind::PotentialEnergy:
            case EntryKind::Equation: return true;
            case EntryKind::LinkPart: return e_.k >= 0;  // β_jk⁽ⁱ⁾: link i's part alone, its terms told apart the same way
            default: return false;
        }
    }

    void links() {
        if (k_.links.empty() || !perLinkSum() || inertial().empty()) return;
        std::vector<int> wrong, rightLinks;
        const symbolic::SampledFunction zero{ex(0)};
        for (std::size_t i = 0; i < k_.links.size(); ++i) {
            if (k_.links[i].mass.empty() && k_.links[i].inertia.empty()) continue;
            const symbolic::Combination its = part(static_cast<int>(i));
            if (same(A_, R_, its)) {
                if (!same(R_, its, zero, {})) rightLinks.push_back(static_cast<int>(i));
            } else {
                wrong.push_back(static_cast<int>(i));
            }
        }
        if (lengthSwap()) return;
        auto list = [](const std::vector<int>& links) {
            std::string s;
            for (int l : links) s += (s.empty() ? "" : ", ") + std::to_string(l + 1);
            return s;
        };
        if (!wrong.empty()) {
            for (int l : wrong) out_.links.push_back(l + 1);
            auto named = [&](const std::vector<int>& links) {
                return message(links.size() == 1 ? MessageId::HintLinkOne : MessageId::HintLinkMany, list(links));
            };
            const bool one = wrong.size() == 1;
            if (rightLinks.empty())
                hint(Message(one ? MessageId::HintLinkWrong : MessageId::HintLinksWrong, {named(wrong)}), AnswerErrorKind::Link);
            else
                hint(Message(one ? MessageId::HintLinkWrongRight : MessageId::HintLinksWrongRight, {named(wrong), named(rightLinks)}),
                     AnswerErrorKind::Link);
            for (std::size_t w = 0; w < wrong.size() && w < 2; ++w) withinLink(wrong[w]);
        }
        if (!wrong.empty() && !same(A_, R_, rest())) hint(message(MessageId::HintOtherTermsWrong));
    }

    // A link length where a centre-of-mass distance belongs (or the reverse), the same
    // link's: ℓc2 for a2 or a2 for ℓc2, everywhere in the answer.
    bool lengthSwap() {
        for (std::size_t i = 0; i < k_.links.size(); ++i)
            for (const GiNaC::symbol& c : k_.links[i].com)
                for (const GiNaC::symbol& l : k_.links[i].lengths)
                    for (int direction = 0; direction < 2; ++direction) {
                        const GiNaC::symbol& from = direction == 0 ? c : l;
                        const GiNaC::symbol& to = direction == 0 ? l : c;
                        if (!right_.has(from)) continue;
                        // the right answer with `to` written for `from`: R at points where from has to's value
                        const symbolic::Combination swapped{symbolic::MaskedValue{1, {}, {{from, to}}}};
                        if (same(R_, swapped, R_, {}) || !same(A_, {}, R_, swapped)) continue;
                        hint(message(MessageId::HintLength, text(to), text(from)), AnswerErrorKind::Length);
                        return true;
                    }
        return false;
    }

    // Link i's rotational part with its inertia tensor left in the link's frame: b_jk's and
    // E_kin's ωᵀIω term written with I_li in place of I_li^0.
    std::optional<ex> unrotated(int link) const {
        if (e_.kind != EntryKind::MassMatrix && e_.kind != EntryKind::KineticEnergy) return std::nullopt;
        const ex* jw = k_.itemValue(k_.derivation, symbolic::Quantity::AngularJacobian, link);
        const ex* t = k_.itemValue(k_.derivation, symbolic::Quantity::Transform, link);
        const ex* i0 = k_.itemValue(k_.derivation, symbolic::Quantity::LinkInertia, link);
        if (!jw || !t || !i0) return std::nullopt;
        const GiNaC::matrix J = GiNaC::ex_to<GiNaC::matrix>(k_.functions(*jw));
        const GiNaC::matrix T = GiNaC::ex_to<GiNaC::matrix>(k_.functions(*t));
        const GiNaC::matrix I0 = GiNaC::ex_to<GiNaC::matrix>(k_.functions(*i0));
        GiNaC::matrix rotation(3, 3);  // R_i^0: the top-left 3×3 of T_i^0
        for (unsigned r = 0; r < 3; ++r)
            for (unsigned c = 0; c < 3; ++c) rotation(r, c) = T(r, c);
        const GiNaC::matrix local = rotation.transpose().mul(I0).mul(rotation);
        // b_rs's rotational term of this link: J_ω[:, r]ᵀ I J_ω[:, s], with I0 (right) and I (left in its frame)
        auto term = [&](const GiNaC::matrix& inertia, unsigned r, unsigned s) {
            ex sum = 0;
            for (unsigned a = 0; a < 3; ++a)
                for (unsigned b = 0; b < 3; ++b) sum += J(a, r) * inertia(a, b) * J(b, s);
            return sum;
        };
        if (e_.kind == EntryKind::MassMatrix) return right_ - term(I0, e_.i, e_.j) + term(local, e_.i, e_.j);
        ex quadratic = 0;
        const auto& qd = k_.derivation.qd;
        for (unsigned r = 0; r < qd.size(); ++r)
            for (unsigned s = 0; s < qd.size(); ++s) quadratic += qd[r] * (term(local, r, s) - term(I0, r, s)) * qd[s];
        return right_ + GiNaC::numeric(1, 2) * quadratic;
    }

    void withinLink(int link) {
        const LinkRoles& roles = k_.links[link];
        if (auto variant = unrotated(link)) {
            const symbolic::SampledFunction v(*variant);
            if (!same(R_, v) && same(A_, v)) {
                hint(message(MessageId::HintNotRotated, link + 1), AnswerErrorKind::Rotation);
                return;
            }
        }
        if (roles.mass.empty() || roles.inertia.empty()) return;
        const symbolic::Combination translational = part(link, roles.inertia), rotational = part(link, roles.mass);
        const bool translationalWrong = !same(A_, R_, translational);
        const bool rotationalWrong = !same(A_, R_, rotational);
        if (translationalWrong && !rotationalWrong) {
            // a difference in the translational term that no coordinate changes: a parallel-axis slip
            const symbolic::SampledFunction difference(answer_ - right_);
            bool constant = true;
            for (const GiNaC::symbol& q : k_.derivation.q)
                constant = constant && !symbolic::dependsOn(difference, q, sampler_, translational);
            if (constant && e_.kind != EntryKind::Gravity && e_.kind != EntryKind::PotentialEnergy)
                hint(message(MessageId::HintSteiner, link + 1), AnswerErrorKind::Steiner);
            else hint(message(MessageId::HintTranslational, link + 1), AnswerErrorKind::Translational);
        } else if (rotationalWrong && !translationalWrong) {
            hint(message(MessageId::HintRotational, link + 1), AnswerErrorKind::RotationalTerm);
        }
    }

    // ---- what it depends on ------------------------------------------------------------------

    void coordinates() {
        const symbolic::Derivation& d = k_.derivation;
        auto name = [&](int i, int dots) { return present::textCoordinateName(d.coordinateNames[i], dots); };
        for (std::size_t i = 0; i < d.q.size(); ++i) {
            const bool theirs = symbolic::dependsOn(R_, d.q[i], sampler_), mine = symbolic::dependsOn(A_, d.q[i], sampler_);
            if (theirs == mine) continue;
            hint(message(theirs ? MessageId::HintDependsNot : MessageId::HintDependsExtra, e_.id, name(static_cast<int>(i), 0)),
                 AnswerErrorKind::Coordinates);
            return;
        }
        std::string theirs, mine;
        for (std::size_t i = 0; i < d.qd.size(); ++i) {
            if (symbolic::dependsOn(R_, d.qd[i], sampler_)) theirs += (theirs.empty() ? "" : ", ") + name(static_cast<int>(i), 1);
            if (symbolic::dependsOn(A_, d.qd[i], sampler_)) mine += (mine.empty() ? "" : ", ") + name(static_cast<int>(i), 1);
        }
        if (theirs != mine)
            hint(message(MessageId::HintVelocities, e_.id, theirs.empty() ? "–" : theirs, mine.empty() ? "–" : mine),
                 AnswerErrorKind::Coordinates);
    }

    void homePose() {
        if (k_.derivation.system != symbolic::SystemKind::Robot) return;
        if (symbolic::sameWhere(A_, R_, k_.derivation.q, sampler_)) hint(message(MessageId::HintHomePose), AnswerErrorKind::HomePose);
    }

    const AnswerKey::Data& k_;
    const KeyEntry& e_;
    const ex answer_, right_;
    const symbolic::SampledFunction A_, R_;  // the two, made ready for sampling once
    AnswerCheck& out_;
    symbolic::IdentitySampler sampler_;
};

}  // namespace

void explainWrongAnswer(const AnswerKey::Data& key, const KeyEntry& entry, const ex& answer, AnswerCheck& check) {
    Explainer(key, entry, answer, check).explain();
}

}  // namespace ll
