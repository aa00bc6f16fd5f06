#pragma once
// Loading a scene for a command: warnings go to stderr, errors propagate as InputError.
#include <string>

#include "core/model/diagnostics.hpp"
#include "core/model/scene.hpp"

namespace ll::cli {

// f(); an InputError it throws is rethrown with each field named "<path>: <field>", as
// the errors of loading are.
template <class F>
decltype(auto) inSceneFile(const std::string& path, F&& f) {
    try {
        return f();
    } catch (const InputError& e) {
        std::vector<Diagnostic> named = e.diagnostics();
        for (Diagnostic& d : named) d.field = path + ": " + d.field;
        throw InputError(named);
    }
}

Scene loadSceneReportingWarnings(const std::string& path);

// requireValidScene after command-line overrides, with errors named "<path>: <field>"
// like those of loading.
void requireValidSceneFrom(const Scene& scene, const std::string& path);

}  // namespace ll::cli
