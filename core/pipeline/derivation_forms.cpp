#include "core/pipeline/derivation_forms.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/symbolic/derivation_evaluator.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/present/latex_text.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/present/message_text.hpp"
#include "core/present/structured_control_law.hpp"
#include "core/present/structured_document.hpp"
#include "core/present/text_document.hpp"
#include "core/present/latex_document.hpp"

namespace ll {
namespace {

bool multipleOfHalfPi(double angle) {
    const double k = angle / (std::numbers::pi / 2);
    return std::abs(k - std::round(k)) < 1e-12;
}

struct Triple {
    Eigen::MatrixXd B, C;
    Eigen::MatrixXd g;
};

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

double largest(const Triple& a, const Triple& b) { return std::max({relative(a.B, b.B), relative(a.C, b.C), relative(a.g, b.g)}); }

std::string verificationLine(const std::string& what, double error, int states) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "%s: largest relative difference %.2e in B, C, g (%d random states)", what.c_str(), error, states);
    return buffer;
}

}  // namespace

bool expandedIsCheap(const Scene& scene, Message& reason) {
    const int n = scene.robot.dof();
    int general = 0, generalAngles = 0, offAxis = 0;
    for (const Joint& j : scene.robot.joints) {
        if (!multipleOfHalfPi(j.dh.alpha) || !multipleOfHalfPi(j.dh.theta)) ++general;
        generalAngles += !multipleOfHalfPi(j.dh.alpha) + !multipleOfHalfPi(j.dh.theta);
        if (j.dh.a != 0.0 && j.dh.d != 0.0) ++offAxis;
    }
    // Each constant angle that is not a multiple of π/2 multiplies the expanded terms: a
    // 3-joint arm with 6 of them took 40 s and 360 MB expanded (0.1 s structured).
    if (n <= 2 || (n <= 4 && generalAngles <= 3)) {
        reason = message(MessageId::FormCheap, message(MessageId::FormJoints, n));
        return true;
    }
    if (n <= 6 && general == 0 && offAxis <= 1) {
        reason = message(MessageId::FormCheap, message(MessageId::FormJointsRightAngles, n));
        return true;
    }
    reason = message(MessageId::FormGrows, n > 6         ? message(MessageId::FormJoints, n)
                                           : general > 0 ? message(MessageId::FormJointsGeneralAngles, n, generalAngles)
                                                         : message(MessageId::FormJointsOffAxis, n));
    return false;
}

// The structured form's text or LaTeX with its step 9 (the control law over step 8's entries
// by name, core/present/structured_control_law) put in before the document's end: the step
// written by the display documents' own writers, cut from its heading to its end.
std::string withControlLaw(std::string document, const Scene& scene, const symbolic::StructuredDynamics& s, const DocumentRequest& request) {
    using present::DocumentFormat;
    if (!scene.effects.control || request.firstStep > symbolic::controlStepNumber || request.lastStep < symbolic::controlStepNumber ||
        (request.format != DocumentFormat::Text && request.format != DocumentFormat::Latex))
        return document;
    present::DisplayDocument law;
    law.systemName = s.systemName;
    law.robot = true;
    for (int i = 0; i < s.n; ++i) law.coordinateNames.push_back("q" + std::to_string(i + 1));
    law.steps.push_back(present::structuredControlStep(scene, s));
    const auto shown = present::localizedDocument(law, request.presentation);
    const present::Language l = request.presentation.language;
    const bool text = request.format == DocumentFormat::Text;
    const std::string written = text ? present::textDocument(*shown) : present::latexDocument(*shown);
    const std::string step = present::messageText(MessageId::DocumentStep, l) + " " + std::to_string(symbolic::controlStepNumber);
    const std::size_t from = written.find(text ? "\n" + step + ". " : "\\section*{" + step + ": ");
    const std::size_t to = written.rfind(text ? "\n" + present::messageText(MessageId::DocumentActuation, l) + ":"
                                             : "\\paragraph{" + present::messageText(MessageId::DocumentActuation, l) + "}");
    if (from == std::string::npos || to == std::string::npos || to < from) return document;
    const std::string part = written.substr(from, to - from);
    const std::size_t end = text ? std::string::npos : document.rfind("\\end{document}");
    if (end == std::string::npos) return document + part;
    return document.insert(end, part + "\n");
}

Message formName(DerivationForm form) {
    if (form == DerivationForm::Auto) return {};
    return form == DerivationForm::Expanded ? MessageId::FormExpanded : MessageId::FormStructured;
}

