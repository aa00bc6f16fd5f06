// The window's answer key and checks on their worker (ui/document/answer_checking) while the
// window's derivation worker holds the GiNaC lock beside them; under ThreadSanitizer
// (labelled threads), which follows the results back through ui/document/handover.
//
// Every verdict that comes back is the one the same key gives when asked directly, for the
// newest scene and the newest answer of each entry: older answers' and older scenes'
// results never arrive, whatever order the worker finishes in.
#include "test_registry.hpp"

#include <map>

#include <QCoreApplication>

#include "core/io/scene_file.hpp"
#include "ui/document/answer_checking.hpp"
#include "ui/document/live_derivation.hpp"
#include "window_waits.hpp"

namespace test_answer_checking {

using namespace ll;

namespace {

Scene example(const char* name) { return loadScene(std::string(LL_EXAMPLES_DIR "/") + name).scene; }

}  // namespace

class TestAnswerChecking : public QObject {
    Q_OBJECT

private slots:
    void newestAnswerAndSceneWin() {
        const Scene planar = example("planar_2r.json");
        Scene longer = planar;
        longer.parameters.front().second *= 2;  // another a1: another key
        ui::AnswerChecking checking;
        ui::LiveDerivation derivation;  // the window's other GiNaC user, running beside
        std::map<QString, std::vector<std::pair<QString, AnswerCheck>>> got;
        QObject::connect(&checking, &ui::AnswerChecking::checked, [&](const QString& entry, const QString& answer, const AnswerCheck& c) {
            got[entry].push_back({answer, c});
        });
        const QStringList entries{"b11", "b12", "b22", "g1", "g2", "c12", "E_kin"};
        for (int round = 0; round < 6; ++round) {
            const Scene& scene = round % 2 ? longer : planar;
            checking.setScene(scene);
            derivation.request(scene);
            for (int k = 0; k < 4; ++k)
                for (const QString& e : entries) checking.check(e, QString("m2 a1 lc2 c2 + %1 I2").arg(k), k == 3);
            QVERIFY(ll::test::waitUntil([&] { return checking.key() != nullptr; }, 120000));
            // and again with the key there: each check starts on the worker at once
            for (int k = 0; k < 4; ++k)
                for (const QString& e : entries) checking.check(e, QString("m2 a1 lc2 c2 + %1 I2").arg(k), k == 3);
            if (round % 3 == 0) ll::test::waitUntil([&] { return !derivation.busy(); }, 120000);
        }
        // the last answers, checked with the last scene's key
        for (const QString& e : entries) checking.check(e, "I1 + I2 + m2 a1^2", false);
        QVERIFY(ll::test::waitUntil(
            [&] {
                return got.size() == std::size_t(entries.size()) && std::all_of(entries.begin(), entries.end(), [&](const QString& e) {
                           return !got[e].empty() && got[e].back().first == "I1 + I2 + m2 a1^2";
                       });
            },
            120000));
        checking.wait();
        derivation.wait();
        QCoreApplication::processEvents();
        const auto key = AnswerKey::build(longer);  // round 5 was the longer arm
        for (const QString& e : entries) {
            const auto& [answer, c] = got[e].back();
            const AnswerCheck direct = key->check({e.toStdString(), answer.toStdString()});
            QCOMPARE(int(c.verdict), int(direct.verdict));
            QCOMPARE(c.readAs, direct.readAs);
            QCOMPARE(c.kinds.size(), direct.kinds.size());
        }
        // per batch only the newest answer of each entry came back (the older three were
        // asked again before any result could arrive), with its right answer (it asked to reveal)
        for (const QString& e : entries) {
            QVERIFY2(got[e].size() <= 13, qPrintable(e));
            for (std::size_t k = 0; k + 1 < got[e].size(); ++k) {
                QCOMPARE(got[e][k].first, QString("m2 a1 lc2 c2 + 3 I2"));
                QVERIFY(!got[e][k].second.rightAnswer.empty());
            }
        }
    }
};

LL_TEST_GUILESS_MAIN(TestAnswerChecking)

}  // namespace test_answer_checking
#include "test_answer_checking.moc"
