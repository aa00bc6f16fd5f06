#include "ui/document/entry_selection.hpp"

#include <algorithm>
#include <cmath>

#include "core/visual/link_colors.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

QString readableNumber(double v) {
    if (!std::isfinite(v)) return QString::number(v);
    if (v == 0) return "0";
    const double a = std::abs(v);
    QString s;
    if (a >= 1e-4 && a < 1e5) {
        s = QString::number(v, 'g', 4);
    } else {
        const int exponent = static_cast<int>(std::floor(std::log10(a)));
        const double mantissa = v / std::pow(10.0, exponent);
        static const char* const superscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
        QString power;
        for (QChar c : QString::number(std::abs(exponent))) power += QString::fromUtf8(superscript[c.digitValue()]);
        s = QString::number(mantissa, 'g', 4) + QString::fromUtf8("·10") + (exponent < 0 ? QString::fromUtf8("⁻") : "") + power;
    }
    return s.replace('-', QChar(0x2212));
}

EntrySelection::EntrySelection(QObject* parent) : QObject(parent) {}
EntrySelection::~EntrySelection() = default;

void EntrySelection::setCatalogue(std::shared_ptr<const EntryCatalogue> catalogue, std::shared_ptr<const Scene> scene) {
    const std::string picked = entry() ? entry()->id : std::string();
    const int link = link_;
    catalogue_ = std::move(catalogue);
    scene_ = std::move(scene);
    contributions_.reset();
    if (scene_ && !scene_->lagrangian && scene_->robot.dof() > 0) contributions_.emplace(scene_->robot, scene_->effects);
    entry_ = -1;
    link_ = -1;
    marked_.clear();
    all_.clear();
    if (catalogue_ && q_.size() != catalogue_->n) {
        q_ = Eigen::VectorXd::Zero(catalogue_->n);
        qd_ = Eigen::VectorXd::Zero(catalogue_->n);
    }
    if (!picked.empty() && catalogue_) {
        if (const CatalogueEntry* e = catalogue_->find(picked)) entry_ = static_cast<int>(e - catalogue_->entries.data());
    } else if (link >= 0 && catalogue_ && (!scene_ || link < scene_->dof())) {
        link_ = link;
        marked_ = catalogue_->fedBy(link);
    }
    update();
    emit selectionChanged();
}

void EntrySelection::setTrajectory(const Trajectory* trajectory) {
    if (trajectory) trajectory_ = *trajectory;
    else trajectory_.reset();
}

bool EntrySelection::select(const std::string& id) {
    if (!catalogue_) return false;
    const CatalogueEntry* e = catalogue_->find(id);
    if (!e) return false;
    pick(static_cast<int>(e - catalogue_->entries.data()));
    return true;
}

bool EntrySelection::selectAt(int step, int item, int row, int col) {
    if (!catalogue_) return false;
    const CatalogueEntry* e = catalogue_->at(step, item, row, col);
    if (!e) return false;
    pick(static_cast<int>(e - catalogue_->entries.data()));
    return true;
}

void EntrySelection::pick(int index) {
    entry_ = index;
    link_ = -1;
    marked_.clear();
    update();
    emit selectionChanged();
}

void EntrySelection::pickLink(int link) {
    entry_ = -1;
    link_ = catalogue_ && link >= 0 && (!scene_ || link < scene_->dof()) ? link : -1;
    marked_ = link_ >= 0 ? catalogue_->fedBy(link_) : std::vector<const CatalogueEntry*>{};
    update();
    emit selectionChanged();
}

void EntrySelection::clear() {
    entry_ = link_ = -1;
    marked_.clear();
    update();
    emit selectionChanged();
}

void EntrySelection::setState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t, bool teachPose) {
    q_ = q;
    qd_ = qd;
    t_ = t;
    teachPose_ = teachPose;
    update();
    emit valueChanged();
}

void EntrySelection::update() {
    value_.clear();
    jointsPart_ = jointsShare_ = 0;
    const int n = scene_ ? scene_->dof() : 0;
    shares_.assign(static_cast<std::size_t>(n), -1.0);
    if (link_ >= 0 && link_ < n) shares_[static_cast<std::size_t>(link_)] = 1.0;
    if (!catalogue_ || q_.size() != catalogue_->n) return;
    catalogue_->evaluate(q_.data(), qd_.data(), t_, all_);  // every entry: the list shows them all
    const CatalogueEntry* e = entry();
    if (!e) return;
    value_.assign(all_.begin() + e->first, all_.begin() + e->first + e->rows * e->cols);
    if (e->perLink && contributions_ && contributions_->links() == n && q_.size() == n) {
        // Each feeding link's share of the value now: |its part| over the sum of the parts'
        // magnitudes, the joints' own part (a motor's armature on b_jj, a spring's on g_j) one of them.
        contributions_->evaluate(q_, qd_);
        double links = 0, sum = 0;
        for (int i : e->links) {
            links += std::abs(linkPart(*e, *contributions_, i));
            sum += linkPart(*e, *contributions_, i);
        }
        const double joints = value_.size() == 1 ? value_[0] - sum : 0.0;
        jointsPart_ = std::abs(joints) > 1e-9 * std::max(links, 1e-300) ? std::abs(joints) : 0.0;
        const double total = links + jointsPart_;
        jointsShare_ = total > 0 ? jointsPart_ / total : 0.0;
        for (int i : e->links) shares_[static_cast<std::size_t>(i)] = total > 0 ? std::abs(linkPart(*e, *contributions_, i)) / total : 0.0;
    } else {
        for (int i : e->links)
            if (i < n) shares_[static_cast<std::size_t>(i)] = 1.0 / static_cast<double>(e->links.size());
    }
}

