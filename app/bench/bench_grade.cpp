// lagrangelab-bench --grade [--batches N]: what grading an exercise set costs (issue 47
// part 4's budget, docs/benchmarks.md): 30 students' answer files of 10 entries each of the
// planar 2R, each against its own robot (a derivation per student), grades.csv and 30
// feedback PDFs, as the whole `lagrangelab grade` process, spawn to reap (budget 10 s).
// Each sheet has its right answers but one wrong (a sign) and one left blank.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/bench/program_run.hpp"
#include "core/io/data_directory.hpp"
#include "core/io/scene_file.hpp"
#include "core/pipeline/exercise_set.hpp"

namespace ll::bench {

using ll::cli::median;

int grade(int runs) {
    namespace fs = std::filesystem;
    const std::string planar = (fs::path(examplesDirectory()) / "planar_2r.json").string();
    const fs::path work = fs::temp_directory_path() / ("lagrangelab-bench-grade-" + std::to_string(::getpid()));
    const fs::path set = work / "set", answers = work / "answers", log = work / "log.txt";
    fs::create_directories(answers);
    const std::string entries = "b11,b12,b22,c11,c12,c21,g1,g2,E_kin,E_pot";
    if (runLagrangelab({"exercise", planar, "--out", set.string(), "--count", "30", "--seed", "47", "--entries", entries}, log) != 0) {
        std::fprintf(stderr, "lagrangelab exercise failed: see %s\n", log.c_str());
        return 1;
    }
    for (int s = 1; s <= 30; ++s) {  // the templates filled: right but for one sign and one blank
        const std::string id = (s < 10 ? "s0" : "s") + std::to_string(s);
        std::ifstream in(set / id / "answers.json"), sceneIn(set / id / "scene.json");
        nlohmann::ordered_json sheet = nlohmann::ordered_json::parse(in);
        const std::string sceneText((std::istreambuf_iterator<char>(sceneIn)), {});
        const auto key = AnswerKey::build(parseScene(sceneText), symbolic::ParameterMode::Parametric);
        for (auto& [entry, answer] : sheet["answers"].items()) answer = maximaAnswer(*key, entry);
        sheet["answers"]["b11"] = "-(" + sheet["answers"]["b11"].get<std::string>() + ")";
        sheet["answers"]["E_pot"] = "";
        std::ofstream(answers / (id + ".json")) << sheet.dump(2);
    }
    std::vector<double> seconds;
    int failed = 0;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        if (runLagrangelab({"grade", set.string(), answers.string(), "--out", (work / "graded").string()}, log) != 0) ++failed;
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::printf("lagrangelab grade: 30 students x 10 entries of the planar 2R, each against its own robot, grades.csv and 30\n"
                "feedback PDFs, whole process, median of %d runs: %.2f s (budget 10 s)\n",
                runs, median(seconds));
    if (failed) std::fprintf(stderr, "%d runs failed: see %s\n", failed, log.c_str());
    else fs::remove_all(work);
    return failed ? 1 : 0;
}

}  // namespace ll::bench
