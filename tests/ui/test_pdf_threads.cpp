// The typeset pages on several threads at once (ui/derivation_pages): the window exports
// on a pool thread while another export runs (a PDF beside SVG or PNG pages too), and
// they share Qt's fonts. Labelled `threads`: `scripts/lab tsan` runs it under ThreadSanitizer, which must
// report no race.
//
// Every PDF is compared with the same document written alone first: its page count and
// every stream inflated (each glyph's position, the font subsets), so a race that drops,
// reorders or corrupts a page fails here even without the sanitizer.
#include "test_registry.hpp"

#include <QGuiApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <thread>

#include "core/io/scene_file.hpp"
#include "core/model/cancellation.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "ui/paint/derivation_pages.hpp"
#include "ui/paint/math_typesetter.hpp"
#include "pdf_streams.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_pdf_threads {

using namespace ll;

namespace {

std::shared_ptr<const present::DisplayDocument> documentOf(const char* example) {
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

Written write(const present::DisplayDocument& document, const QString& path) {
    Written w;
    w.ok = ui::writePdf(document, path, w.error, {}, &w.pages);
    return w;
}

}  // namespace

class TestPdfThreads : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY2(ui::mathFontsAvailable(), "fonts-lmodern is not installed"); }

    // One document: every page laid out is written, the same each time.
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
    // export runs): two threads share the fonts; each PDF equals the one written alone.
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
};

static int runPdfThreads(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    TestPdfThreads test;
    return QTest::qExec(&test, argc, argv);
}
LL_TEST_PROGRAM(runPdfThreads)

}  // namespace test_pdf_threads
#include "test_pdf_threads.moc"
