#pragma once
// What a student picked and what follows from it at the time shown. An entry of the
// derivation (picked in the typeset view, the text view, the entry list, the teach
// panel or with --select) or a link (picked in the 3D view or with --pick-link); from
// the entry catalogue (core/pipeline/entry_catalogue) it knows the entry's value at any
// state from a compiled tape (no GiNaC on the GUI thread), the links whose parameters
// feed it, with each one's share now (core/dynamics/link_contributions), the joints
// whose coordinates and velocities occur in it, its curve over the run, and the
// emphasis the 3D view draws (core/visual/visual_emphasis). Lives on the GUI thread;
// copies in (the catalogue and scene are shared, never written).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <QObject>
#include <QString>

#include "core/dynamics/link_contributions.hpp"
#include "core/model/scene.hpp"
#include "core/pipeline/entry_catalogue.hpp"
#include "core/simulation/trajectory.hpp"
#include "core/visual/visual_emphasis.hpp"

namespace ll::ui {

class EntrySelection : public QObject {
    Q_OBJECT
public:
    explicit EntrySelection(QObject* parent = nullptr);
    ~EntrySelection() override;

    // A new derivation's entries, for the scene they were derived from: the pick is kept
    // when the new catalogue has an entry of the same id (else cleared).
    void setCatalogue(std::shared_ptr<const EntryCatalogue> catalogue, std::shared_ptr<const Scene> scene);
    const EntryCatalogue* catalogue() const { return catalogue_.get(); }
    // The run the entry's curve is drawn over (copied; null: none).
    void setTrajectory(const Trajectory* trajectory);

    // Picks by id as typed (b12, g2, beta23_4): false when the catalogue has no such
    // entry. The entry at item `item` of step `step` of the document (its cell row, col).
    bool select(const std::string& id);
    bool selectAt(int step, int item, int row = -1, int col = -1);
    // Picks link `link` (0-based): every entry it feeds is marked; −1 clears.
    void pickLink(int link);
    void clear();

    const CatalogueEntry* entry() const { return entry_ >= 0 ? &catalogue_->entries[static_cast<std::size_t>(entry_)] : nullptr; }
    int link() const { return link_; }
    bool active() const { return entry() || link_ >= 0; }
    // The entries the picked link feeds (empty when no link is picked).
    const std::vector<const CatalogueEntry*>& marked() const { return marked_; }

    // The state shown (a time of the run, or the teach pose): the value and the shares
    // follow. Emits valueChanged.
    void setState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t, bool teachPose = false);
    double time() const { return t_; }
    // The picked entry's values at that state (rows·cols numbers, row by row).
    const std::vector<double>& value() const { return value_; }
    // Every entry's values at that state (EntryCatalogue::values' outputs).
    const std::vector<double>& allValues() const { return all_; }
    // An entry's value as the list shows it: a number, a short vector, or its size.
    QString shortValue(const CatalogueEntry& entry) const;
    // Each link's share 0..1 of the entry's value now; negative: it does not feed it.
    const std::vector<double>& shares() const { return shares_; }
    // "b11 = 3.594 kg·m²", "p_c2 = (0.1, −0.2, 0.31) m"
    QString valueText() const;
    // The readout under the 3D view: value, time, the links with their shares (in their
    // colours) and the joints it depends on; rich text.
    QString readout() const;
    // What the 3D view draws for the pick (inactive when nothing is picked).
    VisualEmphasis emphasis(const VisualScene& scene) const;
    // The picked scalar entry over the run (at most ~1000 samples): times and values;
    // empty when there is no run or the entry is not a scalar.
    void series(std::vector<double>& t, std::vector<double>& values) const;

signals:
    void selectionChanged();  // another entry or link (or none)
    void valueChanged();      // a new state

private:
    void pick(int index);
    void update();

    std::shared_ptr<const EntryCatalogue> catalogue_;
    std::shared_ptr<const Scene> scene_;
    std::optional<LinkContributions> contributions_;
    std::optional<Trajectory> trajectory_;
    int entry_ = -1, link_ = -1;
    std::vector<const CatalogueEntry*> marked_;
    Eigen::VectorXd q_, qd_;
    double t_ = 0;
    bool teachPose_ = false;
    std::vector<double> all_, value_, shares_;
    double jointsPart_ = 0, jointsShare_ = 0;  // the joints' own part of the value (armature, springs)
};

// A number as a student writes it: 4 significant digits, − for minus, ×10ⁿ beyond 1e±4.
QString readableNumber(double v);

}  // namespace ll::ui
