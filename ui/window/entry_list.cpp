#include "ui/window/entry_list.hpp"

#include "ui/window/relabel.hpp"

#include <QHeaderView>
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

#include "core/visual/link_colors.hpp"
#include "ui/document/entry_selection.hpp"

namespace ll::ui {

namespace {

QColor colourOf(int link, int alpha = 255) {
    const Rgba c = linkColor(link);
    return QColor(int(c.r * 255), int(c.g * 255), int(c.b * 255), alpha);
}

}  // namespace

EntryListModel::EntryListModel(const EntrySelection& selection, QObject* parent) : QAbstractTableModel(parent), selection_(selection) {}

void EntryListModel::reset() {
    beginResetModel();
    endResetModel();
}

void EntryListModel::refreshValues() {
    if (rowCount() > 0) emit dataChanged(index(0, Value), index(rowCount() - 1, Value), {Qt::DisplayRole});
}

int EntryListModel::rowCount(const QModelIndex& parent) const {
    if (parent.isValid() || !selection_.catalogue()) return 0;
    return static_cast<int>(selection_.catalogue()->entries.size());
}

int EntryListModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant EntryListModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !selection_.catalogue()) return {};
    const CatalogueEntry& e = selection_.catalogue()->entries[static_cast<std::size_t>(index.row())];
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
            case Name: return QString::fromStdString(e.label);
            case Value: return selection_.shortValue(e);
            case Unit: return QString::fromStdString(e.unit);
            case Links: {
                QStringList links;
                for (int i : e.links) links << QString::number(i + 1);
                return links.join(", ");
            }
        }
    }
    if (role == Qt::ToolTipRole && index.column() == Name) return QString::fromStdString(e.id);
    if (role == Qt::UserRole) return QString::fromStdString(e.id);
    if (role == Qt::ForegroundRole && index.column() == Links && e.links.size() == 1) return colourOf(e.links[0]);
    if (role == Qt::BackgroundRole) {
        const int link = selection_.link();
        if (link >= 0)
            for (const CatalogueEntry* m : selection_.marked())
                if (m == &e) return colourOf(link, 60);
    }
    if (role == Qt::TextAlignmentRole && index.column() == Value) return int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant EntryListModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case Name: return tr("entry");
        case Value: return tr("value now");
        case Unit: return tr("unit");
        case Links: return tr("links");
    }
    return {};
}

EntryList::EntryList(EntrySelection& selection, QWidget* parent) : QWidget(parent), selection_(selection) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    search_ = new QLineEdit(this);
    (*new Relabel(this))([this] { search_->setPlaceholderText(tr("Find an entry: b11, g2, beta, p_c…")); });
    search_->setClearButtonEnabled(true);
    model_ = new EntryListModel(selection, this);
    filter_ = new QSortFilterProxyModel(this);
    filter_->setSourceModel(model_);
    filter_->setFilterCaseSensitivity(Qt::CaseInsensitive);
    filter_->setFilterKeyColumn(EntryListModel::Name);
    table_ = new QTableView(this);
    table_->setObjectName("entry-list");
    table_->setModel(filter_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(search_);
    layout->addWidget(table_, 1);
    connect(search_, &QLineEdit::textChanged, filter_, &QSortFilterProxyModel::setFilterFixedString);
    connect(table_->selectionModel(), &QItemSelectionModel::currentRowChanged, this, [this](const QModelIndex& current) {
        if (picking_ || !current.isValid()) return;
        selection_.select(current.data(Qt::UserRole).toString().toStdString());
    });
    connect(&selection, &EntrySelection::selectionChanged, this, &EntryList::catalogueOrPickChanged);
    connect(&selection, &EntrySelection::valueChanged, this, &EntryList::valuesChanged);
}

void EntryList::setFilter(const QString& text) { search_->setText(text); }

int EntryList::shownRows() const { return filter_->rowCount(); }

void EntryList::catalogueOrPickChanged() {
    if (model_->rowCount() != (selection_.catalogue() ? static_cast<int>(selection_.catalogue()->entries.size()) : 0)) model_->reset();
    else emit model_->dataChanged(model_->index(0, 0), model_->index(std::max(0, model_->rowCount() - 1), EntryListModel::ColumnCount - 1));
    picking_ = true;
    if (const CatalogueEntry* e = selection_.entry()) {
        const int row = static_cast<int>(e - selection_.catalogue()->entries.data());
        const QModelIndex shown = filter_->mapFromSource(model_->index(row, 0));
        if (shown.isValid()) {
            table_->setCurrentIndex(shown);
            table_->scrollTo(shown);
        }
    } else {
        table_->clearSelection();
    }
    picking_ = false;
}

void EntryList::valuesChanged() {
    // A few times a second, and only when seen: the list is read, not watched.
    if (!isVisible() || (lastRefresh_.isValid() && lastRefresh_.elapsed() < 200)) return;
    lastRefresh_.start();
    model_->refreshValues();
}

}  // namespace ll::ui
