// libFuzzer: any bytes as a scene file through the reader and the whole validation
// (parseScene, then checkScene: fields, B regular, a Lagrangian's derivation checks).
#include <cstdint>
#include <string>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_check.hpp"
#include "fuzz_support.hpp"

int ll::fuzz::sceneLoader(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const ll::Scene scene = ll::parseScene(text);
        for (const ll::Diagnostic& d : ll::checkScene(scene))
            ll::fuzz::require(!d.field.empty() && ll::isValidUtf8(d.field + d.message.english()), "a check names no field");
    } catch (const ll::InputError& e) {
        ll::fuzz::checkRefusal(e);
    }
    return 0;
}
