// A soak (issue 38): the window plays the PUMA 560, then the Panda, in turns (a scene a
// minute), with an edit every 10 s, for LL_SOAK_SECONDS (120 in ctest; `scripts/lab soak`
// runs 1800). Every 5 s it samples resident memory, threads, open files, the scene
// graph's objects and the pending simulation and derivation requests; after a warm-up
// they must stay flat: the last fifth no higher than the first fifth after warm-up plus a
// margin (memory +25 % + 40 MB; threads +2; files +4; graph objects +10 %), and the
// workers never pile up (at most one request pending at a sample). The figures are
// printed, and with LL_SOAK_REPORT=FILE written as CSV.
#include "test_registry.hpp"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <fstream>
#include <random>

#include "ui/document/joint_table_model.hpp"
#include "ui/document/live_derivation.hpp"
#include "ui/document/live_simulation.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/model_editor.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_view.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_soak_window {

using namespace ll::ui;

namespace {

struct Sample {
    double t = 0;
    int scene = 0, visit = 0;
    long rssKb = 0, threads = 0, files = 0;
    std::size_t graph = 0;
    int pending = 0;
};

long statusField(const char* key) {
    QFile f("/proc/self/status");
    if (!f.open(QIODevice::ReadOnly)) return -1;
    for (const QByteArray& line : f.readAll().split('\n'))
        if (line.startsWith(key)) return line.mid(static_cast<int>(std::strlen(key))).trimmed().split(' ')[0].toLong();
    return -1;
}

Sample sample(MainWindow& w, double t) {
    Sample s;
    s.t = t;
    s.rssKb = statusField("VmRSS:");
    s.threads = statusField("Threads:");
    s.files = static_cast<long>(QDir("/proc/self/fd").entryList(QDir::NoDotAndDotDot | QDir::AllEntries | QDir::System).size());
    s.graph = w.sceneView().graphObjects();
    s.pending = (w.liveSimulation().latestRequest() - (w.result() ? w.result()->request : 0)) + (w.liveDerivation().busy() ? 1 : 0);
    return s;
}

}  // namespace

