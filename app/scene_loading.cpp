#include "app/scene_loading.hpp"

#include <iostream>

#include "core/io/scene_file.hpp"

namespace ll::cli {

Scene loadSceneReportingWarnings(const std::string& path) {
    LoadedScene loaded = loadScene(path);
    for (const Diagnostic& w : loaded.warnings) std::cerr << "warning: " << w.field << ": " << w.message << '\n';
    return std::move(loaded.scene);
}

}  // namespace ll::cli
