// The derivation linked to the motion, in the window under a real X server: an entry
// picked (by id, by a click in the text view, in the teach panel's results) lights up the
// links that feed it in 3D and nothing else; its value at a time of the run is `eval`'s
// (a separate process) at the trajectory's state then; a link clicked marks the entries it
// feeds and selects its inertials row; the Torques and Properties tabs fill from the run.
#include "test_registry.hpp"

#include <set>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QTextBlock>

#include "process_run.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/entry_list.hpp"
#include "ui/window/main_window.hpp"
#include "window_checks.hpp"
#include "window_waits.hpp"
#include "ui/window/entry_linking.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/properties_panel.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/torque_pane.hpp"
#include "ui/window/trajectory_chart.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_linked_derivation {

using ll::ui::MainWindow;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR "/") + name; }

bool settled(MainWindow& w, int seconds = 120) {
    return ll::test::waitUntil(
        [&] {
            return w.result() && !w.liveSimulation().busy() && !w.liveDerivation().busy() && w.derivation() &&
                   w.result()->request == w.liveSimulation().latestRequest() && w.selection().catalogue();
        },
        seconds * 1000);
}

// A window at 1280×800 with `name` opened, simulated and derived.
std::unique_ptr<MainWindow> opened(const char* name) {
    return ll::test::openedWindow(example(name), [](MainWindow& w) { return settled(w); });
}

std::vector<int> lit(MainWindow& w) {
    std::vector<int> links;
    const std::vector<float> s = ll::test::linkStrengths(w);
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i] >= 0) links.push_back(static_cast<int>(i));
    return links;
}

}  // namespace

