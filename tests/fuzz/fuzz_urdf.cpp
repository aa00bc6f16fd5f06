// libFuzzer: any bytes as a URDF file through lagrangelab import (liburdfdom's parser, the
// chain, DH from the axes, the inertials), in the convention the last byte picks. A robot
// accepted is a scene whose checks name their fields, and export-urdf of it reads back
// through import again; a refusal is InputError naming the file or the option.
#include <cstdint>
#include <string>

#include "core/io/urdf_export.hpp"
#include "core/io/urdf_import.hpp"
#include "core/pipeline/scene_check.hpp"
#include "fuzz_support.hpp"

int ll::fuzz::urdf(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data), size - 1);
    ll::UrdfImportOptions options;
    options.convention = data[size - 1] & 1 ? ll::DhConvention::Modified : ll::DhConvention::Standard;
    try {
        const ll::UrdfImport imported = ll::importUrdf(text, "fuzz.urdf", options);
        const std::vector<ll::Diagnostic> checks = ll::checkScene(imported.scene);
        for (const ll::Diagnostic& d : checks)
            ll::fuzz::require(!d.field.empty() && ll::isValidUtf8(d.field + d.message.english()), "a check names no field");
        if (!ll::hasErrors(checks)) {  // a robot the window would open: written and read back
            const ll::UrdfImport again = ll::importUrdf(ll::exportUrdf(imported.scene).xml, "fuzz.urdf", options);
            ll::fuzz::require(again.scene.dof() == imported.scene.dof(), "export-urdf and import changed the number of joints");
        }
    } catch (const ll::InputError& e) {
        ll::fuzz::checkRefusal(e);
    }
    return 0;
}
