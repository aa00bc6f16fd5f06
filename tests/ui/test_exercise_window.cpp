// Exercise mode in the window, as a student uses it, under a real X server: a step of the
// 2R practised hides its answers in the derivation; an answer typed is read back, checked
// on Enter (red, the hint in place, the link the hint names lit in 3D; green when right),
// counted per step, undone and redone, and changes nothing to simulate or derive; Reveal
// gives the key's right answer; the answers are saved with the scene (and in its recovery
// copy), come back with it, and `lagrangelab check-answer` judges what the window saved.
#include "test_registry.hpp"

#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>

#include "process_run.hpp"
#include "ui/window/autosave.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/exercise_mode.hpp"
#include "ui/window/exercise_panel.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/scene_files.hpp"
#include "ui/window/scene_view.hpp"
#include "window_checks.hpp"
#include "window_waits.hpp"

namespace test_exercise_window {

using ll::ui::ExercisePanel;
using ll::ui::MainWindow;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR "/") + name; }

bool settled(MainWindow& w) {
    return ll::test::waitUntil([&] { return ll::test::idle(w) && w.derivation() && !w.exercise().checking().building(); }, 120000);
}

std::unique_ptr<MainWindow> opened(const QString& path) {
    return ll::test::openedWindow(path, [](MainWindow& w) { return settled(w); });
}

// Step `n` of the derivation's text, heading to the next heading.
QString stepText(MainWindow& w, int n) {
    const QString text = w.derivationPanel().text();
    const qsizetype from = text.indexOf(QString("Step %1").arg(n));
    const qsizetype to = text.indexOf(QString("Step %1").arg(n + 1), from + 1);
    return from < 0 ? QString() : text.mid(from, to < 0 ? -1 : to - from);
}

// Types `answer` into the entry's field and presses Enter; waits for the verdict.
ExercisePanel::Mark answer(MainWindow& w, const QString& entry, const QString& text) {
    QLineEdit* field = w.exercisePanel().field(entry);
    if (!field) return ExercisePanel::Mark::None;
    field->setFocus();
    field->selectAll();
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
    ll::test::waitUntil([&] { return w.exercisePanel().mark(entry) != ExercisePanel::Mark::None; }, 30000);
    return w.exercisePanel().mark(entry);
}

}  // namespace