class TestLinkedDerivation : public QObject {
    Q_OBJECT

private:
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        ll::test::keepWindowStateIn(dir_);
    }

    // The 2R: b11 lights links 1 and 2, b22 link 2 alone and fades link 1; b11 depends on
    // q2, so joint 2's axis is drawn and joint 1's is not.
    void planar2rLinksLightUp() {
        const auto window = opened("planar_2r.json");
        MainWindow& w = *window;
        QVERIFY(w.linking().selectEntry("b11"));
        QCOMPARE(lit(w), (std::vector<int>{0, 1}));
        const ll::VisualScene& scene = *w.result()->visual;
        int axes = 0;
        for (std::size_t i = 0; i < scene.parts.size(); ++i)
            if (w.sceneView().emphasis().axes[i] != ll::AxisMark::None) {
                QCOMPARE(scene.parts[i].role, ll::PartRole::Joint);
                QCOMPARE(scene.parts[i].coordinate, 1);
                ++axes;
            }
        QCOMPARE(axes, 1);
        QVERIFY(w.linking().selectEntry("b22"));
        QCOMPARE(lit(w), (std::vector<int>{1}));
        QCOMPARE(ll::test::linkStrengths(w)[0], -1.0f);
        QVERIFY(w.linking().readoutText().contains("b22"));
        QVERIFY(w.linking().readoutText().contains("kg·m²"));
        // its curve over the run beside the energy plot
        QVERIFY(w.entryChart().isVisible());
        QVERIFY(w.entryChart().curvePoints() > 100);
        // an unknown entry is refused and the pick kept
        QVERIFY(!w.linking().selectEntry("b99"));
        QCOMPARE(w.selection().entry()->id, std::string("b22"));
    }

    // The PUMA's g1 is identically zero (joint 1's axis is vertical): nothing lights up.
    void zeroEntryLightsNothing() {
        const auto window = opened("puma560.json");
        MainWindow& w = *window;
        QVERIFY(w.linking().selectEntry("g1"));
        QVERIFY(lit(w).empty());
        for (float s : ll::test::linkStrengths(w)) QCOMPARE(s, -1.0f);
        QVERIFY(w.linking().readoutText().contains("no link"));
    }

    // The Panda (structured form): each β_jk⁽ⁱ⁾ lights link i alone.
    void betaLightsItsLink() {
        const auto window = opened("panda.json");
        MainWindow& w = *window;
        int betas = 0;
        for (const ll::CatalogueEntry& e : w.selection().catalogue()->entries) {
            if (e.id.rfind("beta", 0) != 0 || betas >= 12) continue;
            ++betas;
            QVERIFY(w.linking().selectEntry(QString::fromStdString(e.id)));
            QCOMPARE(lit(w), std::vector<int>{e.link});
        }
        QCOMPARE(betas, 12);
    }

    // The value shown at a time of the run is `eval`'s at the trajectory's state then
    // (a sample's time, so the state is the trajectory's own), within 1e-9 relative.
    void valueIsEvalAtTheState() {
        const auto window = opened("puma560.json");
        MainWindow& w = *window;
        QVERIFY(w.linking().selectEntry("b23"));
        const ll::Trajectory& traj = w.result()->simulation.trajectory;
        for (std::size_t k : {traj.size() / 5, traj.size() / 2, traj.size() - 1}) {
            w.playback().pause();
            w.playback().setTime(traj.t[k]);
            ll::test::flushEvents();
            QCOMPARE(w.selection().time(), traj.t[k]);
            const double shown = w.selection().value().at(0);
            QStringList q, qd;
            for (int i = 0; i < traj.n; ++i) {
                q << QString::number(traj.q[k][i], 'g', 17);
                qd << QString::number(traj.qd[k][i], 'g', 17);
            }
            const auto run = ll::test::runProcess(LL_CLI, {"eval", example("puma560.json"), "--q", q.join(','), "--qd", qd.join(',')});
            QCOMPARE(run.exitCode, 0);
            const double b23 = QJsonDocument::fromJson(run.out).object()["B"].toArray()[1].toArray()[2].toDouble();
            QVERIFY2(std::abs(shown - b23) <= 1e-9 * std::abs(b23), qPrintable(QString("%1 vs %2").arg(shown).arg(b23)));
        }
    }

    // A click on b12 in the text view picks it; the text view and the typeset view mark it.
    void clickInTheTextPicks() {
        const auto window = opened("planar_2r.json");
        MainWindow& w = *window;
        w.showDerivationView("text");
        auto* text = w.derivationPanel().findChild<QPlainTextEdit*>();
        QVERIFY(text);
        // Where b12 stands: the line starting "  b12 = " or the block's cell; click its middle.
        QTextCursor found = text->document()->find("I2 + m2 (ℓc2² + a1 ℓc2 c2)");
        QVERIFY(!found.isNull());
        QTextCursor at(text->document());
        at.setPosition(found.selectionStart() + 3);
        text->setTextCursor(at);
        text->ensureCursorVisible();
        ll::test::flushEvents();
        const QPoint p = text->cursorRect(at).center();
        QTest::mouseClick(text->viewport(), Qt::LeftButton, {}, p);
        ll::test::flushEvents();
        QVERIFY(w.selection().entry());
        const std::string id = w.selection().entry()->id;
        QVERIFY2(id == "b12" || id == "b21", id.c_str());
        QVERIFY(!text->extraSelections().isEmpty());
    }

    // Clicks across the typeset page of step 7 pick the entries of B drawn there, each
    // where it is drawn: every b_jk of the 2R is picked by some click, and nothing else
    // of B is.
    void clicksInTheTypesetPagePick() {
        const auto window = opened("planar_2r.json");
        MainWindow& w = *window;
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.showDerivationStep(7);
        ll::test::flushEvents();
        QWidget* canvas = w.derivationView().findChild<QWidget*>("derivation-canvas");
        QVERIFY(canvas);
        std::set<std::string> picked;
        // The scan again when the page was laid out anew under it (the window still
        // taking its size on a loaded machine moved b11 between clicks once in CI); a
        // real picking fault fails every pass.
        for (int pass = 0; pass < 3 && !picked.count("b11"); ++pass) {
            ll::test::flushEvents();
            const QSize size = canvas->size();
            for (int y = 4; y < std::min(canvas->height(), 700); y += 7)
                for (int x = 40; x < canvas->width() - 10; x += 24) {
                    w.selection().clear();
                    QTest::mouseClick(canvas, Qt::LeftButton, {}, QPoint(x, y));
                    if (const ll::CatalogueEntry* e = w.selection().entry()) picked.insert(e->id);
                }
            if (canvas->size() == size && picked.count("b11")) break;
        }
        for (const char* id : {"b11", "b12", "b21", "b22"}) QVERIFY2(picked.count(id), id);
        QVERIFY(picked.count("E_kin"));
    }

    // A link clicked (picked) marks every entry it feeds, and only those, and selects its
    // row in the inertials table.
    void pickedLinkMarksItsEntries() {
        const auto window = opened("planar_2r.json");
        MainWindow& w = *window;
        w.linking().pickLink(1);
        QCOMPARE(w.selection().link(), 1);
        const auto& marked = w.selection().marked();
        QVERIFY(!marked.empty());
        for (const ll::CatalogueEntry* e : marked) QVERIFY(std::find(e->links.begin(), e->links.end(), 1) != e->links.end());
        bool b11 = false, b22 = false;
        for (const ll::CatalogueEntry* e : marked) b11 |= e->id == "b11", b22 |= e->id == "b22";
        QVERIFY(b11 && b22);
        QCOMPARE(lit(w), std::vector<int>{1});
        const auto inertials = w.findChildren<QTableView*>();
        bool selected = false;
        for (QTableView* t : inertials)
            if (t->isVisible() && t->selectionModel() && t->selectionModel()->isRowSelected(1, {})) selected = true;
        QVERIFY(selected);
        QVERIFY(w.linking().readoutText().contains("link&nbsp;2"));
    }

    // The Torques tab draws a joint's parts; the Properties tab says every property holds.
    void torquesAndProperties() {
        const auto window = opened("puma560.json");
        MainWindow& w = *window;
        ll::test::waitUntil([&] { return w.analysis() != nullptr; }, 60000);
        QVERIFY(w.analysis());
        QVERIFY(w.showPlotTab("torques"));
        w.torquePane().setJoint(1);
        QVERIFY(w.torquePane().chart().curvePoints() > 100);
        QVERIFY(w.showPlotTab("properties"));
        QVERIFY(w.propertiesPanel().properties()->passed());
        QVERIFY(w.propertiesPanel().text().contains("All 6 properties"));
    }
};

LL_TEST_MAIN(TestLinkedDerivation)

}  // namespace test_linked_derivation
#include "test_linked_derivation.moc"
