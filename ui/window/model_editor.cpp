#include "ui/window/model_editor.hpp"

#include <functional>
#include <initializer_list>
#include <utility>

#include <QCheckBox>
#include <QComboBox>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>

#include "core/present/diagnostic_text.hpp"
#include "core/present/message_text.hpp"
#include "ui/document/field_list_model.hpp"
#include "ui/document/joint_table_model.hpp"
#include "ui/document/parameter_rename.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/relabel.hpp"

namespace ll::ui {

namespace {

QTableView* makeTable(QAbstractItemModel* model, QWidget* parent) {
    auto* table = new QTableView(parent);
    table->setModel(model);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed | QAbstractItemView::AnyKeyPressed);
    table->setSelectionBehavior(QAbstractItemView::SelectItems);
    return table;
}

}  // namespace

ModelEditor::ModelEditor(SceneDocument& document, QWidget* parent) : QWidget(parent), doc_(document) {
    joints_ = new JointTableModel(doc_, this);
    parameters_ = new FieldListModel(doc_, parameterRows, this);
    initial_ = new FieldListModel(doc_, initialStateRows, this);
    solver_ = new FieldListModel(doc_, solverRows, this);
    lagrangian_ = new FieldListModel(doc_, lagrangianRows, this);

    relabel_ = new Relabel(this);
    (*relabel_)([this] { joints_->relabel(); });  // "joint 1" / "led 1": the header takes the new width
    tabs_ = new QTabWidget(this);
    tabs_->addTab(buildDhPage(), QString());
    tabs_->addTab(buildInertialPage(), QString());
    tabs_->addTab(buildParameterPage(), QString());
    tabs_->addTab(makeTable(initial_, tabs_), QString());
    tabs_->addTab(makeTable(solver_, tabs_), QString());
    lagrangianPage_ = makeTable(lagrangian_, tabs_);
    tabs_->addTab(lagrangianPage_, QString());
    tabs_->addTab(buildJsonPage(), QString());
    (*relabel_)([tabs = tabs_] {
        int i = 0;
        for (const QString& title :
             {tr("DH"), tr("Inertials"), tr("Parameters"), tr("Initial && gravity"), tr("Solver"), tr("Lagrangian"), tr("JSON")})
            tabs->setTabText(i++, title);
    });
    connect(tabs_, &QTabWidget::currentChanged, this, &ModelEditor::refreshJson);

    diagnostics_ = new QListWidget(this);
    diagnostics_->setMaximumHeight(110);
    diagnostics_->setWordWrap(true);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(tabs_, 1);
    auto* checks = new QLabel(this);
    (*relabel_)([checks] { checks->setText(tr("Checks (errors keep the last valid model on screen):")); });
    layout->addWidget(checks);
    layout->addWidget(diagnostics_);

    // A joint's row chosen in the DH or inertials table lights the joint up in the 3D view.
    const auto highlight = [this](const QModelIndex& index) { emit jointHighlighted(index.isValid() ? index.row() : -1); };
    connect(dhView_->selectionModel(), &QItemSelectionModel::currentChanged, this, highlight);
    connect(inertialView_->selectionModel(), &QItemSelectionModel::currentChanged, this, highlight);
}

