#include "app/scene_loading.hpp"

#include <iostream>

#include "app/cli_options.hpp"
#include "core/io/scene_file.hpp"
#include "core/present/diagnostic_text.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"

namespace ll::cli {

Scene loadSceneReportingWarnings(const std::string& path) {
    LoadedScene loaded = loadScene(path);
    // A Lagrangian's input errors (E_kin not quadratic, dependent coordinates, a
    // conservative Q) come from its derivation: found here, they name the file too.
    if (loaded.scene.lagrangian)
        inSceneFile(path, [&] {
            const auto lock = symbolic::lockGinac();
            (void)symbolic::deriveLagrangian(loaded.scene, symbolic::ParameterMode::Numeric);
        });
    for (const Diagnostic& w : loaded.warnings) std::cerr << present::diagnosticText(w, presentation().language) << '\n';
    return std::move(loaded.scene);
}

void requireValidSceneFrom(const Scene& scene, const std::string& path) {
    inSceneFile(path, [&] { (void)requireValidScene(scene); });
}

}  // namespace ll::cli
