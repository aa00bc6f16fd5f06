// json_writer: the derivation's JSON is written as it is produced, without a nlohmann
// document. Checked against nlohmann itself, the independent implementation: the same
// documents (fixed and random) dumped with dump(2), and with dump() in the compact layout,
// are the same bytes; invalid UTF-8 is refused by both; and the CLI's JSON of the 2R,
// the expanded SCARA and the structured Panda (compact) reads back and dumps again to
// exactly what the CLI wrote.
#include "test_registry.hpp"

#include <cmath>
#include <random>

#include <nlohmann/json.hpp>

#include "core/present/json_writer.hpp"
#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_json_writer {

using ll::present::JsonWriter;
using ordered = nlohmann::ordered_json;

namespace {

// The same value written by JsonWriter, as nlohmann's dump(2) lays it out.
void write(JsonWriter& w, const ordered& j) {
    switch (j.type()) {
        case ordered::value_t::object:
            w.beginObject();
            for (const auto& [key, value] : j.items()) {
                w.key(key);
                write(w, value);
            }
            w.endObject();
            return;
        case ordered::value_t::array:
            w.beginArray();
            for (const ordered& value : j) write(w, value);
            w.endArray();
            return;
        case ordered::value_t::string: return w.value(j.get<std::string>());
        case ordered::value_t::boolean: return w.value(j.get<bool>());
        case ordered::value_t::number_integer:
        case ordered::value_t::number_unsigned: return w.value(j.get<long long>());
        case ordered::value_t::number_float: return w.value(j.get<double>());
        default: QFAIL("a value type the derivation's JSON does not have");
    }
}

std::string written(const ordered& j, JsonWriter::Layout layout = JsonWriter::Layout::Indented) {
    std::string out;
    JsonWriter w(out, layout);
    write(w, j);
    return out;
}

std::string compact(const ordered& j) { return written(j, JsonWriter::Layout::Compact); }

// A random valid UTF-8 string: ASCII (every control character among it), 2-, 3- and
// 4-byte sequences, quotes and backslashes.
std::string randomString(std::mt19937& rng) {
    std::uniform_int_distribution<int> length(0, 12), kind(0, 5), ascii(0, 127);
    const char* const pieces[] = {"θ", "q̇", "ℓ", "−", "⎡", "𝔸", "\"", "\\", "é", "\u07FF", "\uFFFD", "\U0010FFFF"};
    std::uniform_int_distribution<int> piece(0, static_cast<int>(std::size(pieces)) - 1);
    std::string s;
    for (int i = length(rng); i > 0; --i)
        if (kind(rng) < 3) s += static_cast<char>(ascii(rng));
        else s += pieces[piece(rng)];
    return s;
}

ordered randomValue(std::mt19937& rng, int depth) {
    std::uniform_int_distribution<int> kind(0, depth > 3 ? 4 : 7), size(0, 4);
    std::uniform_real_distribution<double> real(-1e3, 1e3);
    switch (kind(rng)) {
        case 0: return randomString(rng);
        case 1: return std::uniform_int_distribution<long long>(-1000000, 1000000)(rng);
        case 2: {
            const double x = real(rng);
            const int scale = std::uniform_int_distribution<int>(-12, 12)(rng);
            return std::ldexp(x, scale * 4);  // 1e-05-like and 2.0-like forms both come up
        }
        case 3: return std::uniform_int_distribution<int>(0, 1)(rng) == 1;
        case 4: return static_cast<double>(std::uniform_int_distribution<int>(-5, 5)(rng));  // 2.0, -0.0
        case 5:
        case 6: {
            ordered a = ordered::array();
            for (int i = size(rng); i > 0; --i) a.push_back(randomValue(rng, depth + 1));
            return a;
        }
        default: {
            ordered o = ordered::object();
            for (int i = size(rng); i > 0; --i) o[randomString(rng) + std::to_string(i)] = randomValue(rng, depth + 1);
            return o;
        }
    }
}

}  // namespace

