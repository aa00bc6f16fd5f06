// The typeset PDF's threads (ui/derivation_pages): a second thread lays out the pages
// while QPdfWriter writes the finished ones, and the window may export two documents at
// once (a PDF beside SVG or PNG pages too). Labelled `threads`: `scripts/lab tsan` runs it under ThreadSanitizer, which must
// report no race.
//
// Every PDF is compared with the same document written alone first: its page count and
// every stream inflated (each glyph's position, the font subsets), so a race that drops,
// reorders or corrupts a page fails here even without the sanitizer.
#include <QtTest>

#include <QGuiApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <thread>

#include "core/io/scene_file.hpp"
#include "core/model/cancellation.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/symbolic/display_stream.hpp"
#include "ui/derivation_pages.hpp"
#include "ui/math_typesetter.hpp"
#include "pdf_streams.hpp"

using namespace ll;

namespace {

std::shared_ptr<const symbolic::DisplayDocument> documentOf(const char* example) {
    const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example).scene;
    return deriveDisplay(scene, DocumentRequest{}).display;
}

// The PDF's streams inflated (tests/pdf_streams.hpp): everything it shows, without its
// creation date. Read here, not by pdftotext: under ThreadSanitizer a process that has
// run threads may not fork.
QList<QByteArray> streamsOf(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    return test::inflatedStreams(file.readAll());
}

// Pages: content streams begin by setting the graphics state and flipping y.
int pagesIn(const QList<QByteArray>& streams) {
    int pages = 0;
    for (const QByteArray& s : streams) pages += s.startsWith("/GSa gs") && s.contains(" cm\n");
    return pages;
}

struct Written {
    bool ok = false;
    int pages = 0;
    std::string error;
};

// A PDF written from a stream on its own thread. Should the test stop early (a failed
// check returns), the stream is failed and the thread joined: never left running.
class StreamWriter {
public:
    StreamWriter(symbolic::DisplayStream& stream, const QString& path)
        : stream_(stream), thread_([this, path] { written_.ok = ui::writePdf(stream_, path, written_.error, {}, &written_.pages); }) {}
    ~StreamWriter() {
        if (!thread_.joinable()) return;
        stream_.fail();
        thread_.join();
    }
    const Written& join() {
        thread_.join();
        return written_;
    }

private:
    symbolic::DisplayStream& stream_;
    Written written_;
    std::thread thread_;
};

Written write(const symbolic::DisplayDocument& document, const QString& path) {
    Written w;
    w.ok = ui::writePdf(document, path, w.error, {}, &w.pages);
    return w;
}

}  // namespace

