#pragma once
// Interim derivation pane of the window: deriveDocument's text output (steps 0–8) in a
// read-only text view, derived in its own worker thread (GiNaC under its lock, the
// previous derivation cancelled when a newer scene arrives). It has the API of the
// typeset ll::ui::DerivationView (issue 10), so the window can swap one for the other.
#include <atomic>
#include <memory>

#include <QThreadPool>
#include <QWidget>

#include "core/model/scene.hpp"

class QPlainTextEdit;
class QLabel;

namespace ll::ui {

class DerivationPanel : public QWidget {
    Q_OBJECT
public:
    explicit DerivationPanel(QWidget* parent = nullptr);
    ~DerivationPanel() override;

    // Derives `scene` (copied) in the worker; the text is replaced when it is done.
    void setScene(const ll::Scene& scene);
    // Scrolls to step n (0..8) of the current text.
    void showStep(int n);
    int step() const { return step_; }
    void setZoom(double factor);

    // Stops the running derivation (its scene is stale: an edit is being checked). Not in
    // DerivationView's API: the window calls it so a derivation holding the GiNaC lock
    // does not hold up the check of the next edit.
    void cancel();

    // What is shown (tests), and whether a derivation is still running.
    QString text() const;
    bool busy() const { return delivered_ < requested_; }

public slots:
    void nextStep() { showStep(step_ + 1); }
    void previousStep() { showStep(step_ - 1); }

signals:
    void stepChanged(int step);
    // A derivation finished and is shown.
    void derived();

private:
    QPlainTextEdit* view_;
    QLabel* status_;
    QThreadPool pool_;
    std::shared_ptr<std::atomic<bool>> cancel_;
    int requested_ = 0, delivered_ = 0;
    int step_ = 0;
    double baseFont_ = 10.0;
};

}  // namespace ll::ui
