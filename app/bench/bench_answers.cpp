// lagrangelab-bench --answers [--batches N]: what checking a student's answer costs
// (issue 47's budgets, docs/benchmarks.md):
//  - whole `lagrangelab check-answer examples/puma560.json --entry b11 --answer …`
//    processes, spawn to reap, with the right answer expanded and with a wrong one (budget
//    0.3 s);
//  - one check against a key already built, as a window holding its derivation would
//    (budget 100 ms), right and wrong;
//  - 300 checks (30 students × 10 entries) of the planar 2R's entries against one key:
//    grading without the per-student derivations, which part 4 adds (budget 10 s).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/bench/program_run.hpp"
#include "core/io/data_directory.hpp"
#include "core/io/scene_file.hpp"
#include "core/pipeline/answer_key_data.hpp"
#include "core/symbolic/ginac_lock.hpp"

namespace ll::bench {

using ll::cli::median;

namespace {

double since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int answers(int runs) {
    namespace fs = std::filesystem;
    const std::string puma = (fs::path(examplesDirectory()) / "puma560.json").string();
    const std::string planar = (fs::path(examplesDirectory()) / "planar_2r.json").string();
    const auto key = AnswerKey::build(loadScene(puma).scene);
    std::string right;  // exact, as GiNaC writes it: the text rightAnswer shows rounds the scene's decimals
    {
        const auto lock = symbolic::lockGinac();
        const AnswerKey::Data& data = key->data();
        for (const KeyEntry& e : data.entries)
            if (e.id == "b11") {
                std::ostringstream text;
                text << data.valueOf(e);
                right = text.str();
            }
    }
    const std::string wrong = right + " + 0.1 c2";
    const fs::path log = fs::temp_directory_path() / ("lagrangelab-bench-answers-" + std::to_string(::getpid()) + ".log");
    int failed = 0;
    std::printf("check-answer of the PUMA 560's b11 (%zu characters expanded), median of %d runs\n", right.size(), runs);
    for (const auto& [what, answer, expected] : {std::tuple<const char*, std::string, int>{"right", right, 0}, {"wrong", wrong, 1}}) {
        std::vector<double> process, inKey;
        for (int r = 0; r < runs; ++r) {
            auto start = std::chrono::steady_clock::now();
            const int code = runLagrangelab({"check-answer", puma, "--entry", "b11", "--answer", answer}, log);
            process.push_back(since(start));
            if (code != expected) ++failed;
            start = std::chrono::steady_clock::now();
            const AnswerCheck c = key->check({"b11", answer});
            inKey.push_back(since(start));
            if ((c.verdict == AnswerVerdict::Right) != (expected == 0)) ++failed;
        }
        std::printf("  %-5s  whole process %.3f s (budget 0.3 s)   one check against a built key %.1f ms (budget 100 ms)\n", what,
                    median(process), 1e3 * median(inKey));
    }
    const auto planarKey = AnswerKey::build(loadScene(planar).scene);
    const std::vector<std::pair<std::string, std::string>> sheet = {{"b11", "I1 + m1 lc1^2 + I2 + m2 (a1^2 + lc2^2 + 2 a1 lc2 c2)"},
                                                                    {"b12", "I2 + m2 (lc2^2 + a1 lc2 c2)"},
                                                                    {"b22", "I2 + m2 lc2^2"},
                                                                    {"c11", "-m2 a1 lc2 s2 qd2"},
                                                                    {"c12", "-m2 a1 lc2 s2 (qd1 + qd2)"},
                                                                    {"c21", "m2 a1 lc2 s2 qd1"},
                                                                    {"c22", "0"},
                                                                    {"g1", "(m1 lc1 + m2 a1) g c1 + m2 lc2 g c12"},
                                                                    {"g2", "m2 lc2 g c12"},
                                                                    {"E_pot", "g (m1 lc1 s1 + m2 a1 s1)"}};
    std::vector<double> grading;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        for (int student = 0; student < 30; ++student)
            for (const auto& [entry, answer] : sheet) (void)planarKey->check({entry, answer});
        grading.push_back(since(start));
    }
    std::printf("300 checks (30 students x 10 entries of the planar 2R, one wrong per sheet) against one key: %.2f s (budget 10 s)\n",
                median(grading));
    fs::remove(log);
    return failed ? 1 : 0;
}

}  // namespace ll::bench
