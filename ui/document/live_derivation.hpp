#pragma once
// Re-derivation after every valid edit, off the GUI thread, once for every view of it:
// request(scene) copies the scene to one worker, cancels the derivation before it (one
// cancel token), and derives the display trees (core/present/derivation_document) under
// the GiNaC lock; the worker then renders the plain text from those trees (no GiNaC).
// The result comes back through a queued call as plain data shared by the typeset view
// and the text panel, so an edit costs one derivation whatever the tabs show. The form is
// the one `derive --form auto` picks (core/pipeline/display_derivation): the structured
// form for large robots such as the Panda. Results
// older than the newest request are dropped: the newest edit wins.
#include <atomic>
#include <memory>
#include <string>

#include <QObject>
#include <QString>

#include "core/model/scene.hpp"
#include "core/pipeline/entry_catalogue.hpp"
#include "core/present/derivation_document.hpp"
#include "core/present/text_document.hpp"
#include "ui/document/newest_wins.hpp"
#include "ui/document/work_pool.hpp"

namespace ll::ui {

struct DerivationResult {
    int request = 0;                                          // which request this answers
    std::shared_ptr<const present::DisplayDocument> display;  // the steps as display trees
    std::shared_ptr<const EntryCatalogue> catalogue;          // its entries, traced and compiled
    QString text;                                             // the same steps as plain text
    std::vector<present::TextSpan> textSpans;                 // where each item and entry stands in it
    std::shared_ptr<const Scene> scene;                       // the scene derived
    QString error;                                            // why there is no derivation
    bool stopped = false;                                     // cancelled for an edit being checked
    double seconds = 0.0;                                     // wall time in the worker
};

class LiveDerivation : public QObject {
    Q_OBJECT
public:
    explicit LiveDerivation(QObject* parent = nullptr);
    ~LiveDerivation() override;

    // Derives `scene` (copied) now; a running derivation of an older scene is cancelled.
    void request(const Scene& scene);
    // Stops the running derivation (an edit is being checked and needs the GiNaC lock);
    // its scene is kept, and resume() derives it again unless a newer request came.
    void cancel();
    void resume();

    int latestRequest() const { return work_.newest(); }
    bool busy() const { return delivered_ < work_.newest(); }
    // Derivations started since construction (each one deriveDocument call).
    int runs() const { return runs_; }
    // Blocks until the worker has finished (tests, shutdown).
    void wait() { pool_.waitForDone(); }
    // Tests: every derivation waits this long before it starts (cancellable), so a test can
    // type its next edit while one is surely running, whatever the machine's speed.
    void setStartDelay(int milliseconds) { startDelayMs_ = milliseconds; }

signals:
    void started(int request);
    void finished(std::shared_ptr<const ll::ui::DerivationResult> result);

private:
    WorkPool pool_;
    std::shared_ptr<const Scene> scene_;  // the newest requested scene
    NewestWins work_;
    bool stopped_ = false;  // the newest request was cancelled before it finished
    int delivered_ = 0, runs_ = 0;
    int startDelayMs_ = 0;
};

}  // namespace ll::ui
