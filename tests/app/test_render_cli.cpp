// `lagrangelab render` as a user runs it, with DISPLAY unset (headless EGL): PNG frames
// that change over time and show the robot, an MP4 checked with ffprobe, a GIF and a
// still, the Lagrangian mass–spring pair's bodies, every bad option (exit 2, one line,
// nothing written), and an interrupted render that leaves no file and no ffmpeg.
#include "test_registry.hpp"

#include <QDir>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

#include <csignal>

#include "ui/paint/composite_frame.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_render_cli {

class TestRenderCli : public QObject {
    Q_OBJECT

    struct Run {
        int exitCode;
        QByteArray out, err;
    };
    static QProcessEnvironment headless() {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.remove("WAYLAND_DISPLAY");
        env.remove("QT_QPA_PLATFORM");
        return env;
    }
    static Run run(const QStringList& args, const QProcessEnvironment& env = headless()) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(LL_CLI, args);
        p.waitForFinished(300000);
        return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
    }
    static QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

    // ffprobe's "key=value" lines for the first video stream.
    static QMap<QString, QString> probe(const QString& file) {
        QProcess p;
        p.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=width,height,nb_read_frames,codec_name,pix_fmt:format=duration", "-of", "default=nw=1", file});
        p.waitForFinished(60000);
        QMap<QString, QString> values;
        for (const QByteArray& line : p.readAllStandardOutput().split('\n'))
            if (const int eq = line.indexOf('='); eq > 0) values[line.left(eq)] = line.mid(eq + 1).trimmed();
        return values;
    }

    // Share of pixels that differ clearly from the background colour (top-left corner
    // of the 3D view, below the overlay box).
    static double coverage(const QImage& image) {
        const QRgb background = image.pixel(image.width() / 2, 2);
        long differ = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb c = image.pixel(x, y);
                if (std::abs(qRed(c) - qRed(background)) + std::abs(qGreen(c) - qGreen(background)) +
                        std::abs(qBlue(c) - qBlue(background)) >
                    40)
                    ++differ;
            }
        return double(differ) / (image.width() * image.height());
    }

    // Processes whose command line mentions `text` (an ffmpeg left behind).
    static QStringList processesMentioning(const QString& text) {
        QStringList found;
        for (const QString& pid : QDir("/proc").entryList(QDir::Dirs))
            if (!pid.isEmpty() && pid[0].isDigit()) {
                QFile f("/proc/" + pid + "/cmdline");
                if (f.open(QIODevice::ReadOnly) && f.readAll().replace('\0', ' ').contains(text.toUtf8())) found << pid;
            }
        return found;
    }

