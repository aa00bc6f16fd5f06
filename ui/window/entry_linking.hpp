#pragma once
// The derivation linked to the motion: an entry picked anywhere (the typeset page, the
// text, the teach panel's B(q) and g(q), an id typed: b12, g2, beta23_4) or a link
// clicked in the 3D view is shown in every view at once: marked in both renderings of
// the derivation, tinted in the teach panel, plotted over the run beside the energy, its
// links emphasised in the 3D view, and its value now with what feeds it under the view.
#include <QObject>
#include <QString>

#include "ui/document/entry_selection.hpp"
#include "ui/window/window_parts.hpp"

namespace ll::ui {

class EntryLinking : public QObject {
    Q_OBJECT
public:
    EntryLinking(EntrySelection& selection, const OnScreen& shown, const WindowParts& parts);

    // Picks an entry by id as typed (false when the derivation shown has none).
    bool selectEntry(const QString& id);
    // Picks link `link` (0-based; −1 clears): the entries it feeds are marked, its
    // inertials row selected.
    void pickLink(int link);
    // A new run is shown: its plot, emphasis and readout follow the pick.
    void runShown();
    // A new time or pose: the value, the shares, the emphasis.
    void valueChanged();
    // The links an exercise's hint names changed (OnScreen::litLinks): lit while nothing is picked.
    void showLit();

    QString readoutText() const;
    static QString readoutHint();

private:
    void pickedInDerivation(int step, int item, int row, int col);
    void selectionChanged();

    EntrySelection& selection_;
    const OnScreen& shown_;
    const WindowParts& parts_;
    bool litShown_ = false;  // the view shows OnScreen::litLinks
};

}  // namespace ll::ui