// DH table with the convention, degree switch and joint list buttons.
QWidget* ModelEditor::buildDhPage() {
    auto* page = new QWidget(tabs_);
    auto* layout = new QVBoxLayout(page);
    auto* bar = new QHBoxLayout;
    convention_ = new QComboBox(page);
    convention_->addItem(QString(), "standard");
    convention_->addItem(QString(), "modified");
    auto* degrees = new QCheckBox(page);
    auto* conventionLabel = new QLabel(page);
    (*relabel_)([convention = convention_, degrees, conventionLabel] {
        convention->setItemText(0, tr("standard (Spong)"));
        convention->setItemText(1, tr("modified (Craig)"));
        degrees->setText(tr("angles in degrees"));
        conventionLabel->setText(tr("convention"));
    });
    bar->addWidget(conventionLabel);
    bar->addWidget(convention_);
    bar->addWidget(degrees);
    bar->addStretch(1);
    layout->addLayout(bar);
    dhView_ = makeTable(joints_, page);
    dhView_->setObjectName("dh-table");
    for (int c = JointTableModel::firstInertialColumn; c <= JointTableModel::lastInertialColumn; ++c) dhView_->setColumnHidden(c, true);
    layout->addWidget(dhView_, 1);
    auto* rowBar = new QHBoxLayout;
    const auto currentRow = [this] { return dhView_->currentIndex().isValid() ? dhView_->currentIndex().row() : joints_->rowCount() - 1; };
    for (auto [text, action] : std::initializer_list<std::pair<const char*, std::function<void()>>>{
             {QT_TR_NOOP("Add joint"), [this, currentRow] { joints_->addJoint(currentRow()); }},
             {QT_TR_NOOP("Remove"), [this, currentRow] { joints_->removeJoint(currentRow()); }},
             {QT_TR_NOOP("Move up"), [this, currentRow] { joints_->moveJoint(currentRow(), -1); }},
             {QT_TR_NOOP("Move down"), [this, currentRow] { joints_->moveJoint(currentRow(), +1); }}}) {
        auto* button = new QPushButton(page);
        (*relabel_)([button, text = text] { button->setText(tr(text)); });
        connect(button, &QPushButton::clicked, this, action);
        rowBar->addWidget(button);
    }
    rowBar->addStretch(1);
    layout->addLayout(rowBar);
    connect(convention_, &QComboBox::activated, this, [this](int i) {
        doc_.setValue("/robot/convention", convention_->itemData(i).toString().toStdString(),
                      tr("Convention: %1").arg(convention_->itemText(i)));
    });
    connect(degrees, &QCheckBox::toggled, joints_, &JointTableModel::setDegrees);
    return page;
}

// Inertials with the shape helper.
QWidget* ModelEditor::buildInertialPage() {
    auto* page = new QWidget(tabs_);
    auto* layout = new QVBoxLayout(page);
    inertialView_ = makeTable(joints_, page);
    for (int c = JointTableModel::firstDhColumn; c <= JointTableModel::lastDhColumn; ++c) inertialView_->setColumnHidden(c, true);
    layout->addWidget(inertialView_, 1);
    auto* bar = new QHBoxLayout;
    auto* shape = new QComboBox(page);
    for (const char* id : {"rod", "cylinder", "disc", "box", "sphere"}) shape->addItem(QString(), id);
    auto* fill = new QPushButton(page);
    (*relabel_)([shape, fill] {
        int i = 0;
        for (const QString& text : {tr("rod (length L)"), tr("cylinder (r, h)"), tr("disc (r)"), tr("box (x, y, z)"), tr("sphere (r)")})
            shape->setItemText(i++, text);
        fill->setText(tr("Fill inertia from shape…"));
    });
    connect(fill, &QPushButton::clicked, this, [this, shape] {
        const int row = inertialView_->currentIndex().isValid() ? inertialView_->currentIndex().row() : 0;
        bool ok = false;
        const QString dims = QInputDialog::getText(
            this, tr("Inertia from a shape"),
            tr("Joint %1, %2: dimensions in metres, comma-separated (numbers or parameters)").arg(row + 1).arg(shape->currentText()),
            QLineEdit::Normal, "", &ok);
        if (ok) joints_->fillInertiaFromShape(row, shape->currentData().toString(), dims.split(','));
    });
    bar->addWidget(shape);
    bar->addWidget(fill);
    bar->addStretch(1);
    layout->addLayout(bar);
    return page;
}

