#pragma once
// The derivation, step by step, typeset (ui/math_typesetter) for the desktop window:
// steps 0–8 listed, Previous/Next, the step's general formula and this system's results,
// each item collapsible, zoom, "Copy as LaTeX" on any item (context menu).
//
// setScene takes a copy and re-derives in a worker thread with the core's cancel token:
// the newest call wins, stale work is cancelled, and the result (plain display trees, no
// GiNaC) comes back through a queued call, so the window never waits on a large robot.
// Only the shown step is typeset, lazily and cached per zoom and width.
#include <QColor>
#include <QWidget>
#include <atomic>
#include <memory>
#include <vector>

#include "core/model/scene.hpp"
#include "ui/document/newest_wins.hpp"
#include "ui/document/work_pool.hpp"
#include "ui/paint/entry_mark.hpp"
#include "core/present/derivation_document.hpp"

class QBoxLayout;
class QListWidget;
class QResizeEvent;
class QPushButton;
class QLabel;
class QScrollArea;

namespace ll::ui {

class DerivationCanvas;

class DerivationView : public QWidget {
    Q_OBJECT

public:
    explicit DerivationView(QWidget* parent = nullptr);
    ~DerivationView() override;

    void setScene(const ll::Scene& scene);
    // A derivation run elsewhere (the window derives once per edit for all its views):
    // setDeriving marks one as started, setDerivation shows its document (or error) as
    // if this view had derived it. Either drops a derivation of this view's own.
    void setDeriving();
    void setDerivation(std::shared_ptr<const present::DisplayDocument> document, const QString& error = {});
    void showStep(int step);  // a listed step (poseStepNumber: the pose results); one the derivation has not: the next it has
    // The results at the teach pose (core/pipeline/pose_results) as step poseStepNumber,
    // listed after the derivation's steps; null takes it away (and leaves it for the last).
    void setPoseResults(std::shared_ptr<const present::DisplayStep> step);
    const present::DisplayStep* poseResults() const { return pose_.get(); }
    int step() const { return step_; }
    // The step list's rows as shown ("Step 6: Potential energy").
    QStringList listedSteps() const;
    // The page alone, without the step list, its buttons and status (presentation mode:
    // the page's heading names the step, the arrow keys turn it).
    void setPageOnly(bool on);
    void setZoom(double zoom);  // 1 = 15 px per em; clamped to 0.25..8
    double zoom() const { return zoom_; }
    // How far down the step's page is scrolled: 0 the top, 1 the bottom (a saved view).
    double scrollFraction() const;
    void setScrollFraction(double fraction);

    bool isDeriving() const { return deriving_; }
    QString errorText() const { return error_; }  // the last derivation's error, if any
    // The shown document (null before the first derivation finishes).
    std::shared_ptr<const present::DisplayDocument> document() const { return document_; }
    // The LaTeX of item `index` of the shown step ("b_{11} = …"): what Copy as LaTeX copies.
    QString itemLatex(int index) const;
    // Item `index`'s header (and the name in its Copy menu): b11, g(q), equation 1.
    QString itemTitle(int index) const;
    // Tinted backgrounds: the picked entry, a picked link's entries in its colour. Steps
    // are indices into the document's steps (−1: the pose results); row < 0 the whole item.
    using Mark = EntryMark;
    void setMarks(std::vector<Mark> marks);
    // Shows the step holding document step `stepIndex`'s items, scrolled to item `item`
    // (−1: where it is) or to its cell (row, col).
    void showDocumentStep(int stepIndex, int item = -1, int row = -1, int col = -1);

public slots:
    void nextStep();
    void previousStep();
    // Stops the running derivation (its result is dropped); the next setScene starts anew.
    void cancel();

signals:
    void stepChanged(int step);
    void derivationFinished();  // a new document (or error) is shown
    // A click on item `item` of document step `step` (−1: the pose results), on its cell
    // (row, col) of a matrix or on the item (−1, −1).
    void entryPicked(int step, int item, int row, int col);

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void accept(std::shared_ptr<const present::DisplayDocument> document, QString error);
    void refresh();
    void showStatus();

    QBoxLayout* layout_ = nullptr;
    QListWidget* steps_ = nullptr;
    QPushButton *previous_ = nullptr, *next_ = nullptr;
    QLabel* status_ = nullptr;
    QScrollArea* scroll_ = nullptr;
    DerivationCanvas* canvas_ = nullptr;
    std::shared_ptr<const present::DisplayDocument> document_;
    std::shared_ptr<const present::DisplayStep> pose_;
    present::DisplayStep poseWritten_;  // pose_ in the document's language, as shown
    int lastStep() const { return listed_.back(); }
    void relist();
    std::vector<int> listed_;  // the step numbers listed, ascending (9: the pose results)
    NewestWins derivations_;   // setScene's own derivations, and the documents set from outside
    WorkPool pool_;
    int step_ = 0;
    double zoom_ = 1.0;
    bool deriving_ = false;
    QString error_;
    std::vector<Mark> marks_;
    int shownIndex_ = -1;  // the document step shown (−1: none, or the pose results)
};

}  // namespace ll::ui
