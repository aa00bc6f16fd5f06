#pragma once
// Loading a scene for a command: warnings go to stderr, errors propagate as InputError.
#include <string>

#include "core/model/scene.hpp"

namespace ll::cli {

Scene loadSceneReportingWarnings(const std::string& path);

// requireValidScene after command-line overrides, with errors named "<path>: <field>"
// like those of loading.
void requireValidSceneFrom(const Scene& scene, const std::string& path);

}  // namespace ll::cli