// Parameters with add, remove and rename (each one undoable edit).
QWidget* ModelEditor::buildParameterPage() {
    auto* page = new QWidget(tabs_);
    auto* layout = new QVBoxLayout(page);
    parameterView_ = makeTable(parameters_, page);
    layout->addWidget(parameterView_, 1);
    auto* bar = new QHBoxLayout;
    auto* add = new QPushButton(page);
    auto* remove = new QPushButton(page);
    auto* rename = new QPushButton(page);
    (*relabel_)([add, remove, rename] {
        add->setText(tr("Add parameter…"));
        remove->setText(tr("Remove"));
        rename->setText(tr("Rename…"));
    });
    connect(rename, &QPushButton::clicked, this, [this] {
        const QModelIndex index = parameterView_->currentIndex();
        if (!index.isValid()) return;
        const QString from = parameters_->row(index.row()).name;
        bool ok = false;
        const QString to =
            QInputDialog::getText(this, tr("Rename parameter"), tr("New name of %1 (every expression using it follows):").arg(from),
                                  QLineEdit::Normal, from, &ok);
        QString error;
        if (ok && !renameParameter(from, to, &error)) QMessageBox::warning(this, tr("Rename parameter"), error);
    });
    connect(add, &QPushButton::clicked, this, [this] {
        bool ok = false;
        const QString name =
            QInputDialog::getText(this, tr("Add parameter"), tr("Name (letters, digits, _; e.g. m3, l2, k):"), QLineEdit::Normal, "", &ok);
        if (!ok || name.isEmpty()) return;
        const QString value = QInputDialog::getText(this, tr("Add parameter"), tr("Value of %1 (a number, SI units):").arg(name),
                                                    QLineEdit::Normal, "1", &ok);
        QString error;
        if (ok && !addParameter(name, value, &error)) QMessageBox::warning(this, tr("Add parameter"), error);
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        const QModelIndex index = parameterView_->currentIndex();
        if (index.isValid()) removeParameter(parameters_->row(index.row()).name);
    });
    bar->addWidget(add);
    bar->addWidget(remove);
    bar->addWidget(rename);
    bar->addStretch(1);
    layout->addLayout(bar);
    return page;
}

// The whole scene as JSON (effects, bodies, anything the tables do not list).
QWidget* ModelEditor::buildJsonPage() {
    auto* page = new QWidget(tabs_);
    auto* layout = new QVBoxLayout(page);
    jsonEdit_ = new QPlainTextEdit(page);
    jsonEdit_->setObjectName("scene-json");
    jsonEdit_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    auto* apply = new QPushButton(page);
    (*relabel_)([apply] { apply->setText(tr("Apply (undoable)")); });
    connect(apply, &QPushButton::clicked, this, [this] {
        try {
            doc_.replace(SceneJson::parse(jsonEdit_->toPlainText().toStdString()), tr("Edit scene JSON"));
        } catch (const std::exception& e) {
            QMessageBox::warning(this, tr("Scene JSON"), QString::fromUtf8(e.what()));
        }
    });
    layout->addWidget(jsonEdit_, 1);
    layout->addWidget(apply);
    return page;
}

void ModelEditor::documentChanged(present::Language language) {
    const std::string convention =
        doc_.value("/robot/convention").is_string() ? doc_.value("/robot/convention").get<std::string>() : "standard";
    convention_->setCurrentIndex(convention == "modified" ? 1 : 0);
    jsonStale_ = true;
    refreshJson();
    diagnostics_->clear();
    for (const Diagnostic& d : doc_.diagnostics()) {
        QString text = QString::fromStdString(present::diagnosticText(d, language));
        // An error on a whole joint (B singular there) right after one value was edited:
        // that value is named, the likely cause the message itself cannot know.
        const std::string& edited = doc_.lastEditedField();
        if (d.severity == Severity::Error && !edited.empty() && d.field.ends_with("]") &&
            d.field.find("robot.joints[") != std::string::npos && edited.rfind("robot.joints[", 0) == 0)
            text +=
                "\n" + tr("hint: it happened with your edit of %1")
                           .arg(QString::fromStdString(present::messageText(Diagnostic{Severity::Error, edited, {}}.place(), language)));
        auto* item = new QListWidgetItem(text, diagnostics_);
        item->setForeground(d.severity == Severity::Error ? QColor(180, 0, 0) : QColor(140, 100, 0));
    }
    if (doc_.diagnostics().empty()) new QListWidgetItem(tr("no errors, no warnings"), diagnostics_);
    // A parameter typed over in one cell but still used elsewhere: the student may have
    // meant to change it everywhere (a1 → 1.2 in the DH table, a1 still in the COM lc1-a1).
    for (const ParameterStillUsed& used : doc_.stillUsedAfterLastEdit()) {
        QStringList places;
        for (const std::string& field : used.fields)
            places << QString::fromStdString(present::messageText(Diagnostic{Severity::Warning, field, {}}.place(), language));
        const QString edited =
            QString::fromStdString(present::messageText(Diagnostic{Severity::Warning, doc_.lastEditedField(), {}}.place(), language));
        auto* item = new QListWidgetItem(tr("hint: %1 is no longer in %2 but still in %3; to change it everywhere, change %1 under Parameters")
                                             .arg(QString::fromStdString(used.parameter), edited, places.join(", ")),
                                         diagnostics_);
        item->setForeground(QColor(30, 70, 150));
    }
}

