#pragma once
// Every entry the derivation shows, searchable: its name, its value at the time shown,
// its unit and the links that feed it (each in its link's colour). Typing filters (b1,
// beta, g); picking a row picks the entry everywhere (ui/entry_selection). The entries
// a picked link feeds are tinted in its colour. Values are refreshed a few times a
// second while visible, not every frame.
#include <QAbstractTableModel>
#include <QElapsedTimer>
#include <QWidget>

class QLineEdit;
class QSortFilterProxyModel;
class QTableView;

namespace ll::ui {

class EntrySelection;

class EntryListModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Name, Value, Unit, Links, ColumnCount };
    explicit EntryListModel(const EntrySelection& selection, QObject* parent = nullptr);

    // A new catalogue (rows anew), or new values (the value column).
    void reset();
    void refreshValues();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    const EntrySelection& selection_;
};

class EntryList : public QWidget {
    Q_OBJECT
public:
    EntryList(EntrySelection& selection, QWidget* parent = nullptr);

    // Shows the filter text (tests, --select).
    void setFilter(const QString& text);
    int shownRows() const;

private:
    void catalogueOrPickChanged();
    void valuesChanged();

    EntrySelection& selection_;
    EntryListModel* model_;
    QSortFilterProxyModel* filter_;
    QLineEdit* search_;
    QTableView* table_;
    QElapsedTimer lastRefresh_;
    bool picking_ = false;  // a row selected by the selection itself, not the user
};

}  // namespace ll::ui
