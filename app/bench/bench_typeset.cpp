// lagrangelab-bench --typeset [SCENE...] [--batches N]: what typesetting and printing
// the derivation cost, wall and CPU time (medians of N runs): one entry of B laid out;
// whole derivations to PDF (default the 2R and the PUMA 560); and for the Franka Panda
// (or the scenes given) the derivation beside its text, JSON, LaTeX and PDF, each in
// every parameter mode and in the form `derive` picks by default (auto: structured for
// the Panda), so "printing never costs more than deriving" can be read off.
#include <QFile>
#include <QTemporaryDir>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <functional>

#include "core/io/data_directory.hpp"
#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/scene_loading.hpp"
#include "core/pipeline/derivation_forms.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/structured_dynamics.hpp"
#include "ui/paint/derivation_pages.hpp"

namespace ll::bench {

using namespace ll::cli;
namespace {

struct Cost {
    double wall = 0, cpu = 0;  // seconds, medians
};

Cost measure(int runs, const std::function<void()>& work) {
    std::vector<double> wall, cpu;
    for (int r = 0; r < runs; ++r) {
        const auto w0 = std::chrono::steady_clock::now();
        const std::clock_t c0 = std::clock();
        work();
        cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
        wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    }
    return {median(wall), median(cpu)};
}

DerivedDocument derive(const Scene& scene, symbolic::ParameterMode mode, present::DocumentFormat format) {
    DocumentRequest request;
    request.mode = mode;
    request.format = format;
    return deriveDocument(scene, request);
}

// What `derive --format F` does with the default form (auto: structured for large robots).
DerivedDocument deriveAuto(const Scene& scene, symbolic::ParameterMode mode, present::DocumentFormat format) {
    FormRequest request;
    request.document.mode = mode;
    request.document.format = format;
    return deriveInForm(scene, request).derived;
}

// The derivation alone, in the form auto picks, with nothing printed.
void deriveOnly(const Scene& scene, symbolic::ParameterMode mode) {
    Message reason;
    if (!scene.lagrangian && !expandedIsCheap(scene, reason)) {
        symbolic::DerivationOptions options;
        options.mode = mode;
        const auto lock = symbolic::lockGinac();
        symbolic::deriveStructured(scene, options);
        return;
    }
    DocumentRequest bare;
    bare.mode = mode;
    bare.firstStep = bare.lastStep = 0;  // B, C, g, Q derived; nothing shaped but step 0
    deriveDocument(scene, bare);
}

void toPdf(const Scene& scene, symbolic::ParameterMode mode, const QString& path) {
    DocumentRequest request;
    request.mode = mode;
    const DerivedDocument d = deriveDisplay(scene, request);
    std::string error;
    if (!ui::writePdf(*d.display, path, error)) throw std::runtime_error(error);
}

}  // namespace

int typeset(const std::vector<std::string>& scenes, int runs) {
    const auto app = makeGuiApplication();
    if (!ui::mathFontsAvailable()) throw std::runtime_error("the Latin Modern fonts are missing: install fonts-lmodern");
    QTemporaryDir dir;
    const std::string examples = examplesDirectory().string();
    const Scene planar = loadSceneReportingWarnings(examples + "/planar_2r.json");
    std::printf("medians of %d runs; wall [ms] and CPU [ms] of this process\n\n", runs);

    // One B entry: b11 of the 2R, laid out (boxes, fonts measured; caches warm after run 1).
    const DerivedDocument shown = derive(planar, symbolic::ParameterMode::Parametric, present::DocumentFormat::Display);
    const present::DisplayNode* b11 = nullptr;
    for (const auto& step : shown.display->steps)
        for (const auto& item : step.items)
            if (item.name == "B") b11 = item.value->rows[0][0].get();
    std::vector<double> each;
    for (int r = 0; r < std::max(runs, 5) * 20; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        const ui::MathBox box = ui::layoutMath(*b11);
        each.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
        if (box.width <= 0) return 1;
    }
    std::sort(each.begin(), each.end());
    std::printf("typeset b11 of the 2R (layout, cached glyph metrics): %.1f µs median, first %.1f µs\n\n", each[each.size() / 2],
                each.back());

    std::printf("%-32s %-10s | %18s | %18s\n", "system", "mode", "derive [ms] wall/cpu", "to PDF [ms] wall/cpu");
    const std::vector<std::string> pdfScenes = {examples + "/planar_2r.json", examples + "/puma560.json"};
    for (const std::string& file : pdfScenes) {
        const Scene scene = loadSceneReportingWarnings(file);
        const auto mode = symbolic::ParameterMode::Parametric;
        const Cost d = measure(runs, [&] { deriveOnly(scene, mode); });
        const Cost p = measure(runs, [&] { toPdf(scene, mode, dir.filePath("bench.pdf")); });
        std::printf("%-32s %-10s | %8.1f / %7.1f | %8.1f / %7.1f\n", file.substr(file.rfind('/') + 1).c_str(), modeName(mode), 1e3 * d.wall,
                    1e3 * d.cpu, 1e3 * p.wall, 1e3 * p.cpu);
    }

    std::vector<std::string> big = scenes;
    if (big.empty()) big.push_back(examples + "/panda.json");
    std::printf("\nthe default form (auto): derivation alone (no document) beside derive + print, CPU [s] (medians)\n");
    std::printf("%-24s %-10s | %7s | %7s %7s %7s %7s | %6s\n", "system", "mode", "derive", "text", "json", "latex", "pdf", "worst");
    for (const std::string& file : big) {
        const Scene scene = loadSceneReportingWarnings(file);
        for (auto mode : {symbolic::ParameterMode::Parametric, symbolic::ParameterMode::Numeric, symbolic::ParameterMode::Textbook}) {
            const Cost d = measure(runs, [&] { deriveOnly(scene, mode); });
            const Cost t = measure(runs, [&] { deriveAuto(scene, mode, present::DocumentFormat::Text); });
            const Cost j = measure(runs, [&] { deriveAuto(scene, mode, present::DocumentFormat::Json); });
            const Cost l = measure(runs, [&] { deriveAuto(scene, mode, present::DocumentFormat::Latex); });
            const Cost p = measure(runs, [&] { toPdf(scene, mode, dir.filePath("big.pdf")); });
            const double worst = std::max({t.cpu, j.cpu, l.cpu, p.cpu}) / d.cpu;
            std::printf("%-24s %-10s | %7.2f | %7.2f %7.2f %7.2f %7.2f | %5.2fx\n", file.substr(file.rfind('/') + 1).c_str(),
                        modeName(mode), d.cpu, t.cpu, j.cpu, l.cpu, p.cpu, worst);
        }
    }
    return 0;
}

}  // namespace ll::bench
