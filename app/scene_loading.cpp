#include "app/scene_loading.hpp"

#include <iostream>

#include "core/io/scene_file.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"

namespace ll::cli {

Scene loadSceneReportingWarnings(const std::string& path) {
    LoadedScene loaded = loadScene(path);
    // A Lagrangian's input errors (E_kin not quadratic, dependent coordinates, a
    // conservative Q) come from its derivation: found here, they name the file too.
    if (loaded.scene.lagrangian) try {
            const auto lock = symbolic::lockGinac();
            (void)symbolic::deriveLagrangian(loaded.scene, symbolic::ParameterMode::Numeric);
        } catch (const InputError& e) {
            std::vector<Diagnostic> diagnostics = e.diagnostics();
            for (Diagnostic& d : diagnostics) d.field = path + ": " + d.field;
            throw InputError(diagnostics);
        }
    for (const Diagnostic& w : loaded.warnings) std::cerr << "warning: " << w.field << ": " << w.message << '\n';
    return std::move(loaded.scene);
}

void requireValidSceneFrom(const Scene& scene, const std::string& path) {
    try {
        requireValidScene(scene);
    } catch (const InputError& e) {
        std::vector<Diagnostic> named = e.diagnostics();
        for (Diagnostic& d : named) d.field = path + ": " + d.field;
        throw InputError(named);
    }
}

}  // namespace ll::cli
