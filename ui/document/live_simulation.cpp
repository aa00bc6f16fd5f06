#include "ui/document/live_simulation.hpp"

#include <chrono>
#include <optional>

#include "core/model/diagnostics.hpp"
#include "core/present/diagnostic_text.hpp"
#include "core/present/message_text.hpp"
#include "ui/document/app_language.hpp"
#include "core/pipeline/scene_simulation.hpp"

namespace ll::ui {

LiveSimulation::LiveSimulation(QObject* parent) : QObject(parent) {
    debounce_.setSingleShot(true);
    debounce_.setInterval(15);
    connect(&debounce_, &QTimer::timeout, this, &LiveSimulation::start);
    pool_.setMaxThreadCount(2);
}

LiveSimulation::~LiveSimulation() {
    work_.cancel();
    pool_.waitForDone();
}

void LiveSimulation::request(const Scene& scene) {
    pending_ = std::make_shared<const Scene>(scene);
    work_.request();
    // Leading edge: the first edit after a pause starts at once; edits coming faster than
    // the interval wait for the last of them.
    if (!debounce_.isActive() && (!lastStart_.isValid() || lastStart_.elapsed() >= debounce_.interval())) {
        start();
        return;
    }
    debounce_.start();
}

void LiveSimulation::requestNow(const Scene& scene) {
    pending_ = std::make_shared<const Scene>(scene);
    work_.request();
    debounce_.stop();
    start();
}

void LiveSimulation::start() {
    if (!pending_) return;
    lastStart_.start();
    NewestWins::Flag cancel = work_.begin();  // the previous run's result would be dropped anyway
    auto scene = std::move(pending_);
    pending_.reset();
    const int request = work_.newest();
    const SimulationSettings settings = override_.value_or(scene->simulation);
    pool_.start([self = this, scene, settings, request, cancel, analysing = analysing_, language = windowLanguage()] {
        const auto begin = std::chrono::steady_clock::now();
        auto result = std::make_shared<LiveResult>();
        result->request = request;
        result->scene = scene;
        std::optional<SimulationInput> input;
        try {
            PreparedScene prepared = prepareScene(*scene);  // the scene's expressions compiled once
            input = std::move(prepared.simulation);
            result->simulation = ll::simulate(*input, settings, {}, cancel.get());
            if (cancel->load()) return;
            result->visual = std::make_shared<VisualScene>(*scene, std::move(prepared.bodies));
            if (result->simulation.trajectory.size() > 0) result->visual->fitToMotion(result->simulation.trajectory);
            if (result->simulation.status == SimulationStatus::Failed)
                result->error = present::messageText(result->simulation.message, language);
        } catch (const InputError& e) {
            for (const Diagnostic& d : e.diagnostics()) result->error += present::diagnosticBody(d, language) + "\n";
        } catch (const std::exception& e) {
            result->error = present::errorText(e, language);
        }
        if (cancel->load()) return;
        result->workerSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        self->work_.deliver(request, [self, result] {  // dropped when a newer edit came
            self->delivered_ = result->request;
            emit self->finished(result);
        });
        if (!analysing || !input || result->simulation.trajectory.size() == 0) return;
        auto analysis = std::make_shared<RunAnalysis>();
        analysis->request = request;
        try {
            analysis->torques = std::make_shared<const TorqueHistory>(torqueHistory(*input, result->simulation.trajectory));
            if (cancel->load()) return;
            if (!scene->lagrangian && scene->effects.control)
                analysis->control = std::make_shared<const ControlHistory>(controlHistory(*input, result->simulation.trajectory, *analysis->torques));
            analysis->properties = std::make_shared<const ModelProperties>(checkModelProperties(*input, result->simulation.trajectory));
        } catch (const std::exception& e) {
            analysis->error = present::errorText(e, language);
        }
        if (cancel->load()) return;
        self->work_.deliver(request, [self, analysis] { emit self->analysed(analysis); });
    });
}

}  // namespace ll::ui
