#include "ui/window/lesson_mode.hpp"

#include <algorithm>

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

#include "core/present/diagnostic_text.hpp"
#include "ui/document/app_language.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/language_menu.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/presentation_mode.hpp"
#include "ui/window/relabel.hpp"
#include "ui/window/scene_files.hpp"
#include "ui/window/view_state.hpp"
#include "ui/window/window_parts.hpp"

namespace ll::ui {

namespace {

QString problemLines(const std::vector<Diagnostic>& problems, present::Language language) {
    QStringList lines;
    for (const Diagnostic& d : problems) lines << QString::fromStdString(present::diagnosticText(d, language));
    return lines.join('\n');
}

// One edit of the lesson: the lesson before and after it (a lesson is a few views: copies
// are cheap, and undo never has to know what an edit did).
class LessonEdit : public QUndoCommand {
public:
    LessonEdit(const QString& text, Lesson before, Lesson after, int merge, std::function<void(const Lesson&)> show)
        : QUndoCommand(text), before_(std::move(before)), after_(std::move(after)), merge_(merge), show_(std::move(show)) {}
    void redo() override { show_(after_); }
    void undo() override { show_(before_); }
    int id() const override { return merge_; }
    bool mergeWith(const QUndoCommand* other) override {
        after_ = static_cast<const LessonEdit*>(other)->after_;
        return true;
    }

private:
    Lesson before_, after_;
    int merge_;
    std::function<void(const Lesson&)> show_;
};

}  // namespace

void LessonMode::edit(const QString& what, const std::function<void(Lesson&)>& change, int merge) {
    Lesson after = lesson_;
    change(after);
    undo_->push(new LessonEdit(what, lesson_, std::move(after), merge > 0 ? merge : -1, [this](const Lesson& l) {
        lesson_ = l;
        current_ = std::min(current_, int(lesson_.views.size()) - 1);
        refreshList();
    }));
}

LessonMode::LessonMode(MainWindow& window, const WindowParts& parts) : QObject(&window), window_(window), parts_(parts) {
    undo_ = new QUndoStack(this);
    dock_ = new QDockWidget(&window);
    dock_->setObjectName("lesson");
    auto* page = new QWidget(dock_);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(4, 4, 4, 4);
    title_ = new QLabel(page);
    title_->setWordWrap(true);
    list_ = new QListWidget(page);
    list_->setObjectName("lesson-views");
    list_->setDragDropMode(QAbstractItemView::InternalMove);  // reorder by dragging
    list_->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::SelectedClicked);  // F2 renames
    note_ = new QPlainTextEdit(page);
    note_->setObjectName("lesson-note");
    note_->setMaximumHeight(120);
    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(page);
    auto* update = new QPushButton(page);
    auto* remove = new QPushButton(page);
    auto* show = new QPushButton(page);
    for (QPushButton* b : {add, update, remove, show}) buttons->addWidget(b);
    layout->addWidget(title_);
    layout->addWidget(list_, 1);
    layout->addWidget(note_);
    layout->addLayout(buttons);
    dock_->setWidget(page);
    window.addDockWidget(Qt::LeftDockWidgetArea, dock_);
    window.tabifyDockWidget(parts.modelDock, dock_);
    dock_->hide();  // until there is a lesson
    (*new Relabel(page))([this, add, update, remove, show] {
        dock_->setWindowTitle(tr("Lesson"));
        add->setText(tr("Add view"));
        update->setText(tr("Update"));
        remove->setText(tr("Remove"));
        show->setText(tr("Present"));
        note_->setPlaceholderText(tr("The speaker's note for this view"));
        refreshList();
    });
    connect(add, &QPushButton::clicked, this, &LessonMode::addCurrentView);
    connect(update, &QPushButton::clicked, this, &LessonMode::updateCurrentView);
    connect(remove, &QPushButton::clicked, this, [this] { removeView(list_->currentRow()); });
    connect(show, &QPushButton::clicked, this, [this] { present(std::max(0, list_->currentRow())); });
    connect(list_, &QListWidget::itemDoubleClicked, this, [this](QListWidgetItem* item) { go(list_->row(item)); });
    connect(list_, &QListWidget::currentRowChanged, this, [this](int row) {
        const QSignalBlocker quiet(note_);
        note_->setPlainText(row >= 0 && row < int(lesson_.views.size()) ? QString::fromStdString(lesson_.views[std::size_t(row)].view.note) : QString());
    });
    connect(note_, &QPlainTextEdit::textChanged, this, [this] {
        const int row = list_->currentRow();
        const std::string note = note_->toPlainText().toStdString();
        if (row >= 0 && row < int(lesson_.views.size()))  // the keys typed into one note are one undo step
            edit(tr("Edit the note of view %1").arg(row + 1), [row, note](Lesson& l) { l.views[std::size_t(row)].view.note = note; }, 1000 + row);
    });
    connect(list_, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        QString name = item->text();
        name.remove(QRegularExpression("^\\d+\\.\\s*"));  // the number shown before it
        renameView(list_->row(item), name);
    });
    // A drag changed the order: the lesson takes the list's.
    connect(list_->model(), &QAbstractItemModel::rowsMoved, this, [this] {
        std::vector<LessonView> views;
        int current = current_;
        for (int i = 0; i < list_->count(); ++i) {
            const int was = list_->item(i)->data(Qt::UserRole).toInt();
            views.push_back(lesson_.views[std::size_t(was)]);
            if (was == current_) current = i;  // the view shown keeps being the one Page Down starts from
        }
        current_ = current;
        QTimer::singleShot(0, this, [this, views] {  // not inside the model's own signal
            edit(tr("Move a view"), [views](Lesson& l) { l.views = views; });
        });
    });
    connect(&window.presentationMode(), &PresentationMode::changed, this, &LessonMode::presentationChanged);
    // A view that says "play from t₀ to t₁" stops at t₁ (Space plays it again from t₀).
    connect(&window.playback(), &PlaybackBar::timeChanged, this, [this](double t) {
        if (!stopAt_ || t < (*stopAt_)[1] - 1e-9 || !window_.playback().isPlaying()) return;
        window_.playback().pause();
        window_.playback().setTime((*stopAt_)[1]);
    });
    connect(&window.playback(), &PlaybackBar::playingChanged, this, [this](bool playing) {
        if (playing && stopAt_ && window_.playback().time() >= (*stopAt_)[1] - 1e-9) window_.playback().setTime((*stopAt_)[0]);
    });
    // N shows or hides the speaker's window while a lesson is presented (shown from the
    // start only with a second screen to put it on: on one screen it would cover the slide).
    notesWanted_ = QGuiApplication::screens().size() > 1;
    notesKey_ = new QAction(&window);
    notesKey_->setShortcut(Qt::Key_N);
    notesKey_->setEnabled(false);
    connect(notesKey_, &QAction::triggered, this, [this] {
        notesWanted_ = !notesWanted_;
        showNotes();
    });
    window.addAction(notesKey_);
}

