#pragma once
// The derivation as plain text (steps 0–8) in a read-only text view: searchable and
// copyable, beside the typeset ll::ui::DerivationView. It derives nothing itself: the
// window's one derivation worker (ui/live_derivation) hands it the text rendered from
// the same display trees the typeset tab shows.
#include <vector>

#include <QWidget>

#include "core/present/text_document.hpp"
#include "ui/paint/entry_mark.hpp"

class QPlainTextEdit;
class QLabel;

namespace ll::ui {

struct DerivationResult;

class DerivationPanel : public QWidget {
    Q_OBJECT
public:
    explicit DerivationPanel(QWidget* parent = nullptr);

    // A derivation has started (the text shown stays until it is done).
    void setDeriving();
    // Shows a finished derivation: its text, or why there is none; a stopped one (an
    // edit is being checked) keeps the text shown.
    void setDerivation(const DerivationResult& result);
    // Scrolls to step n (0..8) of the current text.
    void showStep(int n);
    int step() const { return step_; }
    void setZoom(double factor);

    // The picked entry and a picked link's entries, tinted (ui/paint/entry_mark.hpp).
    void setMarks(const std::vector<EntryMark>& marks);
    // Scrolls to the first line of item `item` of document step `step`.
    void showItem(int step, int item);

    // What is shown (tests), and whether a derivation is still running.
    QString text() const;
    bool busy() const { return busy_; }

    // The step numbers of the text shown, ascending (a typed Lagrangian: 0, 6, 7, 8).
    const std::vector<int>& steps() const { return steps_; }

public slots:
    void nextStep();
    void previousStep();

signals:
    void stepChanged(int step);
    // A derivation finished and is shown.
    void derived();
    // A click on an item (row = col = −1) or on one entry of its matrix.
    void entryPicked(int step, int item, int row, int col);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void readHeadings(present::Language language);
    QPlainTextEdit* view_;
    std::vector<present::TextSpan> spans_;
    QLabel* status_;
    bool busy_ = false;
    int step_ = 0;
    // The text's "Step N." headings, read once per derivation: step numbers ascending and
    // the text block each starts at.
    std::vector<int> steps_{0}, headingBlocks_{0};
    double baseFont_ = 10.0;
};

}  // namespace ll::ui