QStringList ModelEditor::diagnosticLines() const {
    QStringList lines;
    for (int i = 0; i < diagnostics_->count(); ++i) lines << diagnostics_->item(i)->text();
    return lines;
}

// Hidden, the JSON text is refilled when shown (setPlainText and its layout cost 2–3 ms
// of every edit's frame for nothing).
void ModelEditor::refreshJson() {
    if (!jsonStale_ || !jsonEdit_->isVisible() || jsonEdit_->hasFocus()) return;
    jsonEdit_->setPlainText(QString::fromStdString(doc_.text()));
    jsonStale_ = false;
}

QString ModelEditor::currentTabName() const { return tabs_->tabText(tabs_->currentIndex()); }

void ModelEditor::showTabForOpenedScene() {
    tabs_->setCurrentWidget(doc_.json().contains("lagrangian") ? lagrangianPage_ : tabs_->widget(0));
}

void ModelEditor::showLinkInertials(int link) {
    if (link < 0 || link >= joints_->rowCount()) return;
    tabs_->setCurrentWidget(inertialView_->parentWidget());
    inertialView_->selectRow(link);
}

void ModelEditor::selectDhRow(int joint) {
    if (joint >= 0 && joint < joints_->rowCount()) dhView_->selectRow(joint);
}

void ModelEditor::markDhParameter(int joint, int column) {
    if (joint >= 0 && joint < joints_->rowCount()) dhView_->setCurrentIndex(dhView_->model()->index(joint, column));
}

// Whether `typed` (trimmed) can name a new parameter: an identifier no parameter has.
bool ModelEditor::freeParameterName(const QString& typed, QString* error) const {
    static const QRegularExpression identifier("^[A-Za-z_][A-Za-z0-9_]*$");
    const QString trimmed = typed.trimmed();
    if (!identifier.match(trimmed).hasMatch()) {
        if (error) *error = tr("parameter name '%1': letters, digits and _ only, starting with a letter").arg(typed);
        return false;
    }
    if (!doc_.value("/parameters/" + trimmed.toStdString()).is_null()) {
        if (error) *error = tr("parameter name '%1': there is a parameter of that name").arg(trimmed);
        return false;
    }
    return true;
}

bool ModelEditor::addParameter(const QString& name, const QString& value, QString* error) {
    const QString trimmed = name.trimmed();
    if (!freeParameterName(name, error)) return false;
    // The loader checks the rest (reserved names such as c1 or s12, the value) and marks it.
    doc_.setValue("/parameters/" + trimmed.toStdString(), SceneDocument::parseCell(value), tr("Add parameter %1").arg(trimmed));
    return true;
}

bool ModelEditor::renameParameter(const QString& from, const QString& to, QString* error) {
    const QString trimmed = to.trimmed();
    if (doc_.value("/parameters/" + from.toStdString()).is_null()) {
        if (error) *error = tr("no parameter '%1'").arg(from);
        return false;
    }
    if (trimmed == from) return true;
    if (!freeParameterName(to, error)) return false;
    // The loader checks the rest (a reserved name such as c1, a clash with a coordinate).
    doc_.replace(renamedParameter(doc_.json(), from.toStdString(), trimmed.toStdString()),
                 tr("Rename parameter %1 to %2").arg(from, trimmed));
    return true;
}

void ModelEditor::removeParameter(const QString& name) {
    doc_.setValue("/parameters/" + name.toStdString(), SceneJson(), tr("Remove parameter %1").arg(name));
}

}  // namespace ll::ui
