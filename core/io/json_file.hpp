#pragma once
// Reading a file whole, and a JSON file as an object, every problem naming the file: what
// the scene, view and lesson readers share.
#include <optional>
#include <string>

#include "core/io/scene_json.hpp"

namespace ll {

// The file's bytes; nullopt when it cannot be read (errno says why).
std::optional<std::string> readWholeFile(const std::string& path);

// The file's JSON object. Throws InputError whose fields start with `path`: unreadable,
// not UTF-8, a syntax error (at its line and column), no object.
scene_json::Json readJsonFile(const std::string& path);

}  // namespace ll