LessonMode::~LessonMode() { delete notes_; }

void LessonMode::addMenu(QMenuBar* bar) {
    QMenu* menu = bar->addMenu(QString());
    QAction* create = menu->addAction(QString(), this, [this] {
        if (maybeSave()) newLesson();
    });
    QAction* open = menu->addAction(QString(), this, &LessonMode::openAsked);
    QAction* save = menu->addAction(QString(), this, [this] { saveAsked(false); });
    QAction* saveAs = menu->addAction(QString(), this, [this] { saveAsked(true); });
    menu->addSeparator();
    // The lesson's own undo (its edits are not the scene's: Edit → Undo stays the scene's).
    QAction* undo = menu->addAction(QString(), undo_, &QUndoStack::undo);
    QAction* redo = menu->addAction(QString(), undo_, &QUndoStack::redo);
    const auto name = [this, undo, redo] {
        undo->setText(undo_->undoText().isEmpty() ? tr("Undo in the lesson") : tr("Undo in the lesson: %1").arg(undo_->undoText()));
        redo->setText(undo_->redoText().isEmpty() ? tr("Redo in the lesson") : tr("Redo in the lesson: %1").arg(undo_->redoText()));
        undo->setEnabled(undo_->canUndo());
        redo->setEnabled(undo_->canRedo());
    };
    connect(undo_, &QUndoStack::indexChanged, undo, name);
    connect(undo_, &QUndoStack::cleanChanged, undo, name);
    QAction* add = menu->addAction(QString(), QKeySequence(Qt::Key_F9), this, &LessonMode::addCurrentView);
    QAction* update = menu->addAction(QString(), this, &LessonMode::updateCurrentView);
    QAction* remove = menu->addAction(QString(), this, [this] { removeView(list_->currentRow()); });
    QAction* rename = menu->addAction(QString(), this, [this] {
        const int row = list_->currentRow();
        if (row < 0 || row >= int(lesson_.views.size())) return;
        bool ok = false;
        const QString name = QInputDialog::getText(&window_, tr("Rename view"), tr("Title of the view:"), QLineEdit::Normal,
                                                   QString::fromStdString(lesson_.views[std::size_t(row)].view.name), &ok);
        if (ok) renameView(row, name);
    });
    menu->addSeparator();
    QAction* show = menu->addAction(QString(), this, [this] { present(std::max(0, list_->currentRow())); });
    window_.addAction(add);  // F9 while presenting too (the menus are hidden then)
    (*new Relabel(menu))([=] {
        name();
        menu->setTitle(tr("&Lesson"));
        create->setText(tr("New lesson"));
        open->setText(tr("Open lesson…"));
        save->setText(tr("Save lesson"));
        saveAs->setText(tr("Save lesson as…"));
        add->setText(tr("Add the current view"));
        update->setText(tr("Update the view with the current one"));
        remove->setText(tr("Remove the view"));
        rename->setText(tr("Rename the view…"));
        show->setText(tr("Present the lesson"));
    });
}

