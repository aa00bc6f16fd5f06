// The catalogue of the core's messages (issue 46): every id has English words and Danish
// words with the same arguments, so a message added to core/model/messages/*.def without
// its line in core/present/danish/*.def fails here, naming it; and a message is turned
// into words at the edge, each argument in the same language.
#include "test_registry.hpp"

#include <set>
#include <string>

#include "core/model/diagnostics.hpp"
#include "core/model/message.hpp"
#include "core/model/message_error.hpp"
#include "core/present/diagnostic_text.hpp"
#include "core/present/message_text.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_message_catalogue {

using namespace ll;
namespace present = ll::present;

namespace {

std::vector<MessageId> everyId() {
    std::vector<MessageId> ids;
    for (int k = static_cast<int>(MessageId::Literal) + 1; k < static_cast<int>(MessageId::Count); ++k)
        ids.push_back(static_cast<MessageId>(k));
    return ids;
}

}  // namespace

class TestMessageCatalogue : public QObject {
    Q_OBJECT
private slots:
    void everyIdHasEnglishAndDanishWithTheSameArguments() {
        QVERIFY(everyId().size() > 100);  // the catalogue is read, not empty
        QStringList missing, mismatched;
        for (MessageId id : everyId()) {
            const std::string english = englishWords(id);
            QVERIFY2(!english.empty(), messageIdName(id));
            const char* danish = present::danishWords(id);
            if (!danish || !*danish) {
                missing << messageIdName(id);
                continue;
            }
            if (placeholders(danish) != placeholders(english)) mismatched << messageIdName(id);
        }
        QVERIFY2(missing.isEmpty(), qPrintable("no Danish words for: " + missing.join(", ")));
        QVERIFY2(mismatched.isEmpty(), qPrintable("Danish and English take different arguments: " + mismatched.join(", ")));
    }

    void idsHaveDistinctNames() {
        std::set<std::string> names;
        for (MessageId id : everyId()) QVERIFY2(names.insert(messageIdName(id)).second, messageIdName(id));
    }

    void onlyDigitPlaceholdersAreFilledIn() {
        QCOMPARE(filledIn("a {1} {x} {2}{1} {9} {\"k\": 1}", {"A", "B"}), std::string("a A {x} BA  {\"k\": 1}"));
    }

    // Arguments are numbers as formatValue writes them and nested messages in the same
    // language as the message around them.
    void argumentsAreWrittenInTheMessagesLanguage() {
        const Message m = message(MessageId::LikelyUnitSlip, message(MessageId::FieldOfJoint, "robot.joints[1].mass", 2),
                                  message(MessageId::ValueNotFinite, 1.0 / 0.0));
        QCOMPARE(m.english(), std::string("a unit slip, robot.joints[1].mass (joint 2): value is not finite (inf)"));
        QCOMPARE(present::messageText(m, present::Language::English), m.english());
        QCOMPARE(present::messageText(m, present::Language::Danish),
                 std::string("en enhedsfejl, robot.joints[1].mass (led 2): værdien er ikke endelig (inf)"));
        QCOMPARE(message(MessageId::ValueSubnormal, 1e-310, 2.2250738585072014e-308).english(),
                 std::string("value 1e-310 is too close to zero for double precision (subnormal, below 2.22507e-308): "
                             "write 0 for zero, else check the exponent"));
    }

    // The frame of a diagnostic (error:/fejl:, the joint in words, hint:/tip:) comes from the
    // catalogue too; English is what Diagnostic::toString() prints.
    void aDiagnosticIsWrittenWholeInOneLanguage() {
        const Diagnostic d{Severity::Error, jointField(0, "mass"), message(MessageId::ValueNotFinite, 0.0 / 0.0),
                           message(MessageId::LikelyLightLinks, message(MessageId::ArmatureAdvice, 1))};
        QCOMPARE(present::diagnosticText(d, present::Language::English), d.toString());
        const std::string danish = present::diagnosticText(d, present::Language::Danish);
        QVERIFY2(danish.starts_with("fejl: robot.joints[0].mass (led 1): værdien er ikke endelig ("), danish.c_str());
        QVERIFY2(danish.find("\ntip: lette yderste links") != std::string::npos, danish.c_str());
        QCOMPARE(present::diagnosticText(d, present::Language::Danish, present::Place::Omitted).substr(0, 6), std::string("fejl: "));
    }

    // An exception of ours is worded in the reader's language, its what() in English; a
    // library's own words stay as they are.
    void anErrorOfOursIsWordedInTheReadersLanguage() {
        const MessageError saving(
            message(MessageId::CannotSave, "/tmp/a.json", message(MessageId::CannotWriteTemporary, "/tmp/a.json.tmp-1")));
        QCOMPARE(std::string(saving.what()), std::string("/tmp/a.json: cannot save: cannot write /tmp/a.json.tmp-1"));
        QCOMPARE(present::errorText(saving, present::Language::English), std::string(saving.what()));
        QCOMPARE(present::errorText(saving, present::Language::Danish),
                 std::string("/tmp/a.json: kan ikke gemme: kan ikke skrive /tmp/a.json.tmp-1"));
        const InputError input(jointField(1, "mass"), message(MessageId::ValueNotFinite, "nan"));
        QCOMPARE(present::errorText(input, present::Language::Danish),
                 std::string("robot.joints[1].mass (led 2): værdien er ikke endelig (nan)"));
        QCOMPARE(present::errorText(std::runtime_error("rem: arguments must be polynomials"), present::Language::Danish),
                 std::string("rem: arguments must be polynomials"));
    }
};

LL_TEST_GUILESS_MAIN(TestMessageCatalogue)

}  // namespace test_message_catalogue
#include "test_message_catalogue.moc"
