#pragma once
// The model dock: what a student edits, in tabs (DH table with its convention, inertials
// with the shape helper, parameters, initial state and gravity, solver, a typed
// Lagrangian's fields, the whole scene as JSON), and under them the checks of the model.
// Every change is one undoable edit of the SceneDocument.
#include <QString>
#include <QStringList>
#include <QWidget>

#include "core/present/language.hpp"

class QComboBox;
class QListWidget;
class QPlainTextEdit;
class QTabWidget;
class QTableView;

namespace ll::ui {

class FieldListModel;
class JointTableModel;
class Relabel;
class SceneDocument;

class ModelEditor : public QWidget {
    Q_OBJECT
public:
    ModelEditor(SceneDocument& document, QWidget* parent = nullptr);

    JointTableModel& joints() { return *joints_; }
    FieldListModel& parameters() { return *parameters_; }
    FieldListModel& initialState() { return *initial_; }
    FieldListModel& lagrangian() { return *lagrangian_; }

    // The document changed or was checked: convention, JSON and the checks follow, the
    // checks' text in `language`.
    void documentChanged(present::Language language);
    // The checks as listed (one line each; "no errors, no warnings" when none).
    QStringList diagnosticLines() const;

    // The tab shown ("DH", "Lagrangian", …), and the tab that describes a newly opened
    // scene: a typed Lagrangian's fields, or the DH table.
    QString currentTabName() const;
    void showTabForOpenedScene();
    // A link picked: its inertials row. A joint pointed at: its DH row.
    void showLinkInertials(int link);
    void selectDhRow(int joint);
    // The DH step-through marks the parameter it carries out (a JointTableModel column).
    void markDhParameter(int joint, int column);

    // Parameters: one undoable edit each. add and rename refuse a name that is not an
    // identifier or is taken (false, the reason in *error).
    bool addParameter(const QString& name, const QString& value, QString* error = nullptr);
    void removeParameter(const QString& name);
    // Renames a parameter and every expression that uses it (ui/document/parameter_rename).
    bool renameParameter(const QString& from, const QString& to, QString* error = nullptr);

    // The JSON tab's text follows the document while it is seen (called when the dock shows).
    void refreshJson();

signals:
    // The current row of the DH or inertials table (−1: none): the joint to light up.
    void jointHighlighted(int joint);

private:
    QWidget* buildDhPage();
    QWidget* buildInertialPage();
    QWidget* buildParameterPage();
    QWidget* buildJsonPage();
    bool freeParameterName(const QString& typed, QString* error) const;

    SceneDocument& doc_;
    Relabel* relabel_ = nullptr;  // the texts, set again when the language changes
    JointTableModel* joints_ = nullptr;
    FieldListModel *parameters_ = nullptr, *initial_ = nullptr, *solver_ = nullptr, *lagrangian_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    QTableView *dhView_ = nullptr, *inertialView_ = nullptr, *parameterView_ = nullptr;
    QComboBox* convention_ = nullptr;
    QPlainTextEdit* jsonEdit_ = nullptr;
    QListWidget* diagnostics_ = nullptr;
    QWidget* lagrangianPage_ = nullptr;
    bool jsonStale_ = true;  // the JSON tab's text is older than the document
};

}  // namespace ll::ui
