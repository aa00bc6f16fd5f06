#include "ui/document/live_derivation.hpp"

#include "core/present/text_document.hpp"

#include <chrono>
#include <thread>

#include "core/model/cancellation.hpp"
#include "core/model/diagnostics.hpp"
#include "core/present/diagnostic_text.hpp"
#include "ui/document/app_language.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_derivation.hpp"

namespace ll::ui {

LiveDerivation::LiveDerivation(QObject* parent) : QObject(parent) { pool_.setMaxThreadCount(1); }

LiveDerivation::~LiveDerivation() {
    work_.cancel();
    pool_.waitForDone();
}

void LiveDerivation::cancel() {
    if (busy()) {
        work_.cancel();
        stopped_ = true;
    }
}

void LiveDerivation::resume() {
    if (stopped_ && scene_) request(*scene_);
}

void LiveDerivation::request(const Scene& scene) {
    const int request = work_.request();
    NewestWins::Flag cancel = work_.begin();
    scene_ = std::make_shared<const Scene>(scene);
    stopped_ = false;
    ++runs_;
    emit started(request);
    pool_.start(
        [self = this, scene = scene_, request, cancel, delay = std::chrono::milliseconds(startDelayMs_), language = windowLanguage()] {
            const auto begin = std::chrono::steady_clock::now();
            auto result = std::make_shared<DerivationResult>();
            result->request = request;
            result->scene = scene;
            try {
                while (std::chrono::steady_clock::now() - begin < delay) {
                    throwIfCancelled(cancel.get());
                    std::this_thread::sleep_for(std::chrono::milliseconds(2));
                }
                DocumentRequest r;
                r.format = present::DocumentFormat::Display;
                r.cancel = cancel.get();
                r.catalogue = true;  // the entries a student can pick, with what feeds them
                // The form `derive --form auto` picks: expanded when cheap, else structured (the
                // Panda's expanded B has thousands of terms of 15-digit products per entry).
                DerivedDocument derived = deriveDisplay(*scene, r);
                result->display = std::move(derived.display);
                result->catalogue = std::move(derived.catalogue);
                // Text from the same trees, outside the GiNaC lock.
                result->text = QString::fromStdString(present::textDocument(*result->display, &result->textSpans));
            } catch (const Cancelled&) {
                result->stopped = true;
            } catch (const InputError& e) {
                for (const Diagnostic& d : e.diagnostics())
                    result->error += QString::fromStdString(present::diagnosticBody(d, language) + "\n");
            } catch (const std::exception& e) {
                result->error = QString::fromStdString(e.what());
            }
            result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            self->work_.deliver(request, [self, result] {  // dropped when a newer scene is deriving
                self->delivered_ = result->request;
                emit self->finished(result);
            });
        });
}

}  // namespace ll::ui
