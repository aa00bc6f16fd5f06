// The command line's usage errors in the reader's language: every id of the program's
// catalogue (app/usage_messages.def) has Danish words (app/usage_messages_da.def) with
// the same arguments, so an error added without its Danish line fails here, naming it; and
// the program, given a bad option, prints the catalogue's line in Danish under --lang da or
// LANGUAGE=da and its English line, unchanged, otherwise, with exit code 2.
#include "test_registry.hpp"

#include <QProcess>
#include <set>
#include <string>

#include "app/usage_message.hpp"
#include "process_run.hpp"
#include "core/model/message.hpp"
#include "core/present/message_text.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_usage_messages {

using namespace ll;
using cli::UsageId;
using cli::UsageMessage;
using present::Language;

namespace {

struct Run {
    int code;
    QString err;
};

// The program as on a fresh Debian, with `env` added.
Run run(const QStringList& args, const QStringList& env = {}) {
    const test::ProcessRun r = test::runProcess(LL_CLI, args, {}, test::freshLocaleEnvironment(env), 120000);
    return {r.exitCode, QString::fromUtf8(r.err)};
}

// The whole line the program prints for `message` in `language`, from the catalogues:
// the core's "error: "/"fejl: " and the message's words.
QString expectedLine(const UsageMessage& message, Language language) {
    return QString::fromStdString(present::messageText(MessageId::ErrorLine, language) + cli::usageText(message, language) + "\n");
}

QString scene() { return QString(LL_EXAMPLES_DIR) + "/planar_2r.json"; }

// Bad options of `check` (refused before the scene is read): the arguments, the message
// the program makes of them and its English line as the program has always printed it.
struct BadOption {
    QStringList args;
    UsageMessage message;
    const char* english;
};

std::vector<BadOption> badOptions() {
    return {
        {{"check", scene(), "--format", "bogus"},
         cli::usageMessage(UsageId::ExpectedOneOf, "format", "text", "json", "bogus"),
         "error: --format: expected text or json, got 'bogus'\n"},
        {{"check", scene(), "--bogus", "1"},
         cli::usageMessage(UsageId::UnknownOptionAmong, "bogus", "--duration, --format"),
         "error: unknown option --bogus (known: --duration, --format)\n"},
    };
}

}  // namespace

class TestUsageMessages : public QObject {
    Q_OBJECT
private slots:
    void everyIdHasDanishWithTheSameArguments() {
        const int count = static_cast<int>(UsageId::Count);
        QVERIFY(count > 40);  // the catalogue is read, not empty
        QStringList missing, mismatched;
        for (int k = static_cast<int>(UsageId::Literal) + 1; k < count; ++k) {
            const auto id = static_cast<UsageId>(k);
            const std::string english = cli::englishWords(id);
            QVERIFY2(!english.empty(), cli::usageIdName(id));
            const char* danish = cli::danishWords(id);
            if (!danish || !*danish) {
                missing << cli::usageIdName(id);
                continue;
            }
            if (placeholders(danish) != placeholders(english)) mismatched << cli::usageIdName(id);
        }
        QVERIFY2(missing.isEmpty(), qPrintable("no Danish words for: " + missing.join(", ")));
        QVERIFY2(mismatched.isEmpty(), qPrintable("Danish and English take different arguments: " + mismatched.join(", ")));
    }

    void badOptionUnderLangDaAndEn() {
        for (const BadOption& bad : badOptions()) {
            const QString danish = expectedLine(bad.message, Language::Danish);
            QVERIFY2(danish.startsWith("fejl: ") && danish != expectedLine(bad.message, Language::English), qPrintable(danish));
            const Run da = run(bad.args + QStringList{"--lang", "da"});
            QCOMPARE(da.code, 2);
            QCOMPARE(da.err, danish);
            const Run en = run(bad.args + QStringList{"--lang", "en"});
            QCOMPARE(en.code, 2);
            QCOMPARE(en.err, QString(bad.english));
            QCOMPARE(en.err, expectedLine(bad.message, Language::English));  // the catalogue's English is that line
            QCOMPARE(run(bad.args).err, QString(bad.english));               // English without a language asked for
        }
    }

    void badOptionUnderLanguageDaInTheEnvironment() {
        for (const BadOption& bad : badOptions()) {
            const Run da = run(bad.args, {"LANGUAGE=da"});
            QCOMPARE(da.code, 2);
            QCOMPARE(da.err, expectedLine(bad.message, Language::Danish));
            const Run en = run(bad.args + QStringList{"--lang", "en"}, {"LANGUAGE=da"});  // --lang wins
            QCOMPARE(en.code, 2);
            QCOMPARE(en.err, QString(bad.english));
        }
        // A bad --lang itself is told in the environment's language.
        const UsageMessage badLang = cli::usageMessage(UsageId::ExpectedOneOf, "lang", "da", "en", "xx");
        const Run da = run({"check", scene(), "--lang", "xx"}, {"LANGUAGE=da"});
        QCOMPARE(da.code, 2);
        QCOMPARE(da.err, expectedLine(badLang, Language::Danish));
        QCOMPARE(run({"check", scene(), "--lang", "xx"}).err, QString("error: --lang: expected da or en, got 'xx'\n"));
    }
};

LL_TEST_GUILESS_MAIN(TestUsageMessages)

}  // namespace test_usage_messages
#include "test_usage_messages.moc"
