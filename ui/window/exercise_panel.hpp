#pragma once
// The exercise tab of the derivation dock: the entries a student answers, grouped by the
// derivation's steps, each with an answer field, what was read ("read as: …", as the
// student types), Check and Reveal, the verdict in place (green right, red wrong with the
// hints) and, per step, how many are right. It holds no document: ExerciseMode
// (ui/window/exercise_mode.hpp) fills it and acts on its signals.
#include <map>
#include <vector>

#include <QString>
#include <QStringList>
#include <QWidget>

class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTimer;
class QVBoxLayout;

namespace ll::ui {

class ExercisePanel : public QWidget {
    Q_OBJECT
public:
    explicit ExercisePanel(QWidget* parent = nullptr);

    struct Step {
        int number = 0;
        QString title;        // "Step 7: kinetic energy and inertia matrix"
        QStringList entries;  // ids, as asked
    };
    // The entries asked, by step; answers typed keep their fields when their entry stays.
    void setEntries(const std::vector<Step>& steps);
    // The steps a student can add (number and title) and whether an entry is picked.
    void setChoices(const std::vector<Step>& steps, bool entryPicked);
    // An answer as the document holds it (undo, open): the field shows it; nothing is emitted.
    void setAnswer(const QString& entry, const QString& answer);
    QString answer(const QString& entry) const;

    enum class Mark { None, Right, Wrong, Unreadable };
    // What was read from the field's text (plain text; empty: nothing yet).
    void showReading(const QString& entry, const QString& readAs);
    // The verdict, with its explanation lines, in place; the step's count follows.
    void showVerdict(const QString& entry, Mark mark, const QStringList& lines);
    void showRight(const QString& entry, const QString& rightAnswer);
    // A line under the step choice: the key is being built, or why there is none.
    void setStatus(const QString& text);

    // Tests: the marks and the step headings as shown.
    Mark mark(const QString& entry) const;
    QString verdictText(const QString& entry) const;
    QString stepHeading(int step) const;
    QStringList entries() const;
    QLineEdit* field(const QString& entry) const;
    QString revealed(const QString& entry) const;  // the right answer shown, or empty

signals:
    void answerTyped(const QString& entry, const QString& answer);     // while typing (after a pause)
    void answerFinished(const QString& entry, const QString& answer);  // Enter, or the field left
    void checkRequested(const QString& entry, const QString& answer);
    void revealRequested(const QString& entry);
    void addStepRequested(int step);
    void addPickedRequested();
    void clearRequested();

private:
    struct Row {
        QLineEdit* field = nullptr;
        QLabel *reading = nullptr, *verdict = nullptr, *right = nullptr;
        QTimer* pause = nullptr;
        Mark mark = Mark::None;
        int step = 0;
    };
    Row& addRow(QWidget* box, const QString& entry, int step);
    void updateHeading(int step);
    void relabel();

    QComboBox* steps_;
    QPushButton *addStep_, *addPicked_, *clear_;
    QLabel *status_, *empty_;
    QWidget* list_;
    QVBoxLayout* listLayout_;
    std::map<QString, Row> rows_;
    std::map<int, QGroupBox*> boxes_;
    std::map<int, QString> titles_;
};

}  // namespace ll::ui