class TestExerciseWindow : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        ll::test::keepWindowStateIn(dir_);
    }

    void practiseAStep() {
        QFile::copy(example("planar_2r.json"), dir_.filePath("mine.json"));
        QFile(dir_.filePath("mine.json")).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
        const auto window = opened(dir_.filePath("mine.json"));
        MainWindow& w = *window;
        ExercisePanel& panel = w.exercisePanel();
        const QString stepBefore = stepText(w, 7);
        QVERIFY(!stepBefore.contains('?'));

        // the tab builds the key; step 7 is offered and practised
        w.showDerivationView("exercise");
        QVERIFY(ll::test::waitUntil([&] { return w.exercise().checking().key() != nullptr; }, 60000));
        auto* steps = panel.findChild<QComboBox*>("exercise-steps");
        QVERIFY(steps);
        const int at = steps->findData(7);
        QVERIFY2(at >= 0, "step 7 is offered");
        steps->setCurrentIndex(at);
        const int simulations = w.liveSimulation().latestRequest(), derivations = w.liveDerivation().runs();
        panel.findChild<QPushButton*>("exercise-add-step")->click();
        QVERIFY(ll::test::waitUntil([&] { return panel.entries().size() == 4; }, 30000));
        for (const char* e : {"b11", "b12", "b22", "E_kin"}) QVERIFY2(panel.entries().contains(e), e);
        QVERIFY(panel.stepHeading(7).contains("0 of 4 right"));
        // hidden in the derivation: B's entries and E_kin are '?', b22's value appears nowhere in step 7
        const auto key = w.exercise().checking().key();
        const QString b22 = QString::fromStdString(key->rightAnswer("b22"));
        QVERIFY(stepBefore.contains(b22.section(' ', 0, 0)));
        QVERIFY(ll::test::waitUntil([&] { return stepText(w, 7).contains('?'); }, 30000));
        QVERIFY(!stepText(w, 7).contains(QString::fromStdString(key->rightAnswer("E_kin")).left(20)));
        QCOMPARE(stepText(w, 6), QString(stepText(w, 6)).replace('?', ' '));  // step 6 untouched

        // b22 without the parallel-axis term: red, the hint names link 2 and Steiner, link 2 lit
        QCOMPARE(answer(w, "b22", "I2"), ExercisePanel::Mark::Wrong);
        QVERIFY2(panel.verdictText("b22").contains("Steiner"), qPrintable(panel.verdictText("b22")));
        QVERIFY(ll::test::nextFrameDrawn(w));
        const std::vector<float> lit = ll::test::linkStrengths(w);
        QVERIFY2(lit[1] >= 0 && lit[0] == -1.0f, "link 2 lit, link 1 faded");
        QCOMPARE(QString::fromStdString(w.document().exercise().answer("b22")), QString("I2"));

        // right, in the student's own form: green, counted, nothing lit
        QCOMPARE(answer(w, "b22", "m2*lc2**2 + I2"), ExercisePanel::Mark::Right);
        QVERIFY(panel.stepHeading(7).contains("1 of 4 right"));
        QVERIFY(ll::test::nextFrameDrawn(w));
        QVERIFY(!w.sceneView().emphasis().active());

        // undo: the answer before; redo: back, judged again when checked
        w.document().undoStack()->undo();
        QCOMPARE(panel.answer("b22"), QString("I2"));
        w.document().undoStack()->redo();
        QCOMPARE(panel.answer("b22"), QString("m2*lc2**2 + I2"));

        // Reveal: the key's right answer, in the student's view only
        QTest::mouseClick(panel.findChild<QPushButton*>("reveal-b11"), Qt::LeftButton);
        QVERIFY(ll::test::waitUntil([&] { return !panel.revealed("b11").isEmpty(); }, 30000));
        QVERIFY(panel.revealed("b11").contains(QString::fromStdString(key->rightAnswer("b11")).toHtmlEscaped()));

        // answers are the student's work, not the model: nothing was simulated or derived again
        QCOMPARE(w.liveSimulation().latestRequest(), simulations);
        QCOMPARE(w.liveDerivation().runs(), derivations);

        // the recovery copy holds them
        w.autosave().write();
        QFile copy(w.autosave().ownFile());
        QVERIFY(copy.open(QIODevice::ReadOnly));
        QVERIFY(copy.readAll().contains("m2*lc2**2 + I2"));

        // saved with the scene
        QVERIFY(w.files().saveTo(dir_.filePath("mine.json")));
    }

    // The saved scene opens in exercise mode: answers hidden, b22 judged right again; the
    // command line judges what the window saved.
    void comesBackWithTheScene() {
        const auto window = opened(dir_.filePath("mine.json"));
        MainWindow& w = *window;
        ExercisePanel& panel = w.exercisePanel();
        QCOMPARE(panel.entries().size(), 4);
        QCOMPARE(panel.answer("b22"), QString("m2*lc2**2 + I2"));
        QVERIFY(ll::test::waitUntil([&] { return panel.mark("b22") == ExercisePanel::Mark::Right; }, 60000));
        QVERIFY(panel.stepHeading(7).contains("1 of 4 right"));
        QVERIFY(stepText(w, 7).contains('?'));
        const auto run = ll::test::runProcess(LL_CLI, {"check-answer", dir_.filePath("mine.json"), "--format", "json"});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.out.contains("\"entry\":\"b22\",\"verdict\":\"right\""));

        // the exercise ended: every answer shown again, undoable
        panel.findChild<QPushButton*>("exercise-end")->click();
        QVERIFY(ll::test::waitUntil([&] { return !stepText(w, 7).contains('?'); }, 30000));
        QVERIFY(panel.entries().isEmpty());
        w.document().undoStack()->undo();
        QVERIFY(ll::test::waitUntil([&] { return stepText(w, 7).contains('?'); }, 30000));
    }
};

LL_TEST_MAIN(TestExerciseWindow)

}  // namespace test_exercise_window
#include "test_exercise_window.moc"
