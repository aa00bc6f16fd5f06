#include "ui/window/entry_linking.hpp"

#include <QLabel>

#include "core/visual/link_colors.hpp"
#include "ui/document/joint_table_model.hpp"
#include "ui/paint/entry_mark.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/model_editor.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/pose_matrices.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/teach_panel.hpp"
#include "ui/window/trajectory_chart.hpp"

namespace ll::ui {

EntryLinking::EntryLinking(EntrySelection& selection, const OnScreen& shown, const WindowParts& parts)
    : selection_(selection), shown_(shown), parts_(parts) {
    parts.readout->setText(readoutHint());
    connect(&selection_, &EntrySelection::selectionChanged, this, &EntryLinking::selectionChanged);
    connect(&selection_, &EntrySelection::valueChanged, this, &EntryLinking::valueChanged);
    // A click on a link picks it; a click on an entry in either rendering picks it everywhere.
    connect(parts.view, &SceneView::jointClicked, this, &EntryLinking::pickLink);
    connect(parts.typeset, &DerivationView::entryPicked, this, &EntryLinking::pickedInDerivation);
    connect(parts.derivation, &DerivationPanel::entryPicked, this, &EntryLinking::pickedInDerivation);
    // An entry picked in the teach panel's B(q), g(q) is the derivation's entry of that quantity.
    connect(parts.teach, &TeachPanel::entryPicked, this, [this](present::Quantity quantity, int row, int col) {
        if (!selection_.catalogue()) return;
        if (const CatalogueEntry* e = selection_.catalogue()->ofQuantity(quantity, row, col)) selection_.select(e->id);
    });
}

QString EntryLinking::readoutHint() {
    return tr("Click an entry of the derivation (b11, g2, …) or a link in the 3D view to see what feeds it and its value now.");
}

QString EntryLinking::readoutText() const { return parts_.readout->text(); }

bool EntryLinking::selectEntry(const QString& id) { return selection_.select(id.toStdString()); }

void EntryLinking::pickLink(int link) {
    selection_.pickLink(link);
    if (link >= 0 && link < parts_.editor->joints().rowCount()) {
        parts_.editor->showLinkInertials(link);
        parts_.view->highlightJoint(-1);  // the link shows in its own colour, not the selection's
    }
}

void EntryLinking::pickedInDerivation(int step, int item, int row, int col) {
    if (!selection_.catalogue()) return;
    if (step < 0) {  // the results at the teach pose: the same quantity's entry in the derivation
        const present::DisplayStep* pose = parts_.typeset->poseResults();
        if (!pose || item < 0 || item >= static_cast<int>(pose->items.size())) return;
        if (const CatalogueEntry* e = selection_.catalogue()->ofQuantity(pose->items[static_cast<std::size_t>(item)].quantity, row, col))
            selection_.select(e->id);
        return;
    }
    if (!selection_.selectAt(step, item, row, col)) selection_.clear();
}

void EntryLinking::runShown() {
    litShown_ = false;  // a new view of the robot: lit again
    if (shown_.result && shown_.result->visual) parts_.view->setEmphasis(selection_.emphasis(*shown_.result->visual));
    selectionChanged();
}

// The pick changed: every view shows it (marks, the plot, the 3D emphasis, the readout).
void EntryLinking::selectionChanged() {
    std::vector<EntryMark> marks;
    if (const CatalogueEntry* e = selection_.entry()) {
        marks.push_back({e->step, e->item, e->cell ? e->row : -1, e->cell ? e->col : -1, QColor(255, 214, 90, 150)});
        // Show it where it is: the typeset page of its step, the text at its line.
        parts_.typeset->showDocumentStep(e->step, e->item, e->cell ? e->row : -1, e->cell ? e->col : -1);
        parts_.derivation->showItem(e->step, e->item);
    }
    if (selection_.link() >= 0) {
        const Rgba c = linkColor(selection_.link());
        for (const CatalogueEntry* e : selection_.marked())
            marks.push_back({e->step, e->item, e->cell ? e->row : -1, e->cell ? e->col : -1,
                             QColor(int(c.r * 255), int(c.g * 255), int(c.b * 255), 60)});
    }
    parts_.typeset->setMarks(marks);
    parts_.derivation->setMarks(marks);
    // The teach panel tints the same entry of its B(q) or g(q).
    if (const CatalogueEntry* picked = selection_.entry(); picked && picked->row >= 0) {
        using present::Quantity;
        const Quantity q = picked->quantity == Quantity::MassMatrixEntry ? Quantity::MassMatrix
                           : picked->quantity == Quantity::GravityEntry  ? Quantity::GravityVector
                                                                         : picked->quantity;
        parts_.teach->matrices().setMark(q, picked->row, picked->col);
    } else if (picked && picked->quantity == present::Quantity::PotentialEnergy) {
        parts_.teach->matrices().setMark(picked->quantity);
    } else {
        parts_.teach->matrices().setMark(std::nullopt);
    }
    // The entry over the run, beside the energy plot.
    std::vector<double> t, values;
    selection_.series(t, values);
    const CatalogueEntry* e = selection_.entry();
    if (e && !values.empty()) {
        const QString name = QString::fromStdString(e->label);
        parts_.entryChart->setCurves(t, {{name, QColor(200, 120, 0), Qt::SolidLine, values}},
                                     e->unit.empty() ? name : QString("%1 [%2]").arg(name, QString::fromStdString(e->unit)));
        parts_.entryChart->setCursorTime(parts_.playback->time());
        parts_.entryChart->show();
    } else {
        parts_.entryChart->hide();
    }
    valueChanged();
}

void EntryLinking::showLit() {
    litShown_ = false;
    valueChanged();
}

void EntryLinking::valueChanged() {
    if (!selection_.active()) {
        parts_.readout->setText(readoutHint());
        const VisualScene* visual = shown_.result ? shown_.result->visual.get() : nullptr;
        if (!shown_.litLinks.empty() && visual) {
            if (litShown_) return;  // set once, not every frame
            std::vector<double> shares(static_cast<std::size_t>(shown_.result->scene->dof()), -1.0);
            for (int link : shown_.litLinks)
                if (link >= 1 && link <= static_cast<int>(shares.size())) shares[static_cast<std::size_t>(link - 1)] = 1.0;
            parts_.view->setEmphasis(visualEmphasis(*visual, shares, 0, 0));
            litShown_ = true;
        } else if (parts_.view->emphasis().active()) {
            parts_.view->setEmphasis({});
            litShown_ = false;
        }
        return;
    }
    litShown_ = false;
    parts_.readout->setText(selection_.readout());
    if (shown_.result && shown_.result->visual) parts_.view->setEmphasis(selection_.emphasis(*shown_.result->visual));
}

}  // namespace ll::ui