bool LessonMode::open(const QString& path, QStringList* errors, QStringList* unreadable) {
    const present::Language language = window_.language().current().language;
    try {
        lesson_ = loadLesson(path.toStdString());
    } catch (const std::exception& e) {
        if (errors) *errors = QStringList{shownError(e, language)};
        return false;
    }
    path_ = path;
    current_ = -1;
    undo_->clear();
    for (std::size_t i = 0; i < lesson_.views.size(); ++i)
        if (unreadable && !lesson_.views[i].problems.empty())
            *unreadable << QString("%1. %2: %3").arg(i + 1).arg(QString::fromStdString(lesson_.views[i].view.name),
                                                              problemLines(lesson_.views[i].problems, language));
    refreshList();
    dock_->show();
    dock_->raise();
    return true;
}

bool LessonMode::saveTo(const QString& path, QString* error) {
    try {
        saveLesson(lesson_, path.toStdString());
    } catch (const std::exception& e) {
        if (error) *error = shownError(e, window_.language().current().language);
        return false;
    }
    // The views' scene paths stay as seen from here; the file has them relative to itself.
    path_ = path;
    undo_->setClean();
    refreshList();
    return true;
}

bool LessonMode::maybeSave() {
    if (undo_->isClean() || lesson_.views.empty() || !window_.files().asksBeforeClosing()) return true;
    const auto answer = QMessageBox::warning(&window_, tr("Unsaved lesson"), tr("The lesson has unsaved changes. Save them?"),
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) {
        saveAsked(path_.isEmpty());
        return undo_->isClean();
    }
    return answer == QMessageBox::Discard;
}

