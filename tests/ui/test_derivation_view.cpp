// DerivationView: derives in a worker thread (the newest scene wins), steps through 0–8
// with Previous/Next and stepChanged, titles and copies an item as LaTeX, and paints
// typeset math.
#include "test_registry.hpp"

#include <QApplication>
#include <QSignalSpy>

#include "core/io/scene_file.hpp"
#include "ui/window/derivation_view.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_derivation_view {

using namespace ll;

namespace {
Scene example(const char* name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }
}  // namespace

class TestDerivationView : public QObject {
    Q_OBJECT

private slots:
    void newestSceneWinsAndStepsMove() {
        ui::DerivationView view;
        view.resize(1000, 700);
        view.show();
        QSignalSpy finished(&view, &ui::DerivationView::derivationFinished);
        view.setScene(example("puma560.json"));  // stale: cancelled by the next call
        view.setScene(example("planar_2r.json"));
        QVERIFY(view.isDeriving());
        QTRY_VERIFY_WITH_TIMEOUT(!view.isDeriving(), 120000);
        QVERIFY(view.document());
        QCOMPARE(QString::fromStdString(view.document()->systemName), QString("Planar 2R arm (uniform rods)"));
        QCOMPARE(finished.count(), 1);  // the PUMA's result never arrived

        QSignalSpy steps(&view, &ui::DerivationView::stepChanged);
        view.showStep(7);
        QCOMPARE(view.step(), 7);
        view.nextStep();
        QCOMPARE(view.step(), 8);
        view.nextStep();  // stays at the last step
        QCOMPARE(view.step(), 8);
        // Step 8's headers: g, C, Q by their names, the equations by number (not by
        // their whole left side, the row of B q̈ + C q̇ + g written out).
        const QStringList titles = {view.itemTitle(0), view.itemTitle(1), view.itemTitle(2), view.itemTitle(3), view.itemTitle(4)};
        QCOMPARE(titles, (QStringList{"g", "C", "Q", "equation 1", "equation 2"}));
        QCOMPARE(view.itemTitle(5), QString());
        view.previousStep();
        QCOMPARE(view.step(), 7);
        QCOMPARE(steps.count(), 3);
        QCOMPARE(steps.last().at(0).toInt(), 7);

        // Step 7's first item is B(q): its LaTeX, as Copy as LaTeX gives it.
        const QString latex = view.itemLatex(0);
        QVERIFY2(latex.startsWith("B(q) = \\begin{bmatrix}"), qPrintable(latex));
        QVERIFY(latex.contains("\\ell_{c1}^{2}"));

        // The typeset step paints ink; a larger zoom paints more of it.
        QApplication::processEvents();
        auto ink = [&] {
            const QImage image = view.grab().toImage();
            qint64 dark = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = image.width() / 3; x < image.width(); ++x) dark += qGray(image.pixel(x, y)) < 100;
            return dark;
        };
        if (!qEnvironmentVariableIsEmpty("LL_SAVE_GRAB"))  // to look at it: LL_SAVE_GRAB=view.png
            view.grab().save(qEnvironmentVariable("LL_SAVE_GRAB"));
        const qint64 at1 = ink();
        QVERIFY(at1 > 200);
        view.setZoom(2.0);
        QCOMPARE(view.zoom(), 2.0);
        QApplication::processEvents();
        QVERIFY(ink() > at1);
    }

    void destroyedWhileDeriving() {
        auto* view = new ui::DerivationView;
        view->setScene(example("puma560.json"));
        delete view;  // cancels and joins the worker: no crash, no late call
        QApplication::processEvents();
    }
};

static int runDerivationView(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("DISPLAY")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    TestDerivationView test;
    return QTest::qExec(&test, argc, argv);
}
LL_TEST_PROGRAM(runDerivationView)

}  // namespace test_derivation_view
#include "test_derivation_view.moc"