FormDocument deriveInForm(const Scene& scene, const FormRequest& request) {
    using namespace symbolic;
    using namespace present;
    FormDocument out;
    if (scene.lagrangian) {
        out.form = DerivationForm::Expanded;
        out.reason = MessageId::FormTypedLagrangian;
        DocumentRequest document = request.document;
        document.form = {formName(out.form), out.reason};
        out.derived = deriveDocument(scene, document);
        return out;
    }
    Message cheapReason;
    const bool cheap = expandedIsCheap(scene, cheapReason);
    const bool expanded = request.form == DerivationForm::Expanded || (request.form == DerivationForm::Auto && cheap);
    out.reason = request.form == DerivationForm::Auto ? message(MessageId::FormAuto, cheapReason) : Message(MessageId::FormAskedFor);
    const int n = scene.robot.dof();
    std::vector<EntryRef> entries;
    for (const std::string& e : request.entries) entries.push_back(parseEntry(e, n));

    const auto lock = lockGinac();
    const bool needStructured = !expanded || !entries.empty() || request.verify;
    std::shared_ptr<StructuredDynamics> structured;
    if (needStructured) {
        DerivationOptions options;
        options.mode = request.document.mode;
        options.progress = request.document.progress;
        options.cancel = request.document.cancel;
        structured = std::make_shared<StructuredDynamics>(deriveStructured(scene, options));
        out.definitions = structured->table->size();
    }
    if (expanded && entries.empty()) {
        out.form = DerivationForm::Expanded;
        DocumentRequest document = request.document;
        document.form = {formName(out.form), out.reason};
        out.derived = deriveDocument(scene, document);
    } else {
        // With --entry and the expanded form, the document is the entries expanded (and
        // the names of the structured form they come from): its form is "expanded".
        out.form = expanded ? DerivationForm::Expanded : DerivationForm::Structured;
        StructuredDocumentInfo info;
        info.modeName = modeName(request.document.mode);
        info.form = formName(out.form);
        info.formReason = expanded ? message(MessageId::FormOnlyEntriesExpanded, out.reason) : out.reason;
        info.entries = entries;
        info.firstStep = request.document.firstStep;
        info.language = request.document.presentation.language;
        info.lastStep = request.document.lastStep;
        if (request.form != DerivationForm::Structured)
            for (const EntryRef& e : entries) info.expanded.push_back(expandEntry(*structured, e, request.document.cancel));
        throwIfCancelled(request.document.cancel);
        const auto printing = std::chrono::steady_clock::now();
        out.derived.document = withControlLaw(structuredDocument(*structured, request.document.format, info), scene, *structured, request.document);
        out.derived.printSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - printing).count();
        out.derived.timings.push_back({0, "structured derivation (steps 1-8)", structured->seconds});
    }

    if (request.verify) {
        const RobotModel& robot = scene.robot;
        std::mt19937 rng(4242);
        std::uniform_real_distribution<double> u(-2.0, 2.0);
        const int states = 3;
        double structuredError = 0, expandedError = 0;
        std::optional<Derivation> full;
        if (cheap || out.form == DerivationForm::Expanded) {
            DerivationOptions options;
            options.mode = request.document.mode;
            options.cancel = request.document.cancel;
            full = deriveRobot(scene, options);
        }
        for (int k = 0; k < states; ++k) {
            Eigen::VectorXd q(n), qd(n);
            for (int i = 0; i < n; ++i) {
                q[i] = u(rng);
                qd[i] = u(rng);
            }
            RobotData data(robot);
            forwardKinematics(robot, data, q);
            computeMassMatrix(robot, data);
            computeCoriolisMatrix(robot, data, qd);
            computePotentialGradient(robot, data, scene.effects, q);
            const Triple numeric{data.B, data.C, data.g};
            const DefinitionValues v(*structured->table,
                                     structuredInputs(*structured, {q.data(), q.data() + n}, {qd.data(), qd.data() + n}));
            Triple s{Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, n), Eigen::MatrixXd(n, 1)};
            for (int i = 0; i < n; ++i) {
                s.g(i, 0) = v(structured->g(i, 0));
                for (int j = 0; j < n; ++j) {
                    s.B(i, j) = v(structured->B(i, j));
                    s.C(i, j) = v(structured->C(i, j));
                }
            }
            structuredError = std::max(structuredError, largest(s, numeric));
            if (full) {
                const DerivationEvaluator eval(*full);
                const Triple e{eval.value(full->B, q, qd), eval.value(full->C, q, qd), eval.value(full->g, q, qd)};
                expandedError = std::max(expandedError, largest(e, numeric));
            }
        }
        out.verification.push_back(verificationLine("structured vs numeric core", structuredError, states));
        if (full) out.verification.push_back(verificationLine("expanded vs numeric core", expandedError, states));
        else out.verification.push_back("expanded: not derived (" + cheapReason.english() + ")");
        if (structured)
            out.verification.push_back(std::string("Bdot - 2C skew-symmetric over the names: ") +
                                       (skewSymmetric(*structured) ? "yes" : "NO"));
    }
    return out;
}

}  // namespace ll
