// Where each item and matrix entry stands in the text document (core/present/
// text_document's spans, what the window's text view picks from a click): on the 2R,
// the PUMA 560 and the Panda, every entry's span holds exactly that entry as the text
// prints it — a block matrix's cell, or a listed entry's "b11 = …" line.
#include "test_registry.hpp"

#include <sstream>

#include "core/io/scene_file.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/present/labels.hpp"
#include "core/present/text_document.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_text_spans {

using namespace ll;

namespace {

// Columns [from, to) of a line, as a terminal counts them (a combining mark takes none).
std::string columns(const std::string& line, int from, int to) {
    std::string out;
    int column = -1;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const unsigned char b = static_cast<unsigned char>(line[i]);
        const bool continuation = (b & 0xC0) == 0x80;
        const bool combining = b == 0xCC || (b == 0xCD && i + 1 < line.size() && static_cast<unsigned char>(line[i + 1]) < 0xB0);
        if (!continuation && !combining) ++column;
        if (column >= from && column < to) out += line[i];
    }
    return out;
}

std::string trimmed(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    while (!s.empty() && s.front() == ' ') s.erase(0, 1);
    return s;
}

}  // namespace

class TestTextSpans : public QObject {
    Q_OBJECT

private slots:
    void spansHoldTheirEntries_data() {
        QTest::addColumn<QString>("example");
        QTest::newRow("2R") << "planar_2r.json";
        QTest::newRow("PUMA 560") << "puma560.json";
        QTest::newRow("Panda") << "panda.json";
    }
    void spansHoldTheirEntries() {
        QFETCH(QString, example);
        const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + example.toStdString()).scene;
        const auto display = deriveDisplay(scene, {}).display;
        std::vector<present::TextSpan> spans;
        const std::string text = present::textDocument(*display, &spans);
        QCOMPARE(text, present::textDocument(*display));  // the spans change nothing
        std::vector<std::string> lines;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        int cells = 0, items = 0;
        for (const present::TextSpan& s : spans) {
            QVERIFY(s.line >= 0 && s.line < static_cast<int>(lines.size()));
            const present::DisplayItem& item = display->steps[static_cast<std::size_t>(s.step)].items[static_cast<std::size_t>(s.item)];
            const std::string shown = trimmed(columns(lines[static_cast<std::size_t>(s.line)], s.from, s.to));
            if (s.row < 0) {
                ++items;
                continue;
            }
            ++cells;
            const present::DisplayNode& cell = *item.value->rows[static_cast<std::size_t>(s.row)][static_cast<std::size_t>(s.col)];
            const std::string value = present::renderDisplay(cell, present::DisplayStyle::Text);
            const std::string listed =
                present::entryName(item, static_cast<std::size_t>(s.row), static_cast<std::size_t>(s.col)) + " = " + value;
            QVERIFY2(shown == value || shown == listed, (item.name + ": '" + shown + "' is not '" + value + "'").c_str());
        }
        // the expanded form's B, C, g are matrices (cells); the structured form lists b_jk as items
        if (display->form.id == MessageId::FormExpanded) QVERIFY(cells >= 3);
        QVERIFY(items > 0);
    }
};

LL_TEST_GUILESS_MAIN(TestTextSpans)

}  // namespace test_text_spans
#include "test_text_spans.moc"
