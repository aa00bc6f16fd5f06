#pragma once
// The modes of lagrangelab-bench (app/bench/bench_main.cpp), one file each. Each prints
// its table on stdout and returns the exit code: 0, 1 when a timed run failed, 2 for a
// bad argument.
#include <string>
#include <vector>

namespace ll::bench {

// --derive --chains A..B: structured beside expanded on seeded random chains (bench_derive_chains.cpp).
int deriveChains(const std::string& range, const std::vector<std::string>& scenes, int repeats, double capSeconds);
// --render: the cost of headless export (bench_render.cpp).
int render(const std::vector<std::string>& scenes, int runs);
// --typeset: typesetting and printing the derivation (bench_typeset.cpp).
int typeset(const std::vector<std::string>& scenes, int runs);
// --process: whole `lagrangelab derive` processes in every format against their budgets (bench_process.cpp).
int process(const std::vector<std::string>& scenes, int runs, const std::string& form);
// --gui: edit-to-view latency, a large robot opened to its derivation on screen,
// animation frame rate, start to first frame (bench_gui.cpp).
int gui(const std::vector<std::string>& scenes, int runs);
// --entries: B11 and C11 expanded on demand on chains with special and general constant
// angles (bench_expanded_entries.cpp); benchChains(): its default scenes, docs/bench/chain8*.json.
int expandedEntries(const std::vector<std::string>& scenes, const std::vector<std::string>& entries, int runs);
std::vector<std::string> benchChains();
// --answers: a student's answer checked, as a process and against a built key (bench_answers.cpp).
int answers(int runs);
// --grade: `lagrangelab grade` of 30 students' files of 10 entries (bench_grade.cpp).
int grade(int runs);
// --urdf: lagrangelab import of a 7-joint URDF, as a process and in this one (bench_urdf.cpp).
int urdf(int runs);
// --lesson: the next view of a lesson on screen, its scene loaded or not (bench_lesson.cpp).
int lesson(int runs);
// --linked: the entry catalogue, per-frame evaluation and the run's analysis (bench_linked.cpp).
int linked(const std::vector<std::string>& scenes, int runs);

}  // namespace ll::bench