void LessonMode::newLesson() {
    lesson_ = Lesson{};
    lesson_.title = tr("Lesson").toStdString();
    path_.clear();
    current_ = -1;
    undo_->clear();
    refreshList();
    dock_->show();
    dock_->raise();
}

void LessonMode::addCurrentView() {
    if (dock_->isHidden() && lesson_.views.empty()) newLesson();
    LessonView lv;
    lv.view = window_.views().capture();
    lv.view.present.reset();  // presenting is the lesson's to decide
    lv.view.name = tr("View %1").arg(lesson_.views.size() + 1).toStdString();
    const int at = current_ >= 0 ? current_ + 1 : int(lesson_.views.size());
    current_ = at;
    edit(tr("Add view %1").arg(at + 1), [at, lv](Lesson& l) { l.views.insert(l.views.begin() + at, lv); });
    window_.statusBar()->showMessage(tr("Added to the lesson as view %1").arg(at + 1), 4000);
}

void LessonMode::updateCurrentView() {
    const int row = list_->currentRow() >= 0 ? list_->currentRow() : current_;
    if (row < 0 || row >= int(lesson_.views.size())) return;
    WindowView view = window_.views().capture();
    view.present.reset();
    view.name = lesson_.views[std::size_t(row)].view.name;
    view.note = lesson_.views[std::size_t(row)].view.note;
    edit(tr("Update view %1").arg(row + 1), [row, view](Lesson& l) { l.views[std::size_t(row)] = LessonView{view, {}, {}, {}}; });  // inline now
}

void LessonMode::removeView(int index) {
    if (index < 0 || index >= int(lesson_.views.size())) return;
    edit(tr("Remove view %1").arg(index + 1), [index](Lesson& l) { l.views.erase(l.views.begin() + index); });
    if (current_ >= int(lesson_.views.size())) current_ = int(lesson_.views.size()) - 1;
}

void LessonMode::renameView(int index, const QString& name) {
    if (index < 0 || index >= int(lesson_.views.size()) || name.trimmed().isEmpty()) return;
    const std::string title = name.trimmed().toStdString();
    if (title == lesson_.views[std::size_t(index)].view.name) return;
    QTimer::singleShot(0, this, [this, index, title] {  // may be called from the list's own signal
        edit(tr("Rename view %1").arg(index + 1), [index, title](Lesson& l) { l.views[std::size_t(index)].view.name = title; });
    });
}

void LessonMode::moveView(int from, int to) {
    const int n = int(lesson_.views.size());
    if (from < 0 || from >= n || to < 0 || to >= n || from == to) return;
    edit(tr("Move view %1").arg(from + 1), [from, to](Lesson& l) {
        LessonView moved = l.views[std::size_t(from)];
        l.views.erase(l.views.begin() + from);
        l.views.insert(l.views.begin() + to, moved);
    });
    if (current_ == from) current_ = to;
}

void LessonMode::go(int index) {
    if (index < 0 || index >= int(lesson_.views.size())) return;
    const bool forward = index >= current_;
    current_ = index;
    const LessonView& lv = lesson_.views[std::size_t(index)];
    {
        const QSignalBlocker quiet(list_), quietNote(note_);
        list_->setCurrentRow(index);
        note_->setPlainText(QString::fromStdString(lv.view.note));
    }
    showNotes();
    stopAt_.reset();
    if (!lv.problems.empty()) {  // nothing to restore: say why
        const QString why = problemLines(lv.problems, window_.language().current().language);
        window_.statusBar()->showMessage(why, 20000);
        emit viewShown(index, why.split('\n'));
        return;
    }
    WindowView view = lv.view;
    view.present = presenting_ || window_.presentationMode().on();
    // Presenting, a view that names no language or notation is shown in the lecture's (those
    // on screen when it began), whichever view came before it.
    if (presenting_ && !view.language) view.language = before_.language;
    if (presenting_ && !view.notation) view.notation = before_.notation;
    // A view stepped through starts at its first step going forward, at its last going back.
    if (view.derivation.through) view.derivation.step = (*view.derivation.through)[forward ? 0 : 1];
    disconnect(pending_);  // the view restored last is the one pressed for last
    pending_ = connect(&window_.views(), &ViewState::restored, this, [this, index, play = view.playback.play](const QStringList& problems) {
        disconnect(pending_);
        stopAt_ = play;
        if (!problems.isEmpty()) window_.statusBar()->showMessage(problems.join(' '), 20000);
        emit viewShown(index, problems);
    });
    window_.views().restore(view);
}

