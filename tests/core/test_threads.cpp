// The core called from several threads at once, as the window's workers will: GiNaC
// (not thread-safe) is serialised by one lock, everything that crosses threads is plain
// data, and long work stops promptly when cancelled. Labelled `threads`:
// `scripts/lab tsan` runs it under ThreadSanitizer, which must report no race.
//
// Each concurrent result is compared with the same work done alone first, so a race
// that corrupts an expression or a trajectory fails here even without the sanitizer.
#include "test_registry.hpp"

#include <atomic>
#include <chrono>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "core/io/scene_file.hpp"
#include "core/model/cancellation.hpp"
#include "core/pipeline/law_comparison.hpp"
#include "core/pipeline/scene_check.hpp"
#include "core/present/text_document.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/present/derivation_document.hpp"

#include <nlohmann/json.hpp>

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_threads {

using namespace ll;

namespace {

Scene example(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

std::string derive(const Scene& scene, symbolic::ParameterMode mode, present::DocumentFormat format) {
    DocumentRequest request;
    request.mode = mode;
    request.format = format;
    return deriveDocument(scene, request).document;
}

// The display trees the documents are rendered from.
std::shared_ptr<const present::DisplayDocument> displayTrees(const Scene& scene, symbolic::ParameterMode mode) {
    DocumentRequest request;
    request.mode = mode;
    request.format = present::DocumentFormat::Display;
    return deriveDocument(scene, request).display;
}

// Every JSON item (name, text, LaTeX, Plain) and the top-level results against the
// display trees rendered here, on one thread, one node at a time.
void compareJsonWithTrees(const nlohmann::json& json, const present::DisplayDocument& display, const char* name) {
    // JSON's Plain: a matrix as rows of entries (a column as a list).
    auto samePlain = [](const nlohmann::json& written, const present::DisplayNode& value) {
        const auto plain = [](const present::DisplayNode& n) { return present::renderDisplay(n, present::DisplayStyle::Plain); };
        if (value.kind != present::DisplayKind::Matrix) return written.get<std::string>() == plain(value);
        if (written.size() != value.rows.size()) return false;
        for (std::size_t r = 0; r < value.rows.size(); ++r)
            for (std::size_t c = 0; c < value.rows[r].size(); ++c) {
                const auto& cell = value.rows[r].size() == 1 ? written[r] : written[r][c];
                if (cell.get<std::string>() != plain(*value.rows[r][c])) return false;
            }
        return true;
    };
    QCOMPARE(json["steps"].size(), display.steps.size());
    std::map<std::string, const present::DisplayItem*> results;
    for (std::size_t k = 0; k < display.steps.size(); ++k) {
        const auto& items = display.steps[k].items;
        QCOMPARE(json["steps"][k]["items"].size(), items.size());
        for (std::size_t i = 0; i < items.size(); ++i) {
            const auto& written = json["steps"][k]["items"][i];
            QCOMPARE(written["name"].get<std::string>(), items[i].name);
            QCOMPARE(written["text"].get<std::string>(), present::itemText(items[i]));
            QCOMPARE(written["latex"].get<std::string>(), present::renderDisplay(*items[i].equation, present::DisplayStyle::Latex));
            if (items[i].name.rfind("equation_", 0) == 0)
                QCOMPARE(written["expr"].get<std::string>(), present::renderDisplay(*items[i].equation, present::DisplayStyle::Plain));
            else QVERIFY2(samePlain(written["expr"], *items[i].value), items[i].name.c_str());
            results[items[i].name] = &items[i];
        }
    }
    int repeated = 0;
    for (const auto& [top, item] : {std::pair{"B", "B"}, {"C", "C"}, {"g", "g"}, {"Q", "Q"}, {"Ekin", "E_kin"}, {"Epot", "E_pot"}}) {
        if (!results.count(item)) continue;
        QVERIFY2(samePlain(json[top], *results[item]->value), top);
        ++repeated;
    }
    QVERIFY2(repeated >= 4, name);
}

SimulationSettings shortRun(const Scene& scene, double duration) {
    SimulationSettings s = scene.simulation;
    s.duration = duration;
    return s;
}

double milliseconds(std::chrono::steady_clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

}  // namespace

class TestThreads : public QObject {
    Q_OBJECT

private slots:
    // Deriving the PUMA 560 fully symbolically, printing the planar 2R as LaTeX,
    // simulating the hand-typed Lagrangian pair, loading scene files and checking a
    // Lagrangian scene, all at the same time.
    void symbolicAndNumericWorkAtOnce() {
        const Scene puma = example("puma560.json");
        const Scene planar = example("planar_2r.json");
        const Scene pair = example("mass_spring_pair_lagrangian.json");
        const std::string pumaAlone = derive(puma, symbolic::ParameterMode::Textbook, present::DocumentFormat::Text);
        const std::string planarAlone = derive(planar, symbolic::ParameterMode::Parametric, present::DocumentFormat::Latex);
        const SimulationResult pairAlone = simulate(pair, shortRun(pair, 2.0));
        QVERIFY(pumaAlone.find("B = ") != std::string::npos);
        QVERIFY(pairAlone.status == SimulationStatus::Completed);

        std::string pumaTogether;
        std::vector<std::string> planarTogether(3);
        std::vector<SimulationResult> pairTogether(2);
        std::atomic<int> loads{0}, checks{0};
        std::vector<std::thread> threads;
        threads.emplace_back([&] { pumaTogether = derive(puma, symbolic::ParameterMode::Textbook, present::DocumentFormat::Text); });
        threads.emplace_back([&] {
            for (std::string& doc : planarTogether)
                doc = derive(planar, symbolic::ParameterMode::Parametric, present::DocumentFormat::Latex);
        });
        for (SimulationResult& r : pairTogether) threads.emplace_back([&] { r = simulate(pair, shortRun(pair, 2.0)); });
        threads.emplace_back([&] {
            for (int k = 0; k < 5; ++k) {
                if (example("elastic_pendulum.json").dof() == 2) ++loads;
                if (!hasErrors(checkScene(pair))) ++checks;
            }
        });
        for (std::thread& t : threads) t.join();

        QCOMPARE(pumaTogether, pumaAlone);
        for (const std::string& doc : planarTogether) QCOMPARE(doc, planarAlone);
        for (const SimulationResult& r : pairTogether) {
            QVERIFY(r.status == SimulationStatus::Completed);
            QCOMPARE(r.trajectory.size(), pairAlone.trajectory.size());
            QVERIFY(r.trajectory.q.back() == pairAlone.trajectory.q.back());  // bitwise: same tape, same steps
        }
        QCOMPARE(loads.load(), 5);
        QCOMPARE(checks.load(), 5);
    }

    // Controlled robots on several threads at once (each controller has its own model and
    // scratch data): the four laws of compare-laws on the 2R and the PUMA's computed torque,
    // twice together, equal to the same runs alone, bit for bit.
    void controlledRunsAtOnce() {
        Scene planar = example("control/planar_2r_pd.json");
        planar.simulation.duration = 1.0;
        Scene puma = example("control/puma560_payload_unknown.json");
        puma.simulation.duration = 1.0;
        const std::vector<LawRun> planarAlone = compareLaws(planar), pumaAlone = compareLaws(puma);
        std::vector<std::vector<LawRun>> together(4);
        std::vector<std::thread> threads;
        for (std::size_t k = 0; k < together.size(); ++k)
            threads.emplace_back([&, k] { together[k] = compareLaws(k % 2 ? puma : planar); });
        for (std::thread& t : threads) t.join();
        for (std::size_t k = 0; k < together.size(); ++k) {
            const std::vector<LawRun>& alone = k % 2 ? pumaAlone : planarAlone;
            QCOMPARE(together[k].size(), alone.size());
            for (std::size_t l = 0; l < alone.size(); ++l) {
                QVERIFY(together[k][l].error == alone[l].error);  // bitwise: the same steps
                QVERIFY(together[k][l].torque == alone[l].torque);
            }
        }
    }

    // A stale Panda derivation stops soon after its cancel flag is set; the latency
    // (flag set → Cancelled caught) is printed, not asserted (no wall-clock limits in
    // tests; `lagrangelab bench --derive` reports its median).
    void cancelStopsADerivation() {
        const Scene panda = example("panda.json");
        std::atomic<bool> cancel{false};
        std::atomic<int> entries{0};
        std::atomic<bool> cancelled{false};
        std::chrono::steady_clock::time_point stopped;
        std::thread worker([&] {
            DocumentRequest request;
            request.mode = symbolic::ParameterMode::Textbook;
            request.cancel = &cancel;
            request.progress = [&](int, const std::string&) { ++entries; };
            try {
                (void)deriveDocument(panda, request);
            } catch (const Cancelled&) {
                cancelled = true;
            }
            stopped = std::chrono::steady_clock::now();
        });
        while (entries.load() < 40) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        const auto set = std::chrono::steady_clock::now();
        cancel = true;
        worker.join();
        QVERIFY(cancelled.load());
        qInfo("Panda (symbolic) derivation cancelled after %d entries; it stopped %.2f ms after the flag was set", entries.load(),
              milliseconds(stopped - set));

        // The lock is free again: the next derivation runs to the end.
        const Scene planar = example("planar_2r.json");
        QVERIFY(derive(planar, symbolic::ParameterMode::Numeric, present::DocumentFormat::Text).find("B = ") != std::string::npos);
    }

    // A text, LaTeX or JSON document says exactly what the display trees say when
    // rendered on their own: the same text and LaTeX, and JSON whose every item, and the
    // B, C, g, Q and energies it repeats at the top level, match the trees.
    void documentsSayWhatTheirTreesSay() {
        for (const char* name : {"planar_2r.json", "puma560.json", "mass_spring_pair_lagrangian.json"}) {
            const Scene scene = example(name);
            for (const auto mode : {symbolic::ParameterMode::Parametric, symbolic::ParameterMode::Textbook}) {
                const auto display = displayTrees(scene, mode);
                QVERIFY(display && !display->steps.empty());
                for (const auto format : {present::DocumentFormat::Text, present::DocumentFormat::Latex})
                    QCOMPARE(derive(scene, mode, format), present::renderDocument(*display, format));

                compareJsonWithTrees(nlohmann::json::parse(derive(scene, mode, present::DocumentFormat::Json)), *display, name);
                if (QTest::currentTestFailed()) return;
            }
        }
    }

    // A long simulation and a work–precision analysis on workers stop with status
    // Cancelled and a partial result.
    void cancelStopsSimulationAndAccuracy() {
        const Scene pendulum = example("double_pendulum.json");
        std::atomic<bool> cancelSim{false}, cancelAccuracy{false};
        SimulationResult sim;
        WorkPrecisionResult accuracy;
        std::thread simulation([&] { sim = simulate(pendulum, shortRun(pendulum, 1e4), {}, &cancelSim); });
        std::thread analysis([&] {
            WorkPrecisionSettings settings;
            settings.duration = 5.0;
            accuracy = runWorkPrecision(pendulum, settings, {}, &cancelAccuracy);
        });
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        cancelSim = true;
        cancelAccuracy = true;
        simulation.join();
        analysis.join();
        QVERIFY(sim.status == SimulationStatus::Cancelled);
        QVERIFY(sim.trajectory.size() > 0);
        QVERIFY(sim.trajectory.t.back() < 1e4);
        QVERIFY(accuracy.status == SimulationStatus::Cancelled);
    }
};

LL_TEST_APPLESS_MAIN(TestThreads)

}  // namespace test_threads
#include "test_threads.moc"
