#include "core/io/json_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace ll {

std::optional<std::string> readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream content;
    content << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return content.str();
}

scene_json::Json readJsonFile(const std::string& path) {
    const std::optional<std::string> text = readWholeFile(path);
    if (!text) throw InputError(path, message(MessageId::CannotReadSceneFile, std::strerror(errno)));
    std::vector<Diagnostic> duplicates;
    try {
        return scene_json::parseJson(*text, duplicates);
    } catch (const InputError& e) {
        std::vector<Diagnostic> named = e.diagnostics();
        for (Diagnostic& d : named) d.field = path + (d.field == scene_json::kDocument ? "" : ": " + d.field);
        throw InputError(named);
    }
}

}  // namespace ll