// A key while a view is still being restored does nothing: it would act on the view before.
void LessonMode::next() {
    if (window_.views().restoring()) return;
    if (current_ >= 0 && current_ < int(lesson_.views.size())) {
        const WindowView& view = lesson_.views[std::size_t(current_)].view;
        const int before = parts_.derivation->step();
        if (view.derivation.through && before < (*view.derivation.through)[1]) {
            parts_.derivation->nextStep();
            if (parts_.derivation->step() != before) return;  // else no step left: the next view
        }
    }
    if (current_ + 1 < int(lesson_.views.size())) go(current_ + 1);
}

void LessonMode::previous() {
    if (window_.views().restoring()) return;
    if (current_ >= 0 && current_ < int(lesson_.views.size())) {
        const WindowView& view = lesson_.views[std::size_t(current_)].view;
        const int before = parts_.derivation->step();
        if (view.derivation.through && before > (*view.derivation.through)[0]) {
            parts_.derivation->previousStep();
            if (parts_.derivation->step() != before) return;
        }
    }
    if (current_ > 0) go(current_ - 1);
}

void LessonMode::present(int index) {
    if (lesson_.views.empty()) return;
    if (!presenting_) {
        before_ = window_.views().capture();
        presenting_ = true;
        notesKey_->setEnabled(true);
        window_.presentationMode().setStepper([this](int delta) { delta > 0 ? next() : previous(); });
        window_.presentationMode().setOn(true);
    }
    current_ = -1;
    go(std::clamp(index, 0, int(lesson_.views.size()) - 1));
}

void LessonMode::presentationChanged(bool on) {
    if (on) {
        dock_->setVisible(false);
        return;
    }
    dock_->setVisible(!lesson_.views.empty() || !path_.isEmpty());
    if (!presenting_) return;
    presenting_ = false;
    stopAt_.reset();
    notesKey_->setEnabled(false);
    window_.presentationMode().setStepper(nullptr);
    if (notes_) notes_->hide();
    WindowView back = before_;
    back.present = false;
    window_.views().restore(back);  // where the lecturer was before presenting
}

void LessonMode::refreshList() {
    const QSignalBlocker quiet(list_);
    const int row = list_->currentRow();
    list_->clear();
    for (std::size_t i = 0; i < lesson_.views.size(); ++i) {
        const LessonView& lv = lesson_.views[i];
        auto* item = new QListWidgetItem(QString("%1. %2%3").arg(i + 1).arg(QString::fromStdString(lv.view.name),
                                                                        lv.problems.empty() ? QString() : QString(" ⚠")),
                                         list_);
        item->setData(Qt::UserRole, int(i));
        item->setFlags(item->flags() | Qt::ItemIsEditable);
        if (!lv.problems.empty()) item->setToolTip(problemLines(lv.problems, window_.language().current().language));
        else if (!lv.view.note.empty()) item->setToolTip(QString::fromStdString(lv.view.note));
    }
    list_->setCurrentRow(std::min(row >= 0 ? row : current_, list_->count() - 1));
    const QString name = path_.isEmpty() ? tr("unsaved") : QFileInfo(path_).fileName();
    title_->setText(tr("<b>%1</b> (%2) · %n view(s)", "", int(lesson_.views.size())).arg(QString::fromStdString(lesson_.title).toHtmlEscaped(), name));
    const QSignalBlocker quietNote(note_);
    const int now = list_->currentRow();
    const QString note = now >= 0 ? QString::fromStdString(lesson_.views[std::size_t(now)].view.note) : QString();
    if (note_->toPlainText() != note) note_->setPlainText(note);  // not while it is being typed (the cursor stays)
}