class TestSoakWindow : public QObject {
    Q_OBJECT
private slots:
    void playsAndEditsForMinutesWithFlatResources() {
        const int seconds = qEnvironmentVariableIsSet("LL_SOAK_SECONDS") ? qEnvironmentVariableIntValue("LL_SOAK_SECONDS") : 120;
        QTemporaryDir dir;
        qputenv("LAGRANGELAB_RECOVERY_DIR", dir.filePath("recovery").toLocal8Bit());
        const QStringList scenes{QString(LL_EXAMPLES_DIR) + "/puma560.json", QString(LL_EXAMPLES_DIR) + "/panda.json"};
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.resize(1280, 800);
        w.show();
        std::mt19937 rng(30);
        std::vector<Sample> samples;
        QElapsedTimer clock;
        clock.start();
        int scene = -1, visit = -1, edits = 0;
        // Each scene is visited at least twice (a minute each in long runs): what a visit
        // holds at its end is compared with the same scene's first visit.
        const double period = std::min(60.0, seconds / 4.0);
        double nextEdit = 10, nextSample = 0, nextScene = 0;
        while (clock.elapsed() < seconds * 1000LL) {
            const double t = clock.elapsed() / 1000.0;
            if (t >= nextScene) {  // a scene a minute, in turns, played in a loop
                scene = (scene + 1) % 2;
                ++visit;
                QVERIFY(w.openFile(scenes[scene], nullptr, true));
                w.playback().setLoop(true);
                w.playback().play();
                nextScene += period;
            }
            if (t >= nextEdit) {  // a student's edit: a link's mass, as typed in the table
                const int row = static_cast<int>(rng() % static_cast<unsigned>(w.editor().joints().rowCount()));
                const QString mass = QString::number(1.0 + (rng() % 100) / 20.0);
                QVERIFY(w.editor().joints().setData(w.editor().joints().index(row, JointTableModel::Mass), mass, Qt::EditRole));
                ++edits;
                nextEdit += 10;
            }
            if (t >= nextSample) {
                samples.push_back(sample(w, t));
                samples.back().scene = scene;
                samples.back().visit = visit;
                QVERIFY2(samples.back().pending <= 2, "the workers pile up");
                nextSample += 5;
            }
            QTest::qWait(20);
        }
        QVERIFY(w.sceneView().framesDrawn() > seconds);  // it did play
        if (qEnvironmentVariableIsSet("LL_SOAK_REPORT")) {
            std::ofstream csv(qgetenv("LL_SOAK_REPORT").toStdString());
            csv << "t_s,scene,visit,rss_kb,threads,open_files,graph_objects,pending\n";
            for (const Sample& s : samples)
                csv << s.t << ',' << (s.scene == 0 ? "puma560" : "panda") << ',' << s.visit + 1 << ',' << s.rssKb << ',' << s.threads << ','
                    << s.files << ',' << s.graph << ',' << s.pending << '\n';
        }
        // Flat: each scene's last visit against its first (the first visit of the PUMA
        // warms up: its second half only), peaks of the samples in them.
        const int lastVisit = visit;
        const auto window = [&](int v, bool secondHalf) {
            Sample top;
            double from = 1e300, to = -1;
            for (const Sample& s : samples)
                if (s.visit == v) from = std::min(from, s.t), to = std::max(to, s.t);
            for (const Sample& s : samples)  // the sample taken as the scene opened shows the one before
                if (s.visit == v && s.t > from + 1 && (!secondHalf || s.t >= (from + to) / 2)) {
                    top.rssKb = std::max(top.rssKb, s.rssKb);
                    top.threads = std::max(top.threads, s.threads);
                    top.files = std::max(top.files, s.files);
                    top.graph = std::max(top.graph, s.graph);
                }
            return top;
        };
        // The PUMA's first visit (its second half) and its last; the Panda's second and last.
        const int lastPuma = lastVisit % 2 == 0 ? lastVisit : lastVisit - 1;
        const int lastPanda = lastVisit % 2 == 1 ? lastVisit : lastVisit - 1;
        QVERIFY2(lastPuma >= 2 && lastPanda >= 3, "each scene visited at least twice");
        for (const auto& [firstVisit, lastOne] : {std::pair{0, lastPuma}, {1, lastPanda}}) {
            const Sample first = window(firstVisit, firstVisit == 0), last = window(lastOne, false);
            const QString figures = QString("%1 s, %2 edits, %3 frames; %4, visit %5 against visit %6 (peaks): "
                                            "RSS %7 -> %8 MB, threads %9 -> %10, open files %11 -> %12, graph objects %13 -> %14")
                                        .arg(seconds)
                                        .arg(edits)
                                        .arg(w.sceneView().framesDrawn())
                                        .arg(firstVisit == 0 ? "PUMA 560" : "Panda")
                                        .arg(lastOne + 1)
                                        .arg(firstVisit + 1)
                                        .arg(first.rssKb / 1024.0, 0, 'f', 1)
                                        .arg(last.rssKb / 1024.0, 0, 'f', 1)
                                        .arg(first.threads)
                                        .arg(last.threads)
                                        .arg(first.files)
                                        .arg(last.files)
                                        .arg(first.graph)
                                        .arg(last.graph);
            qInfo("%s", qPrintable(figures));
            QVERIFY2(last.rssKb <= first.rssKb * 1.25 + 40 * 1024, qPrintable(figures));
            QVERIFY2(last.threads <= first.threads + 2, qPrintable(figures));
            QVERIFY2(last.files <= first.files + 4, qPrintable(figures));
            QVERIFY2(last.graph <= first.graph * 1.1 + 10, qPrintable(figures));
        }
    }
};

LL_TEST_MAIN(TestSoakWindow)

}  // namespace test_soak_window
#include "test_soak_window.moc"
