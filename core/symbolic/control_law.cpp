#include "core/symbolic/control_law.hpp"

#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/model/one_based.hpp"
#include "core/simulation/controller.hpp"
#include "core/symbolic/exact_numbers.hpp"

namespace ll::symbolic {
namespace {

using GiNaC::ex;
using GiNaC::matrix;
using GiNaC::symbol;

// A formula built piece by piece in both styles, the words as numbered inserts.
struct FormulaBuilder {
    std::string text, latex;
    std::vector<FormulaPiece> textInserts, latexInserts;

    void add(const std::string& t, const std::string& l) {
        text += t;
        latex += l;
    }
    void words(MessageId id, const std::vector<std::string>& textArgs, const std::vector<std::string>& latexArgs) {
        textInserts.push_back(formulaWords(id, textArgs));
        latexInserts.push_back(formulaWords(id, latexArgs));
        const std::string mark = "«" + std::to_string(textInserts.size()) + "»";
        add(mark, mark);
    }
    StepFormula formula() const { return stepFormula(text, latex, textInserts, latexInserts); }
};

// The joint pair's indices as the derivation writes them: 12, or 9_10 from ten joints on.
std::string pairIndex(int i, int j, int n) { return idx(i) + (n >= 10 ? "_" : "") + idx(j); }

Message title(ControlLaw law) {
    switch (law) {
        case ControlLaw::Pd: return MessageId::TitleControlPd;
        case ControlLaw::PdGravity: return MessageId::TitleControlPdGravity;
        case ControlLaw::ComputedTorque: return MessageId::TitleControlComputedTorque;
        case ControlLaw::Feedforward: break;
    }
    return MessageId::TitleControlFeedforward;
}

// The driven joints' limits, "80, 40 N·m" (one unit after them when they share it, else
// "80 N·m, 40 N"); in LaTeX with \mathrm{N\,m}.
std::string limitsList(const Scene& scene, const Eigen::VectorXd& limits, const Control& control, bool latex) {
    std::vector<std::pair<std::string, bool>> shown;  // the number, revolute
    for (Eigen::Index i = 0; i < limits.size(); ++i) {
        if (!control.drives(static_cast<int>(i))) continue;
        std::ostringstream number;
        number << limits[i];
        shown.emplace_back(number.str(), scene.robot.joints[static_cast<std::size_t>(i)].dh.type == JointType::Revolute);
    }
    const auto unit = [&](bool revolute) {
        return revolute ? (latex ? R"(\ \mathrm{N\,m})" : " N·m") : (latex ? R"(\ \mathrm{N})" : " N");
    };
    bool shared = true;
    for (const auto& s : shown) shared = shared && s.second == shown.front().second;
    std::string out;
    for (const auto& [number, revolute] : shown) out += (out.empty() ? "" : ", ") + number + (shared ? "" : unit(revolute));
    return shared && !shown.empty() ? out + unit(shown.front().second) : out;
}

}  // namespace

bool controllerModelIsScenes(const ControllerModel& model) {
    return model.links.empty() && model.payloadMass == 0.0 && (model.scale.size() == 0 || (model.scale.array() == 1.0).all());
}

DerivationStep controlLawStep(const Scene& scene, const Derivation& d, const std::function<ex(const ex&)>& reduce) {
    const int n = static_cast<int>(d.q.size());
    // The gains as the controller uses them (from wn and zeta when the scene gives those).
    const Controller controller(scene.robot, scene.effects);
    const Control& control = controller.control();
    const ControlLaw law = control.law;
    const bool conservative = scene.effects.gravity || !scene.effects.springs.empty();
    const bool exact = controllerModelIsScenes(control.model) && law != ControlLaw::Feedforward;

    std::vector<symbol> e, ed, edd, qRef, qdRef, qddRef;
    for (int i = 0; i < n; ++i) {
        e.emplace_back("e" + idx(i));
        ed.emplace_back("e" + idx(i) + "_dot");
        edd.emplace_back("e" + idx(i) + "_ddot");
        qRef.emplace_back("q_d" + idx(i));
        qdRef.emplace_back("q_d" + idx(i) + "_dot");
        qddRef.emplace_back("q_d" + idx(i) + "_ddot");
    }
    // The controller's B̂, Ĉ, ĝ: the derived ones, or its own as named symbols.
    matrix Bh(n, n), Ch(n, n), gh(n, 1);
    for (int i = 0; i < n; ++i) {
        gh(i, 0) = exact ? d.g(i, 0) : conservative ? ex(symbol("g" + idx(i) + "_hat")) : ex(0);
        for (int j = 0; j < n; ++j) {
            Ch(i, j) = exact ? d.C(i, j) : ex(symbol("c" + pairIndex(i, j, n) + "_hat"));
            Bh(i, j) = exact ? d.B(i, j) : j < i ? Bh(j, i) : ex(symbol("b" + pairIndex(i, j, n) + "_hat"));
        }
    }
    matrix Kp(n, n), Kd(n, n);
    for (int i = 0; i < n; ++i)
        if (control.drives(i)) {
            Kp(i, i) = exactNumber(control.kp[i]);
            Kd(i, i) = exactNumber(control.kd[i]);
        }
    // τ = τ_model + τ_feedback: what the model supplies, and what acts on the error; each
    // τ_i also as the textbook writes it, a sum of parts (b_ij (q̈_dj + K_p,j e_j + K_d,j ė_j), …).
    matrix tauModel(n, 1), tauFeedback(n, 1);
    std::vector<std::vector<ItemPart>> tauParts(n);
    for (int i = 0; i < n; ++i) {
        if (!control.drives(i)) continue;
        const ex pd = Kp(i, i) * e[i] + Kd(i, i) * ed[i];
        std::vector<ItemPart>& parts = tauParts[i];
        ex coriolis = 0;
        switch (law) {
            case ControlLaw::Pd:
                tauFeedback(i, 0) = pd;
                parts = {{pd}};
                break;
            case ControlLaw::PdGravity:
                tauModel(i, 0) = gh(i, 0);
                tauFeedback(i, 0) = pd;
                parts = {{pd}, {gh(i, 0)}};
                break;
            case ControlLaw::ComputedTorque:
                for (int j = 0; j < n; ++j) {
                    const ex commanded = qddRef[j] + Kp(j, j) * e[j] + Kd(j, j) * ed[j];
                    tauFeedback(i, 0) += Bh(i, j) * commanded;
                    parts.push_back({Bh(i, j), commanded});
                    coriolis += Ch(i, j) * d.qd[j];
                }
                tauModel(i, 0) = coriolis + gh(i, 0);
                parts.push_back({coriolis, 1, Grouping::Velocities});
                parts.push_back({gh(i, 0)});
                break;
            case ControlLaw::Feedforward:
                for (int j = 0; j < n; ++j) {
                    parts.push_back({Bh(i, j), qddRef[j]});
                    tauModel(i, 0) += Bh(i, j) * qddRef[j];
                    coriolis += Ch(i, j) * qdRef[j];
                }
                tauModel(i, 0) += coriolis + gh(i, 0);
                tauFeedback(i, 0) = pd;
                parts.push_back({coriolis, 1, Grouping::Velocities});
                parts.push_back({gh(i, 0)});
                parts.push_back({pd});
                break;
        }
    }

    // The closed loop: B q̈ + C q̇ + g − τ_model = τ_feedback + Q, row by row, its left side
    // as the equation of motion's (B's row, C q̇, then what is left of g).
    bool otherForces = false;
    for (int i = 0; i < n; ++i) otherForces = otherForces || !d.Q(i, 0).is_zero();
    std::vector<ex> lhs(n);
    for (int i = 0; i < n; ++i) {
        lhs[i] = d.g(i, 0);
        for (int j = 0; j < n; ++j) lhs[i] += d.B(i, j) * d.qdd[j] + d.C(i, j) * d.qd[j];
    }
    std::vector<std::pair<std::vector<ItemPart>, ex>> rows;  // the left side's parts, the right side
    if (law == ControlLaw::ComputedTorque && exact) {
        // With q̈ = q̈_d − ë: B q̈ + C q̇ + g − τ = −B (ë + K_d ė + K_p e), checked here.
        GiNaC::lst errorAcceleration;
        for (int j = 0; j < n; ++j) errorAcceleration.append(d.qdd[j] == qddRef[j] - edd[j]);
        bool cancels = true;
        std::vector<ex> errorTerms(n);
        for (int j = 0; j < n; ++j) errorTerms[j] = edd[j] + Kd(j, j) * ed[j] + Kp(j, j) * e[j];
        for (int i = 0; i < n && cancels; ++i) {
            ex rest = (lhs[i] - tauModel(i, 0) - tauFeedback(i, 0)).subs(errorAcceleration);
            for (int j = 0; j < n; ++j) rest += d.B(i, j) * errorTerms[j];
            cancels = reduce(rest).is_zero();
        }
        if (cancels)
            for (int i = 0; i < n; ++i) {
                if (!otherForces) {
                    rows.push_back({{{edd[i]}, {Kd(i, i) * ed[i]}, {Kp(i, i) * e[i]}}, 0});
                } else {
                    std::vector<ItemPart> weighted;
                    for (int j = 0; j < n; ++j) weighted.push_back({d.B(i, j), errorTerms[j]});
                    rows.push_back({weighted, -d.Q(i, 0)});
                }
            }
    }
    if (rows.empty())
        for (int i = 0; i < n; ++i) {
            std::vector<ItemPart> parts;
            ex velocity = 0;
            for (int j = 0; j < n; ++j) {
                parts.push_back({d.B(i, j), d.qdd[j]});
                velocity += d.C(i, j) * d.qd[j];
            }
            parts.push_back({velocity, 1, Grouping::Velocities});
            parts.push_back({reduce(d.g(i, 0) - tauModel(i, 0))});  // g − ĝ (− Ĉ q̇ for computed torque)
            rows.push_back({parts, tauFeedback(i, 0) + d.Q(i, 0)});
        }
    const bool errorDynamics = law == ControlLaw::ComputedTorque && exact && !otherForces && rows.front().second.is_zero();

    const auto sumOf = [](const std::vector<ItemPart>& parts) {
        ex sum = 0;
        for (const ItemPart& p : parts) sum += p.coefficient * p.factor;
        return sum;
    };
    std::vector<DerivationItem> items{{"K_p", Quantity::ProportionalGain, -1, Grouping::Masses, Kp},
                                      {"K_d", Quantity::DerivativeGain, -1, Grouping::Masses, Kd}};
    for (int i = 0; i < n; ++i)
        items.push_back({"τ_" + idx(i), Quantity::ControlTorque, i, Grouping::Masses, sumOf(tauParts[i]), tauParts[i]});
    for (int i = 0; i < n; ++i)
        items.push_back({"closed_loop_" + idx(i), Quantity::ClosedLoop, i, Grouping::Masses, sumOf(rows[i].first) == rows[i].second,
                         rows[i].first});

    FormulaBuilder f;
    f.add("e = «q»_d − «q»,  ė = «q'»_d − «q'»;  ", R"(e = «q»_d - «q»,\ \dot{e} = «q'»_d - «q'»;\quad )");
    const std::string loop = "«B» «q''» + C «q'» + «g» = τ + «Q»", loopLatex = R"(«B»«q''» + C«q'» + «g» = \tau + «Q»)";
    switch (law) {
        case ControlLaw::Pd:
            f.add("τ = K_p e + K_d ė;  " + loop, R"(\tau = K_p e + K_d \dot{e};\quad )" + loopLatex);
            if (conservative) {
                f.add(";  ", R"(;\quad )");
                f.words(MessageId::FormulaControlSags, {"K_p e = «g»(«q»)"}, {R"(K_p e = «g»(«q»))"});
            }
            break;
        case ControlLaw::PdGravity:
            f.add("τ = K_p e + K_d ė + ĝ(«q»);  ", R"(\tau = K_p e + K_d \dot{e} + \hat{g}(«q»);\quad )");
            if (exact)
                f.words(MessageId::FormulaControlExactModel, {"ĝ = «g»", "«B» «q''» + C «q'» = K_p e + K_d ė + «Q»"},
                        {R"(\hat{g} = «g»)", R"(«B»«q''» + C«q'» = K_p e + K_d \dot{e} + «Q»)"});
            else
                f.words(MessageId::FormulaControlOwnModel, {"ĝ"}, {R"(\hat{g})"});
            break;
        case ControlLaw::ComputedTorque:
            f.add("τ = B̂(«q») («q''»_d + K_p e + K_d ė) + Ĉ(«q», «q'») «q'» + ĝ(«q»);  ",
                  R"(\tau = \hat{B}(«q»)\,(«q''»_d + K_p e + K_d \dot{e}) + \hat{C}(«q», «q'»)\,«q'» + \hat{g}(«q»);\quad )");
            if (exact)
                f.words(MessageId::FormulaControlExactModel, {"B̂ = «B», Ĉ = C, ĝ = «g»", "«B» (ë + K_d ė + K_p e) = −«Q»"},
                        {R"(\hat{B} = «B»,\ \hat{C} = C,\ \hat{g} = «g»)", R"(«B»\,(\ddot{e} + K_d \dot{e} + K_p e) = -«Q»)"});
            else
                f.words(MessageId::FormulaControlOwnModel, {"B̂, Ĉ, ĝ"}, {R"(\hat{B}, \hat{C}, \hat{g})"});
            if (errorDynamics) {
                f.add(";  ", R"(;\quad )");
                f.words(MessageId::FormulaControlErrorDynamics, {"ë + K_d ė + K_p e = 0"}, {R"(\,\ddot{e} + K_d \dot{e} + K_p e = 0)"});  // \, : the space the painted formula keeps
            }
            break;
        case ControlLaw::Feedforward:
            f.add("τ = B̂(«q»_d) «q''»_d + Ĉ(«q»_d, «q'»_d) «q'»_d + ĝ(«q»_d) + K_p e + K_d ė;  ",
                  R"(\tau = \hat{B}(«q»_d)\,«q''»_d + \hat{C}(«q»_d, «q'»_d)\,«q'»_d + \hat{g}(«q»_d) + K_p e + K_d \dot{e};\quad )");
            if (controllerModelIsScenes(control.model))
                f.words(MessageId::FormulaControlAtReference, {"B̂ = «B», Ĉ = C, ĝ = «g»", "«q»_d, «q'»_d"},
                        {R"(\hat{B} = «B»,\ \hat{C} = C,\ \hat{g} = «g»)", R"(«q»_d, «q'»_d)"});
            else
                f.words(MessageId::FormulaControlOwnModel, {"B̂, Ĉ, ĝ"}, {R"(\hat{B}, \hat{C}, \hat{g})"});
            break;
    }
    if (!control.joints.empty()) {
        std::string on;
        for (int j : control.joints) on += (on.empty() ? "«q_»" : ", «q_»") + idx(j);
        f.add(";  ", R"(;\quad )");
        f.words(MessageId::FormulaControlJoints, {on}, {on});
    }
    if (control.torqueLimit.size() == n) {
        f.add(";  ", R"(;\quad )");
        f.words(MessageId::FormulaControlLimits, {limitsList(scene, control.torqueLimit, control, false)},
                {limitsList(scene, control.torqueLimit, control, true)});
    }
    return {controlStepNumber, title(law), f.formula(), std::move(items), 0.0};
}

}  // namespace ll::symbolic
