// Edge smoothing (ui/edge_smoothing) against what anti-aliasing is for: each pixel's
// colour should be the share of it that each surface covers. Pictures of known
// half-planes are compared with their exact coverage (integrated here by 16x16
// sub-samples, independently of the filter), and a real render with and without the
// filter is compared with the same render at 4x MSAA.
#include "test_registry.hpp"

#include <cmath>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/visual/camera_view.hpp"
#include "core/visual/trajectory_sampler.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/visual/visual_scene.hpp"
#include "ui/paint/edge_smoothing.hpp"
#include "ui/paint/headless_renderer.hpp"
#include "ui/paint/osg_scene.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_edge_smoothing {

using namespace ll;

namespace {

// A dark half-plane below the line y = y0 + slope·x on a light background: the
// aliased picture (each pixel by its centre) and the exact coverage (0..1 dark).
struct HalfPlane {
    QImage aliased;
    std::vector<double> coverage;
};

HalfPlane halfPlane(int w, int h, double y0, double slope, bool steep) {
    HalfPlane p{QImage(w, h, QImage::Format_RGBX8888), std::vector<double>(std::size_t(w) * h)};
    auto dark = [&](double x, double y) { return steep ? x > y0 + slope * y : y > y0 + slope * x; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int inside = 0;
            for (int sy = 0; sy < 16; ++sy)
                for (int sx = 0; sx < 16; ++sx) inside += dark(x + (sx + 0.5) / 16, y + (sy + 0.5) / 16);
            p.coverage[std::size_t(y) * w + x] = inside / 256.0;
            p.aliased.setPixelColor(x, y, dark(x + 0.5, y + 0.5) ? QColor(30, 30, 40) : QColor(235, 238, 245));
        }
    return p;
}

// Mean |pixel's darkness − exact coverage| over the pixels the edge passes through.
double coverageError(const QImage& image, const HalfPlane& p) {
    double sum = 0;
    int count = 0;
    for (int y = 1; y < image.height() - 1; ++y)
        for (int x = 1; x < image.width() - 1; ++x) {
            const double exact = p.coverage[std::size_t(y) * image.width() + x];
            if (exact <= 0 || exact >= 1) continue;
            const double darkness = (235 - image.pixelColor(x, y).red()) / double(235 - 30);
            sum += std::abs(darkness - exact);
            ++count;
        }
    return sum / std::max(count, 1);
}

double meanDifference(const QImage& a, const QImage& b) {
    double sum = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            sum += std::abs(p.red() - q.red()) + std::abs(p.green() - q.green()) + std::abs(p.blue() - q.blue());
        }
    return sum / (3.0 * a.width() * a.height());
}

}  // namespace

class TestEdgeSmoothing : public QObject {
    Q_OBJECT
private slots:
    // Shallow and steep lines, both ways: the smoothed staircase is much closer to the
    // true coverage than the aliased one.
    void staircasesBecomeRamps() {
        ui::EdgeSmoothing smoothing;
        for (const double slope : {0.12, -0.2, 0.35}) {
            for (const bool steep : {false, true}) {
                const HalfPlane p = halfPlane(160, 120, steep ? 70.3 : 50.3, slope, steep);
                QImage smoothed = p.aliased;
                smoothing.apply(smoothed);
                const double before = coverageError(p.aliased, p), after = coverageError(smoothed, p);
                qInfo("slope %.2f%s: mean coverage error %.3f aliased, %.3f smoothed", slope, steep ? " (steep)" : "", before, after);
                QVERIFY2(after < 0.5 * before,
                         qPrintable(QString("slope %1%2: error %3 -> %4").arg(slope).arg(steep ? " (steep)" : "").arg(before).arg(after)));
            }
        }
    }

    // Flat areas and a picture with no edge are left exactly as they were.
    void flatPicturesAreUntouched() {
        QImage flat(64, 48, QImage::Format_RGBX8888);
        flat.fill(QColor(120, 130, 140));
        QImage smoothed = flat;
        ui::EdgeSmoothing().apply(smoothed);
        QCOMPARE(smoothed, flat);
        const HalfPlane p = halfPlane(64, 48, 20.3, 0.1, false);
        QImage edge = p.aliased;
        ui::EdgeSmoothing().apply(edge);
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x)
                if (std::abs(y + 0.5 - (20.3 + 0.1 * (x + 0.5))) > 3) QCOMPARE(edge.pixel(x, y), p.aliased.pixel(x, y));
    }

    // A real frame (the PUMA 560 headless, no display needed): the smoothed plain frame
    // is closer to the 4x MSAA frame than the plain one is, and it changes only a small
    // share of the pixels (the edges).
    void renderMovesTowardsMultisampling() {
        const Scene scene = loadScene(LL_EXAMPLES_DIR "/puma560.json").scene;
        SimulationSettings settings = scene.simulation;
        settings.duration = 0.5;
        const Trajectory tr = simulate(scene, settings).trajectory;
        VisualScene visual = visualScene(scene);
        visual.fitToMotion(tr);
        visual.pose(tr.q.back(), tr.t.back());
        ui::OsgSceneOptions options;
        options.frameLabels = false;  // glyphs are drawn with their own smoothing
        options.dropLines = false;    // 1.5 px lines and dots: no edge of a solid to smooth, MSAA draws them wider
        ui::OsgScene graph(visual, options);
        QImage frames[3];
        const int modes[3] = {0, ui::kEdgeSmoothing, 4};
        for (int k = 0; k < 3; ++k) {
            ui::HeadlessRenderer gl(480, 270, modes[k]);
            gl.setScene(graph.root());
            ui::applyCameraView(*gl.camera(), cameraView(visual, parseCameraSpec("iso"), gl.aspect()), gl.aspect());
            gl.render(frames[k]);
        }
        const double plain = meanDifference(frames[0], frames[2]), smoothed = meanDifference(frames[1], frames[2]);
        qInfo("mean |frame - 4x MSAA frame| per channel: %.3f plain, %.3f smoothed", plain, smoothed);
        QVERIFY2(smoothed < 0.85 * plain, qPrintable(QString("mean |plain - MSAA| %1, |smoothed - MSAA| %2").arg(plain).arg(smoothed)));
        int changed = 0;
        for (int y = 0; y < 270; ++y)
            for (int x = 0; x < 480; ++x) changed += frames[0].pixel(x, y) != frames[1].pixel(x, y);
        QVERIFY2(changed > 0 && changed < 480 * 270 / 8, qPrintable(QString("%1 pixels changed").arg(changed)));
    }
};

LL_TEST_GUILESS_MAIN(TestEdgeSmoothing)

}  // namespace test_edge_smoothing
#include "test_edge_smoothing.moc"
