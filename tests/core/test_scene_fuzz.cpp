// The scene reader fed non-ASCII input: every example file with characters and bytes
// inserted at random places (inside expressions, names, keys, between tokens) and
// numbers replaced by strings with degree signs, look-alikes and broken UTF-8. Each
// one either loads or is refused with InputError; nothing else is thrown, nothing
// crashes, and every field and message is valid UTF-8.
#include "test_registry.hpp"

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "core/io/scene_file.hpp"
#include "core/model/utf8_text.hpp"
#include "core/simulation/scene_validation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_scene_fuzz {

using namespace ll;

namespace {

const char* const kInserts[] = {
    "\xC2\xB0",          // ° degree sign
    "\xC2\xBA",          // º ordinal indicator
    "\xE2\x88\x92",      // − minus sign
    "\xC3\x97",          // × multiplication sign
    "\xCF\x80",          // π
    "\xC2\xA0",          // no-break space
    "\xEF\xBB\xBF",      // byte order mark
    "\xF0\x9F\x98\x80",  // 😀, four bytes
    "\xC3\xA9",          // é
    "\xC2",              // a lead byte alone
    "\x80",              // a continuation byte alone
    "\xE2\x88",          // a truncated three-byte sequence
    "\xFF",              // never UTF-8
    "\xED\xA0\x80",      // an encoded surrogate
    "\xC0\xAF",          // an overlong '/'
    "\t",                // a control character
    "90\xC2\xB0",        // an angle in degrees
    " deg",
};

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    return content.str();
}

// Offsets where an insert lands inside a JSON string (after an opening quote) or
// replaces a number ("0.5" -> "\"0.5°\"").
std::string mutate(const std::string& text, std::mt19937& rng) {
    std::uniform_int_distribution<std::size_t> anywhere(0, text.size());
    std::uniform_int_distribution<std::size_t> pick(0, std::size(kInserts) - 1);
    const std::string insert = kInserts[pick(rng)];
    std::string out = text;
    switch (rng() % 3) {
        case 0: {  // inside a string value or key
            std::size_t at = text.find('"', anywhere(rng));
            if (at == std::string::npos) at = text.find('"');
            return out.insert(at + 1, insert);
        }
        case 1: {  // a bare number becomes an expression with the insert in it
            std::size_t at = text.find_first_of("0123456789", anywhere(rng));
            if (at == std::string::npos) return out.insert(anywhere(rng), insert);
            while (at > 0 && (std::isdigit(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '.' || text[at - 1] == '-')) --at;
            const std::size_t end = std::min(text.find_first_not_of("0123456789.e-", at), text.size());
            if (at == 0 || std::string(":[, \n").find(text[at - 1]) == std::string::npos) return out.insert(at, insert);
            return out.replace(at, end - at, "\"" + text.substr(at, end - at) + insert + "\"");
        }
        default:  // anywhere at all
            return out.insert(anywhere(rng), insert);
    }
}

}  // namespace

class TestSceneFuzz : public QObject {
    Q_OBJECT
private slots:
    void nonAsciiInputIsRefusedCleanly() {
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR))
            if (entry.path().extension() == ".json") files.push_back(entry.path());
        std::sort(files.begin(), files.end());
        QVERIFY(files.size() > 20);
        std::mt19937 rng(2026);
        int loaded = 0, refused = 0, namedCodePoint = 0;
        for (const auto& file : files) {
            const std::string original = readFile(file);
            for (int trial = 0; trial < 60; ++trial) {
                std::string text = mutate(original, rng);
                if (rng() % 4 == 0) text = mutate(text, rng);
                try {
                    const Scene scene = parseScene(text);
                    for (const Diagnostic& d : requireValidScene(scene))
                        QVERIFY2(isValidUtf8(d.field) && isValidUtf8(d.message.english()), d.toString().c_str());
                    ++loaded;
                } catch (const InputError& e) {
                    ++refused;
                    QVERIFY(isValidUtf8(e.what()));
                    for (const Diagnostic& d : e.diagnostics()) {
                        QVERIFY2(isValidUtf8(d.field) && isValidUtf8(d.message.english()),
                                 qPrintable(QString::fromStdString(validUtf8(d.toString()))));
                        namedCodePoint += d.message.english().find("(U+") != std::string::npos;
                    }
                } catch (const std::exception& e) {
                    QFAIL(qPrintable(QString::fromStdString(file.filename().string() + ": not an InputError: " + validUtf8(e.what()))));
                }
            }
        }
        // Both outcomes happen (text in descriptions is free), and refusals name the character.
        QVERIFY(loaded > 50);
        QVERIFY(refused > 200);
        QVERIFY(namedCodePoint > 50);
    }
};

LL_TEST_APPLESS_MAIN(TestSceneFuzz)

}  // namespace test_scene_fuzz
#include "test_scene_fuzz.moc"