class TestPdfThreads : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY2(ui::mathFontsAvailable(), "fonts-lmodern is not installed"); }

    // One document: layout and writing overlap; every page arrives, in order, the same
    // each time.
    void pagesWrittenAreThePagesLaidOut() {
        QTemporaryDir dir;
        for (const char* example : {"planar_2r.json", "scara.json", "panda.json"}) {
            const auto document = documentOf(example);
            const std::size_t pages = ui::paginate(*document).pages.size();
            const Written first = write(*document, dir.filePath("first.pdf"));
            QVERIFY2(first.ok, first.error.c_str());
            QCOMPARE(std::size_t(first.pages), pages);
            const QList<QByteArray> streams = streamsOf(dir.filePath("first.pdf"));
            QCOMPARE(pagesIn(streams), int(pages));
            qsizetype glyphs = 0;
            for (const QByteArray& s : streams) glyphs += s.count("Tj\n");
            QVERIFY2(glyphs > 500, example);
            const Written again = write(*document, dir.filePath("again.pdf"));
            QVERIFY2(again.ok, again.error.c_str());
            QVERIFY2(streamsOf(dir.filePath("again.pdf")) == streams, example);
        }
    }

    // Two exports at once (the window exports on a pool thread while the CLI or another
    // export runs): four threads share the fonts; each PDF equals the one written alone.
    void twoExportsAtOnce() {
        QTemporaryDir dir;
        const auto scara = documentOf("scara.json");
        const auto panda = documentOf("panda.json");
        QVERIFY(write(*scara, dir.filePath("scara-alone.pdf")).ok);
        QVERIFY(write(*panda, dir.filePath("panda-alone.pdf")).ok);
        Written a, b;
        std::thread other([&] { a = write(*scara, dir.filePath("scara-together.pdf")); });
        b = write(*panda, dir.filePath("panda-together.pdf"));
        other.join();
        QVERIFY2(a.ok && b.ok, (a.error + b.error).c_str());
        QVERIFY(streamsOf(dir.filePath("scara-together.pdf")) == streamsOf(dir.filePath("scara-alone.pdf")));
        QVERIFY(streamsOf(dir.filePath("panda-together.pdf")) == streamsOf(dir.filePath("panda-alone.pdf")));
        QVERIFY(pagesIn(streamsOf(dir.filePath("panda-together.pdf"))) > 10);
    }

    // The window's SVG and PNG pages (File ▸ Export ▸ Derivation) on pool threads while
    // a PDF is written: each file equals the one written alone (the SVG byte for byte:
    // it has no date; the PNG pixel for pixel).
    void svgAndPngBesideAPdf() {
        QTemporaryDir dir;
        const auto scara = documentOf("scara.json");
        const auto planar = documentOf("planar_2r.json");
        const ui::DerivationPages scaraPages = ui::paginate(*scara), planarPages = ui::paginate(*planar);
        std::string error;
        std::vector<QString> svgAlone, pngAlone, svgTogether, pngTogether;
        QVERIFY(QDir().mkpath(dir.filePath("alone")));
        QVERIFY2(ui::writeSvg(scaraPages, dir.filePath("alone/s.svg"), error, &svgAlone), error.c_str());
        QVERIFY(ui::writePng(planarPages, dir.filePath("alone/p.png"), error, &pngAlone, 72));
        QVERIFY(QDir().mkpath(dir.filePath("together")));
        bool svgOk = false, pngOk = false;
        std::string svgError, pngError;
        std::thread svg([&] {
            const ui::DerivationPages pages = ui::paginate(*scara);  // laid out on this thread, as the window does
            svgOk = ui::writeSvg(pages, dir.filePath("together/s.svg"), svgError, &svgTogether);
        });
        std::thread png([&] {
            const ui::DerivationPages pages = ui::paginate(*planar);
            pngOk = ui::writePng(pages, dir.filePath("together/p.png"), pngError, &pngTogether, 72);
        });
        const Written pdf = write(*scara, dir.filePath("together/s.pdf"));
        svg.join();
        png.join();
        QVERIFY2(svgOk && pngOk && pdf.ok, (svgError + pngError + pdf.error).c_str());
        QCOMPARE(svgTogether.size(), svgAlone.size());
        QCOMPARE(pngTogether.size(), pngAlone.size());
        QVERIFY(svgAlone.size() >= 3);
        const auto bytes = [](const QString& path) {
            QFile f(path);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        for (std::size_t i = 0; i < svgAlone.size(); ++i) {
            const QByteArray a = bytes(svgAlone[i]);
            QVERIFY(a.contains("<use "));
            QVERIFY2(a == bytes(svgTogether[i]), qPrintable(svgTogether[i]));
        }
        for (std::size_t i = 0; i < pngAlone.size(); ++i)
            QVERIFY2(QImage(pngAlone[i]) == QImage(pngTogether[i]), qPrintable(pngTogether[i]));
    }

    // `derive --format pdf`: the pages are laid out and written on two threads while this
    // one still shapes the document (core/symbolic/display_stream). The PDF equals the one
    // written from the finished document, whichever side waits for the other: the real
    // derivation (expanded 2R and SCARA, structured Panda handed over whole), and a
    // document handed over item by item with pauses, so the layout thread waits mid-step.
    void aPdfWrittenWhileTheDocumentIsShaped() {
        QTemporaryDir dir;
        for (const char* example : {"planar_2r.json", "scara.json", "panda.json"}) {
            const auto whole = documentOf(example);
            QVERIFY(write(*whole, dir.filePath("whole.pdf")).ok);
            const QList<QByteArray> expected = streamsOf(dir.filePath("whole.pdf"));
            QVERIFY(pagesIn(expected) >= 1);

            symbolic::DisplayStream stream;
            StreamWriter writer(stream, dir.filePath("streamed.pdf"));
            DocumentRequest request;
            request.displayStream = &stream;
            const auto shaped = deriveDisplay(loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example).scene, request).display;
            const Written streamed = writer.join();
            QVERIFY2(streamed.ok, streamed.error.c_str());
            QCOMPARE(shaped->steps.size(), whole->steps.size());
            QVERIFY2(streamsOf(dir.filePath("streamed.pdf")) == expected, example);

            symbolic::DisplayStream slow;
            StreamWriter slowWriter(slow, dir.filePath("paused.pdf"));
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            slow.open(*whole);
            for (const symbolic::DisplayStep& step : whole->steps) {
                slow.putStep(step);
                for (std::size_t j = 0; j < step.items.size(); ++j) {
                    if (j % 3 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                    slow.putItem(step.items[j]);
                }
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            slow.close(whole->actuation);
            const Written paused = slowWriter.join();
            QVERIFY2(paused.ok, paused.error.c_str());
            QCOMPARE(paused.pages, pagesIn(expected));
            QVERIFY2(streamsOf(dir.filePath("paused.pdf")) == expected, example);
        }
    }

    // The shaping fails half way (an error, a cancel): the writer stops, says so, and
    // saves nothing (no half file, and an older file of that name is left as it was).
    void aFailedShapingSavesNothing() {
        QTemporaryDir dir;
        const QString path = dir.filePath("derivation.pdf");
        {
            QFile old(path);
            QVERIFY(old.open(QIODevice::WriteOnly));
            old.write("an older export");
        }
        const auto whole = documentOf("scara.json");
        symbolic::DisplayStream stream;
        StreamWriter writer(stream, path);
        stream.open(*whole);
        stream.putStep(whole->steps.at(0));
        for (const symbolic::DisplayItem& item : whole->steps.at(0).items) stream.putItem(item);
        stream.putStep(whole->steps.at(1));
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the first page laid out, waiting
        stream.fail();
        const Written w = writer.join();
        QVERIFY(!w.ok);
        QVERIFY2(w.error.find("derivation stopped") != std::string::npos, w.error.c_str());
        QFile old(path);
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("an older export"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(), 1);  // no temporary left

        // And a derivation that throws fails its stream itself (the CLI's writer is never
        // left waiting): a scene whose shaping is cancelled before it starts.
        symbolic::DisplayStream cancelled;
        StreamWriter cancelledWriter(cancelled, dir.filePath("cancelled.pdf"));
        std::atomic<bool> cancel{true};
        DocumentRequest request;
        request.displayStream = &cancelled;
        request.cancel = &cancel;
        QVERIFY_THROWS_EXCEPTION(Cancelled, deriveDisplay(loadScene(std::string(LL_EXAMPLES_DIR) + "/scara.json").scene, request));
        const Written c = cancelledWriter.join();
        QVERIFY(!c.ok);
        QVERIFY(!QFile::exists(dir.filePath("cancelled.pdf")));
    }
};

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    TestPdfThreads test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_pdf_threads.moc"