class TestJsonWriter : public QObject {
    Q_OBJECT
private slots:
    void fixedDocumentAsNlohmannDumpsIt() {
        ordered j;
        j["system"] = "Planar 2R \"elbow\" \\ θ₁";
        j["mode"] = "parameters";
        j["coordinates"] = {"q1", "q2"};
        j["empty array"] = ordered::array();
        j["empty object"] = ordered::object();
        j["controls"] = std::string("\x01\b\t\n\f\r\x1f\x7f end", 13);
        j["numbers"] = {0, -7, 0.008, 1e-05, 2.0, 1e300, -0.0, 0.1 + 0.2};
        j["flags"] = {true, false};
        j["nested"] = {{"a", ordered::array({ordered::array({"x", "y"}), ordered::array()})}, {"b", {{"c", 1}}}};
        j["ünïcödé 𝔸"] = "c̈ ⎡⎤ −";
        QCOMPARE(QString::fromStdString(written(j)), QString::fromStdString(j.dump(2)));
        QCOMPARE(QString::fromStdString(compact(j)), QString::fromStdString(j.dump()));
    }

    void randomDocumentsAsNlohmannDumpsThem() {
        std::mt19937 rng(20261124);
        for (int k = 0; k < 300; ++k) {
            const ordered j = randomValue(rng, 0);
            const std::string expected = j.dump(2), got = written(j);
            if (got != expected)
                QFAIL(qPrintable(QString("document %1 differs:\n%2\n---\n%3")
                                     .arg(k)
                                     .arg(QString::fromStdString(expected), QString::fromStdString(got))));
            const std::string expectedCompact = j.dump(), gotCompact = compact(j);
            if (gotCompact != expectedCompact)
                QFAIL(qPrintable(QString("document %1 differs (compact):\n%2\n---\n%3")
                                     .arg(k)
                                     .arg(QString::fromStdString(expectedCompact), QString::fromStdString(gotCompact))));
        }
    }

    void invalidUtf8RefusedAsByNlohmann() {
        for (const std::string bad :
             {std::string("a\xC3"), std::string("\xC0\x80"), std::string("\xED\xA0\x80"), std::string("\xF4\x90\x80\x80"),
              std::string("\x80"), std::string("\xE2\x82"), std::string("ok \xFF")}) {
            QVERIFY_THROWS_EXCEPTION(nlohmann::json::exception, (void)ordered(bad).dump(2));
            std::string out;
            JsonWriter w(out);
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, w.value(bad));
        }
        // The longest sequences at the edges are valid for both.
        const std::string edges = "\xC2\x80 \xDF\xBF \xE0\xA0\x80 \xED\x9F\xBF \xEE\x80\x80 \xF0\x90\x80\x80 \xF4\x8F\xBF\xBF";
        QCOMPARE(written(ordered(edges)), ordered(edges).dump(2));
    }

    void misuseIsALogicError() {
        std::string out;
        JsonWriter w(out);
        w.beginObject();
        QVERIFY_THROWS_EXCEPTION(std::logic_error, w.value("no key"));
        w.key("k");
        QVERIFY_THROWS_EXCEPTION(std::logic_error, w.key("two keys"));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, w.endArray());
        w.value(1);
        QVERIFY(!w.complete());
        w.endObject();
        QVERIFY(w.complete());
        QVERIFY_THROWS_EXCEPTION(std::logic_error, w.value(2));
    }

    // The CLI's derivation JSON, read back and dumped by nlohmann, is the same bytes.
    void derivationJsonReadsBackUnchanged() {
        const QString examples = LL_EXAMPLES_DIR;
        for (const QStringList& args :
             {QStringList{"derive", examples + "/planar_2r.json", "--format", "json"},
              QStringList{"derive", examples + "/scara.json", "--format", "json", "--form", "expanded", "--symbolic"}}) {
            const auto run = ll::test::runProcess(LL_CLI, args);
            QCOMPARE(run.exitCode, 0);
            const std::string document = run.out.toStdString();
            const ordered j = ordered::parse(document);
            QVERIFY(j.at("steps").size() >= 9);
            QVERIFY(!j.at("B").empty());
            QCOMPARE(QString::fromStdString(document), QString::fromStdString(j.dump(2) + "\n"));
        }
        // The structured form's JSON (the Panda's default), one compact line.
        const auto run = ll::test::runProcess(LL_CLI, {"derive", examples + "/panda.json", "--format", "json"});
        QCOMPARE(run.exitCode, 0);
        const std::string document = run.out.toStdString();
        const ordered j = ordered::parse(document);
        QCOMPARE(j.at("form").get<std::string>(), std::string("structured"));
        QVERIFY(j.at("definitions").size() > 500);
        QCOMPARE(j.at("B").size(), std::size_t(7));
        QCOMPARE(QString::fromStdString(document), QString::fromStdString(j.dump() + "\n"));
    }
};

LL_TEST_GUILESS_MAIN(TestJsonWriter)

}  // namespace test_json_writer
#include "test_json_writer.moc"