// The speaker's window: this view's title and note, the next view's title.
void LessonMode::showNotes() {
    if (!presenting_) return;
    if (!notes_) {
        // It never takes the focus: the clicker's keys stay with the presentation.
        notes_ = new QWidget(nullptr, Qt::Window | Qt::WindowDoesNotAcceptFocus);
        notes_->setAttribute(Qt::WA_ShowWithoutActivating);
        notes_->setObjectName("speaker-notes");
        notes_->setWindowTitle(tr("Speaker notes — LagrangeLab"));
        auto* layout = new QVBoxLayout(notes_);
        notesNow_ = new QLabel(notes_);
        notesText_ = new QLabel(notes_);
        notesNext_ = new QLabel(notes_);
        notesText_->setWordWrap(true);
        notesText_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
        QFont big = notesText_->font();
        big.setPointSizeF(big.pointSizeF() * 1.4);
        notesText_->setFont(big);
        layout->addWidget(notesNow_);
        layout->addWidget(notesText_, 1);
        layout->addWidget(notesNext_);
        notes_->resize(520, 320);
        // On a second screen when there is one; else beside the window where the screen has
        // room, or in its lower right corner (a small window the lecturer moves).
        const QList<QScreen*> screens = QGuiApplication::screens();
        const QRect room = window_.screen() ? window_.screen()->availableGeometry() : QRect();
        QPoint at = room.bottomRight() - QPoint(notes_->width() + 20, notes_->height() + 40);
        if (room.right() - window_.frameGeometry().right() >= notes_->width() + 20)
            at = QPoint(window_.frameGeometry().right() + 10, window_.frameGeometry().top());
        for (QScreen* screen : screens)
            if (screen != window_.screen()) {
                at = screen->availableGeometry().topLeft() + QPoint(40, 40);
                break;
            }
        notes_->move(at);
    }
    const int n = int(lesson_.views.size());
    const LessonView& lv = lesson_.views[std::size_t(current_)];
    notesNow_->setText(tr("<b>%1</b> — view %2 of %3").arg(QString::fromStdString(lv.view.name).toHtmlEscaped()).arg(current_ + 1).arg(n));
    notesText_->setText(lv.view.note.empty() ? tr("(no note)") : QString::fromStdString(lv.view.note));
    notesNext_->setText(current_ + 1 < n ? tr("Next: %1").arg(QString::fromStdString(lesson_.views[std::size_t(current_ + 1)].view.name))
                                         : tr("Last view"));
    notes_->setVisible(notesWanted_);
}

void LessonMode::openAsked() {
    if (!maybeSave()) return;
    const QString path = QFileDialog::getOpenFileName(&window_, tr("Open lesson"), QDir::homePath(), tr("Lessons (*.lesson *.json)"));
    if (path.isEmpty()) return;
    QStringList errors, unreadable;
    if (!open(path, &errors, &unreadable)) QMessageBox::warning(&window_, tr("Cannot open the lesson"), errors.join('\n'));
    else if (!unreadable.isEmpty())
        QMessageBox::information(&window_, tr("Some views could not be read"),
                                 tr("They are kept in the lesson as they are written:\n%1").arg(unreadable.join('\n')));
}

void LessonMode::saveAsked(bool as) {
    QString path = path_;
    if (as || path.isEmpty()) path = QFileDialog::getSaveFileName(&window_, tr("Save lesson"), QDir::homePath() + "/lecture.lesson", tr("Lessons (*.lesson *.json)"));
    if (path.isEmpty()) return;
    QString error;
    if (!saveTo(path, &error)) QMessageBox::warning(&window_, tr("Cannot save the lesson"), error);
}

}  // namespace ll::ui