QString EntrySelection::shortValue(const CatalogueEntry& e) const {
    if (all_.size() < static_cast<std::size_t>(e.first + e.rows * e.cols)) return {};
    if (e.rows * e.cols == 1) return readableNumber(all_[static_cast<std::size_t>(e.first)]);
    if ((e.rows == 1 || e.cols == 1) && e.rows * e.cols <= 3) {
        QStringList parts;
        for (int k = 0; k < e.rows * e.cols; ++k) parts << readableNumber(all_[static_cast<std::size_t>(e.first + k)]);
        return "(" + parts.join(", ") + ")";
    }
    return QString::fromUtf8("%1×%2").arg(e.rows).arg(e.cols);
}

QString EntrySelection::valueText() const {
    const CatalogueEntry* e = entry();
    if (!e || value_.empty()) return {};
    QString v;
    if (value_.size() == 1) {
        v = readableNumber(value_[0]);
    } else if (e->cols == 1 || e->rows == 1) {
        QStringList parts;
        for (double x : value_) parts << readableNumber(x);
        v = "(" + parts.join(", ") + ")";
    } else {
        QStringList rows;
        for (int r = 0; r < e->rows; ++r) {
            QStringList cells;
            for (int c = 0; c < e->cols; ++c) cells << readableNumber(value_[static_cast<std::size_t>(r * e->cols + c)]);
            rows << "[" + cells.join(", ") + "]";
        }
        v = "[" + rows.join(", ") + "]";
    }
    const QString unit = QString::fromStdString(e->unit);
    return QString::fromStdString(e->label) + " = " + v + (unit.isEmpty() ? QString() : QString::fromUtf8(" ") + unit);
}

namespace {

QString linkName(int link) {
    const Rgba c = linkColor(link);
    return QString("<span style=\"color:rgb(%1,%2,%3)\"><b>%4</b></span>")
        .arg(int(c.r * 255))
        .arg(int(c.g * 255))
        .arg(int(c.b * 255))
        .arg(QObject::tr("link&nbsp;%1").arg(link + 1));
}

// q2, q3 (or q̇2, q̇3 in Latin Modern: the desktop's sans font drops the dots).
QString coordinateList(std::uint64_t bits, int n, bool velocities) {
    QStringList names;
    for (int k = 0; k < n && k < 64; ++k)
        if ((bits >> k) & 1u) names << QString(velocities ? "q\u0307%1" : "q%1").arg(k + 1);
    if (!velocities || names.isEmpty()) return names.join(", ");
    return QString("<span style=\"font-family:'%1'\">%2</span>").arg(textbookFont(QFont()).family(), names.join(", "));
}

}  // namespace

QString EntrySelection::readout() const {
    const int n = scene_ ? scene_->dof() : 0;
    if (link_ >= 0) {
        return tr("%1 picked: it feeds %n entries of the derivation, marked in the list and the typeset view", "",
                  static_cast<int>(marked_.size()))
            .arg(linkName(link_));
    }
    const CatalogueEntry* e = entry();
    if (!e) return {};
    QString text =
        "<b>" + valueText().toHtmlEscaped() + "</b>  " + (teachPose_ ? tr("at the teach pose") : tr("at t = %1 s").arg(readableNumber(t_)));
    // 37 %, and "<1 %" for a part that is there but small
    const auto percent = [](double share) {
        const long p = std::lround(100 * share);
        return share > 0 && p == 0 ? QString("&lt;1&nbsp;%") : QString("%1&nbsp;%").arg(p);
    };
    QStringList fed;
    for (int i : e->links)
        if (i < static_cast<int>(shares_.size()))
            fed << (e->perLink ? linkName(i) + "&nbsp;" + percent(shares_[static_cast<std::size_t>(i)]) : linkName(i));
    if (jointsPart_ > 0) {
        using present::Quantity;
        const bool mass =
            e->quantity == Quantity::MassMatrix || e->quantity == Quantity::MassMatrixEntry || e->quantity == Quantity::KineticEnergy;
        fed << (mass ? tr("the motor's armature") : tr("the springs")) + "&nbsp;" + percent(jointsShare_);
    }
    text += " · " + (fed.isEmpty() ? tr("no link's parameters occur in it") : tr("fed by %1").arg(fed.join(", ")));
    const QString q = coordinateList(e->coordinates, n, false), qd = coordinateList(e->velocities, n, true);
    if (!q.isEmpty()) text += " · " + tr("depends on %1").arg(q);
    if (!qd.isEmpty()) text += " · " + tr("with the velocities %1").arg(qd);
    return text;
}

VisualEmphasis EntrySelection::emphasis(const VisualScene& scene) const {
    if (!active()) return {};
    const CatalogueEntry* e = entry();
    return visualEmphasis(scene, shares_, e ? e->coordinates : 0, e ? e->velocities : 0);
}

void EntrySelection::series(std::vector<double>& t, std::vector<double>& values) const {
    t.clear();
    values.clear();
    const CatalogueEntry* e = entry();
    if (!e || !trajectory_ || !catalogue_ || e->rows * e->cols != 1 || trajectory_->n != catalogue_->n) return;
    const Trajectory& tr = *trajectory_;
    const std::size_t stride = std::max<std::size_t>(1, tr.size() / 1000);
    std::vector<double> all;
    for (std::size_t k = 0; k < tr.size(); k += stride) {
        catalogue_->evaluate(tr.q[k].data(), tr.qd[k].data(), tr.t[k], all);
        t.push_back(tr.t[k]);
        values.push_back(all[static_cast<std::size_t>(e->first)]);
    }
}

}  // namespace ll::ui
