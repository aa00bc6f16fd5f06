#include "core/io/scene_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/io/atomic_file.hpp"
#include "core/io/scene_json.hpp"
#include "core/io/scene_reader.hpp"
#include "core/io/scene_writer.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/io/json_file.hpp"

namespace ll {

namespace {

// loadScene's diagnostics name the file: "<path>: <field>".
std::vector<Diagnostic> inFile(std::vector<Diagnostic> diagnostics, const std::string& path) {
    for (Diagnostic& d : diagnostics) d.field = path + ": " + d.field;
    return diagnostics;
}

}  // namespace

Scene parseScene(const std::string& jsonText) {
    const auto lock = symbolic::lockGinac();  // expressions are parsed with GiNaC
    std::vector<Diagnostic> duplicates;
    const scene_json::Json root = scene_json::parseJson(jsonText, duplicates);
    return readScene(root, std::move(duplicates));
}

namespace {

// Each mesh path of the robot's look changed by `change` (package:// URLs left alone).
template <class Change>
void changeMeshPaths(Scene& scene, Change change) {
    for (LinkVisual& link : scene.robot.links)
        for (LinkShape& shape : link.shapes)
            if (shape.kind == LinkShape::Kind::Mesh && !shape.mesh.empty() && shape.mesh.find("://") == std::string::npos)
                shape.mesh = change(std::filesystem::path(shape.mesh)).string();
}

std::filesystem::path folderOf(const std::string& file) { return std::filesystem::absolute(std::filesystem::path(file)).parent_path(); }

}  // namespace

LoadedScene loadScene(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, MessageId::PathIsDirectory);
    const std::optional<std::string> text = readWholeFile(path);
    if (!text) throw InputError(path, message(MessageId::CannotReadSceneFile, std::strerror(errno)));
    std::vector<Diagnostic> duplicates;
    scene_json::Json root;
    try {
        root = scene_json::parseJson(*text, duplicates);
    } catch (const InputError& e) {  // about the whole text: the file is the field
        throw InputError(path, e.diagnostics().front().message);
    }
    try {
        const auto lock = symbolic::lockGinac();  // expressions are parsed with GiNaC
        LoadedScene loaded;
        loaded.scene = readScene(root, std::move(duplicates), &loaded.warnings);
        changeMeshPaths(loaded.scene, [folder = folderOf(path)](const std::filesystem::path& mesh) {
            return mesh.is_relative() ? (folder / mesh).lexically_normal() : mesh;
        });
        const std::vector<Diagnostic> validation = requireValidScene(loaded.scene);
        loaded.warnings.insert(loaded.warnings.end(), validation.begin(), validation.end());
        loaded.warnings = inFile(std::move(loaded.warnings), path);
        return loaded;
    } catch (const InputError& e) {
        throw InputError(inFile(e.diagnostics(), path));
    }
}

std::string serializeScene(const Scene& scene) {
    const auto lock = symbolic::lockGinac();  // expressions are re-checked with GiNaC
    std::string text;
    scene_json::writePretty(text, writeScene(scene), 0);
    return text + "\n";
}


void saveScene(const Scene& scene, const std::string& path) {
    Scene written = scene;
    changeMeshPaths(written, [folder = folderOf(path)](const std::filesystem::path& mesh) {
        if (mesh.is_relative()) return mesh;
        const std::filesystem::path relative = mesh.lexically_relative(folder);
        return relative.empty() ? mesh : relative;
    });
    saveFileAtomically(path, serializeScene(written), Backup::Keep);
}

}  // namespace ll