private slots:
    // 1 s at 10 fps to a folder: 10 PNGs of the asked size, changing over time, with
    // the robot covering a sensible share of the picture.
    void pngFramesOfTheDoublePendulum() {
        QTemporaryDir dir;
        const QString out = dir.filePath("frames");
        const Run r = run({"render", example("double_pendulum.json"), "--duration", "1", "--fps", "10", "--size", "320x240", "--overlay",
                           "none", "--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QStringList files = QDir(out).entryList({"frame_*.png"}, QDir::Files, QDir::Name);
        QCOMPARE(files.size(), 10);
        QImage first(out + "/" + files.first()), last(out + "/" + files.last());
        QCOMPARE(first.size(), QSize(320, 240));
        const double share = coverage(first);
        qInfo("drawn share of the first frame: %.3f", share);
        QVERIFY(share > 0.02 && share < 0.6);
        long changed = 0;
        for (int y = 0; y < 240; ++y)
            for (int x = 0; x < 320; ++x) changed += first.pixel(x, y) != last.pixel(x, y);
        QVERIFY2(changed > 500, qPrintable(QString::number(changed)));
        QVERIFY(QDir(dir.path()).entryList(QDir::Hidden | QDir::AllEntries | QDir::NoDotAndDotDot).size() == 1);  // no temporaries
    }

    void mp4FramesSizeAndDuration() {
        QTemporaryDir dir;
        const QString out = dir.filePath("puma.mp4");
        const Run r = run({"render", example("puma560.json"), "--duration", "2", "--fps", "15", "--size", "640x360", "--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(r.out.trimmed(), out.toUtf8());
        const auto v = probe(out);
        QCOMPARE(v["codec_name"], QString("h264"));
        QCOMPARE(v["pix_fmt"], QString("yuv420p"));
        QCOMPARE(v["width"], QString("640"));
        QCOMPARE(v["height"], QString("360"));
        QCOMPARE(v["nb_read_frames"], QString("30"));
        QVERIFY(std::abs(v["duration"].toDouble() - 2.0) < 0.1);
    }

    // The slide layout: an MP4 of the asked size and frame count at 1280×720, and PNG
    // frames at 1920×1080 whose plot region changes from frame to frame (the cursor) while
    // the equation panel, inked, stays the same.
    void compositeVideoAndFrames() {
        QTemporaryDir dir;
        const QString mp4 = dir.filePath("slide.mp4");
        Run r = run({"render", example("puma560.json"), "--layout", "composite", "--duration", "2", "--fps", "15", "--size", "1280x720",
                     "--out", mp4});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const auto v = probe(mp4);
        QCOMPARE(v["width"], QString("1280"));
        QCOMPARE(v["height"], QString("720"));
        QCOMPARE(v["nb_read_frames"], QString("30"));
        const QString folder = dir.filePath("frames");
        r = run({"render", example("planar_2r.json"), "--layout", "composite", "--duration", "1", "--fps", "10", "--size", "1920x1080",
                 "--out", folder});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QStringList files = QDir(folder).entryList({"frame_*.png"}, QDir::Files, QDir::Name);
        QCOMPARE(files.size(), 10);
        const ll::ui::CompositeLayout layout = ll::ui::CompositeLayout::forSize(QSize(1920, 1080));
        const auto differing = [](const QImage& a, const QImage& b, const QRect& region) {
            long n = 0;
            for (int y = region.top(); y <= region.bottom(); ++y)
                for (int x = region.left(); x <= region.right(); ++x) n += a.pixel(x, y) != b.pixel(x, y);
            return n;
        };
        QImage previous(folder + "/" + files.first());
        QCOMPARE(previous.size(), QSize(1920, 1080));
        long ink = 0;
        for (int y = layout.equation.top(); y <= layout.equation.bottom(); ++y)
            for (int x = layout.equation.left(); x <= layout.equation.right(); ++x) ink += qGray(previous.pixel(x, y)) < 100;
        QVERIFY2(ink > 2000, qPrintable(QString::number(ink)));  // the title and formulas are there
        for (int k = 1; k < files.size(); ++k) {
            const QImage frame(folder + "/" + files[k]);
            QVERIFY2(differing(previous, frame, layout.plot) > 50, qPrintable(files[k]));
            QCOMPARE(differing(previous, frame, layout.equation), 0L);
            previous = frame;
        }
    }

    // Slow motion: 0.5 s of simulation at speed 0.25 is 2 s of video.
    void slowMotionGifAndWebm() {
        QTemporaryDir dir;
        const QString gif = dir.filePath("pendulum.gif");
        Run r = run({"render", example("double_pendulum.json"), "--duration", "0.5", "--speed", "0.25", "--fps", "10", "--size", "200x150",
                     "--out", gif});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        auto v = probe(gif);
        QCOMPARE(v["codec_name"], QString("gif"));
        QCOMPARE(v["nb_read_frames"], QString("20"));
        QCOMPARE(v["width"], QString("200"));
        const QString webm = dir.filePath("pendulum.webm");
        r = run({"render", example("double_pendulum.json"), "--duration", "1", "--fps", "10", "--size", "320x240", "--out", webm});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        v = probe(webm);
        QCOMPARE(v["codec_name"], QString("vp9"));
        QCOMPARE(v["nb_read_frames"], QString("10"));
    }

    // A still at t: the overlay is there (time box top left, energy inset bottom right).
    void stillWithOverlay() {
        QTemporaryDir dir;
        const QString out = dir.filePath("still.png");
        const Run r = run({"render", example("puma560.json"), "--at", "0.5", "--duration", "1", "--size", "640x360", "--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QImage still(out);
        QCOMPARE(still.size(), QSize(640, 360));
        QVERIFY(coverage(still) > 0.05);
        // The inset's white panel with dark text and coloured curves in the bottom-right corner.
        const QImage inset = still.copy(440, 250, 190, 100);
        QSet<QRgb> colours;
        for (int y = 0; y < inset.height(); ++y)
            for (int x = 0; x < inset.width(); ++x) colours.insert(inset.pixel(x, y) & 0xf0f0f0);
        QVERIFY2(colours.size() > 20, qPrintable(QString::number(colours.size())));
    }

    // The Lagrangian mass–spring pair draws its discs (steel blue and indian red).
    void lagrangianBodiesAreDrawn() {
        QTemporaryDir dir;
        const QString out = dir.filePath("pair.png");
        const Run r = run({"render", example("mass_spring_pair_lagrangian.json"), "--size", "400x300", "--overlay", "none", "--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QImage image(out);
        long blue = 0, red = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (c.blue() > c.red() + 40 && c.blue() > c.green() + 10) ++blue;
                if (c.red() > c.green() + 50 && c.red() > c.blue() + 50) ++red;
            }
        qInfo("blue pixels %ld, red pixels %ld", blue, red);
        QVERIFY(blue > 1000);
        QVERIFY(red > 1000);
    }

    void badOptions_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("names");
        const QString out = "/tmp/lagrangelab-bad-option-test.mp4";
        QTest::newRow("size not WxH") << QStringList{"--size", "big", "--out", out} << "--size big";
        QTest::newRow("size zero") << QStringList{"--size", "0x720", "--out", out} << "--size 0x720";
        QTest::newRow("size above 8192") << QStringList{"--size", "9000x720", "--out", out} << "--size 9000x720";
        QTest::newRow("odd for H.264") << QStringList{"--size", "641x481", "--out", out} << "--size 641x481";
        QTest::newRow("fps zero") << QStringList{"--fps", "0", "--out", out} << "--fps 0";
        QTest::newRow("fps negative") << QStringList{"--fps", "-5", "--out", out} << "--fps -5";
        QTest::newRow("gif fps") << QStringList{"--fps", "60", "--out", "/tmp/lagrangelab-bad.gif"} << "--fps 60";
        QTest::newRow("duration zero") << QStringList{"--duration", "0", "--out", out} << "--duration 0";
        QTest::newRow("speed") << QStringList{"--speed", "-1", "--out", out} << "--speed -1";
        QTest::newRow("camera") << QStringList{"--camera", "diagonal", "--out", out} << "--camera diagonal";
        QTest::newRow("overlay") << QStringList{"--overlay", "time,clock", "--out", out} << "--overlay time,clock";
        QTest::newRow("trail") << QStringList{"--trail", "maybe", "--out", out} << "--trail maybe";
        QTest::newRow("msaa") << QStringList{"--msaa", "3", "--out", out} << "--msaa 3";
        QTest::newRow("extension") << QStringList{"--out", "/tmp/movie.avi"} << "--out /tmp/movie.avi";
        QTest::newRow("missing folder") << QStringList{"--out", "/nonexistent/dir/x.mp4"} << "--out /nonexistent/dir/x.mp4";
        QTest::newRow("unwritable folder") << QStringList{"--out", "/proc/x.mp4"} << "--out /proc/x.mp4";
        QTest::newRow("at on a video") << QStringList{"--at", "1", "--out", out} << "--at 1";
        QTest::newRow("at beyond duration") << QStringList{"--at", "20", "--out", "/tmp/lagrangelab-bad.png"} << "--at 20";
        QTest::newRow("no out") << QStringList{"--fps", "10"} << "--out";
        QTest::newRow("layout") << QStringList{"--layout", "poster", "--out", out} << "--layout poster";
        QTest::newRow("step without composite") << QStringList{"--step", "8", "--out", out} << "--step 8";
        QTest::newRow("step beyond 9") << QStringList{"--layout", "composite", "--step", "10", "--out", out} << "--step 10";
        QTest::newRow("overlay with composite")
            << QStringList{"--layout", "composite", "--overlay", "time", "--out", out} << "--overlay time";
    }
    void badOptions() {
        QFETCH(QStringList, args);
        QFETCH(QString, names);
        const Run r = run(QStringList{"render", example("double_pendulum.json")} + args);
        QCOMPARE(r.exitCode, 2);
        const QByteArray firstLine = r.err.split('\n').first();
        QVERIFY2(firstLine.startsWith("error: " + names.toUtf8()), r.err.constData());
        QVERIFY(!QFile::exists("/tmp/lagrangelab-bad-option-test.mp4"));
    }

    // No ffmpeg on PATH: a clear message that offers PNG frames, and no file.
    void ffmpegMissing() {
        QTemporaryDir dir;
        QProcessEnvironment env = headless();
        env.insert("PATH", dir.path());
        const QString out = dir.filePath("x.mp4");
        const Run r = run({"render", example("double_pendulum.json"), "--out", out}, env);
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains("ffmpeg not found") && r.err.contains("PNG frames"), r.err.constData());
        QVERIFY(!QFile::exists(out));
    }

    // SIGINT midway: no output file, no temporary, no ffmpeg left running.
    void interruptLeavesNothing() {
        QTemporaryDir dir;
        const QString out = dir.filePath("long.mp4");
        QProcess p;
        p.setProcessEnvironment(headless());
        p.start(LL_CLI, {"render", example("puma560.json"), "--duration", "60", "--size", "640x360", "--out", out});
        QVERIFY(p.waitForStarted());
        // Wait until frames are being encoded (the temporary exists), then interrupt.
        QElapsedTimer waited;
        waited.start();
        while (QDir(dir.path()).entryList(QDir::Hidden | QDir::Files).isEmpty() && waited.elapsed() < 120000) QTest::qWait(50);
        QVERIFY2(!QDir(dir.path()).entryList(QDir::Hidden | QDir::Files).isEmpty(), "the render never started writing");
        QTest::qWait(300);
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 130);
        QVERIFY(p.readAllStandardError().contains("interrupted"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Hidden | QDir::AllEntries | QDir::NoDotAndDotDot), QStringList());
        QCOMPARE(processesMentioning(dir.path()), QStringList());
    }
};

LL_TEST_GUILESS_MAIN(TestRenderCli)

}  // namespace test_render_cli
#include "test_render_cli.moc"
