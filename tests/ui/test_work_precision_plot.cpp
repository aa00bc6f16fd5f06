// The work–precision plot lays its decade labels out for the space it gets: painted at
// the size the Work–precision tab has in a 1280×800 window, and smaller, no two tick
// labels overlap (every 2nd or 3rd decade is labelled when the decades are close), and
// at the size of a saved plot every decade is labelled. The labels are the boxes the
// painter reports for what it drew.
#include "test_registry.hpp"

#include <QApplication>
#include <QImage>
#include <QPainter>

#include "ui/paint/work_precision_plot.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_work_precision_plot {

using namespace ll;

namespace {

// A sweep as a wide one looks: CPU times over 8 decades, errors over 14, drifts over 12.
WorkPrecisionResult wideSweep() {
    WorkPrecisionResult r;
    r.scene = "wide";
    r.duration = 5;
    r.reference.estimatedError = 1e-15;
    for (const char* integrator : {"rk4", "dopri5", "fehlberg78", "symplectic_euler"})
        for (int k = 0; k < 8; ++k) {
            WorkPrecisionPoint p;
            p.integrator = integrator;
            p.completed = true;
            p.cpuSeconds = std::pow(10.0, -6 + k);
            p.finalError = std::pow(10.0, -1 - 1.8 * k);
            p.maxRelEnergyDrift = std::pow(10.0, -2 - 1.5 * k);
            r.points.push_back(p);
        }
    return r;
}

std::vector<QRectF> labelsAt(QSize size) {
    QImage image(size, QImage::Format_RGB32);
    QPainter p(&image);
    std::vector<QRectF> labels;
    ll::ui::paintWorkPrecision(p, QRectF(QPointF(0, 0), QSizeF(size)), wideSweep(), &labels);
    return labels;
}

}  // namespace

class TestWorkPrecisionPlot : public QObject {
    Q_OBJECT
private slots:
    void noTickLabelsOverlap_data() {
        QTest::addColumn<QSize>("size");
        QTest::newRow("the tab in a 1280x800 window") << QSize(1280, 150);
        QTest::newRow("the tab at 1280x720") << QSize(1280, 120);
        QTest::newRow("a narrow window") << QSize(800, 150);
        QTest::newRow("a saved plot") << QSize(1500, 680);
        QTest::newRow("full screen") << QSize(1920, 900);
    }

    void noTickLabelsOverlap() {
        QFETCH(QSize, size);
        const std::vector<QRectF> labels = labelsAt(size);
        QVERIFY(labels.size() >= 8);  // at least two per axis of each panel
        for (std::size_t i = 0; i < labels.size(); ++i)
            for (std::size_t j = i + 1; j < labels.size(); ++j)
                QVERIFY2(!labels[i].intersects(labels[j]), qPrintable(QString("label %1 (%2,%3 %4x%5) overlaps label %6")
                                                                          .arg(i)
                                                                          .arg(labels[i].x())
                                                                          .arg(labels[i].y())
                                                                          .arg(labels[i].width())
                                                                          .arg(labels[i].height())
                                                                          .arg(j)));
    }

    // With room, every decade keeps its label: 9 + 9 on the time axes (1e-6..1e2), the
    // error axis's 1e-17..1e0 and the drift axis's decades.
    void roomLabelsEveryDecade() {
        const std::size_t large = labelsAt(QSize(1500, 680)).size(), small = labelsAt(QSize(1280, 120)).size();
        QVERIFY2(large > small, qPrintable(QString("%1 labels large, %2 small").arg(large).arg(small)));
        QVERIFY2(large >= 2 * 9 + 15, qPrintable(QString::number(large)));
    }
};

LL_TEST_MAIN(TestWorkPrecisionPlot)

}  // namespace test_work_precision_plot
#include "test_work_precision_plot.moc"
