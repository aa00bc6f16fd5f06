// lagrangelab-bench --urdf [--batches N]: what importing a robot from URDF costs (issue
// 50's budget, docs/benchmarks.md): whole `lagrangelab import` processes of a 7-joint URDF
// (the Panda example written by export-urdf), spawn to reap, budget 0.3 s; and the import
// alone in this process (parse, axes, DH by the rules, inertials).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/bench/program_run.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/data_directory.hpp"
#include "core/io/scene_file.hpp"
#include "core/io/urdf_export.hpp"
#include "core/io/urdf_import.hpp"

namespace ll::bench {

int urdf(int runs) {
    namespace fs = std::filesystem;
    const Scene panda = loadScene((fs::path(examplesDirectory()) / "panda.json").string()).scene;
    const std::string tag = std::to_string(::getpid());
    const fs::path file = fs::temp_directory_path() / ("lagrangelab-bench-panda-" + tag + ".urdf");
    const fs::path out = fs::temp_directory_path() / ("lagrangelab-bench-panda-" + tag + ".json");
    const fs::path log = fs::temp_directory_path() / ("lagrangelab-bench-urdf-" + tag + ".log");
    const std::string xml = exportUrdf(panda).xml;
    saveFileAtomically(file.string(), xml, Backup::None);
    int failed = 0;
    std::vector<double> process, inside;
    for (int r = 0; r < runs; ++r) {
        auto start = std::chrono::steady_clock::now();
        if (runLagrangelab({"import", file.string(), "--out", out.string()}, log) != 0) ++failed;
        process.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        start = std::chrono::steady_clock::now();
        const UrdfImport imported = importUrdf(xml, file.string(), {});
        inside.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (imported.scene.dof() != 7) ++failed;
    }
    std::printf("import of a 7-joint URDF (the Panda written by export-urdf, %zu bytes), median of %d runs:\n"
                "  whole process %.3f s (budget 0.3 s)   the import alone %.2f ms\n",
                xml.size(), runs, ll::cli::median(process), 1e3 * ll::cli::median(inside));
    for (const fs::path& p : {file, out, log}) fs::remove(p);
    return failed ? 1 : 0;
}

}  // namespace ll::bench
