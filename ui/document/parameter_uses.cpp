#include "ui/document/parameter_uses.hpp"

#include <algorithm>
#include <functional>

#include "ui/document/parameter_rename.hpp"

namespace ll::ui {
namespace {

// Every expression string under `node` with its JSON pointer, prose keys skipped.
void forEachExpression(const SceneJson& node, const std::string& pointer,
                       const std::function<void(const std::string&, const std::string&)>& visit) {
    if (node.is_string()) {
        visit(pointer, node.get<std::string>());
    } else if (node.is_array()) {
        for (std::size_t i = 0; i < node.size(); ++i) forEachExpression(node[i], pointer + "/" + std::to_string(i), visit);
    } else if (node.is_object()) {
        for (auto it = node.begin(); it != node.end(); ++it)
            if (!proseKey(it.key())) forEachExpression(it.value(), pointer + "/" + it.key(), visit);
    }
}

std::vector<std::string> namesAt(const SceneJson& scene, const std::string& pointer) {
    const SceneJson::json_pointer p(pointer);
    if (!scene.contains(p)) return {};
    std::vector<std::string> names;
    forEachExpression(scene.at(p), pointer, [&](const std::string&, const std::string& text) {
        for (std::string& name : namesInExpression(text))
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
    });
    return names;
}

}  // namespace

std::string fieldOfPointer(const std::string& pointer) {
    std::string field;
    std::size_t start = 1;
    while (start <= pointer.size()) {
        const std::size_t end = std::min(pointer.find('/', start), pointer.size());
        const std::string part = pointer.substr(start, end - start);
        if (!part.empty() && std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; })) field += "[" + part + "]";
        else field += (field.empty() ? "" : ".") + part;
        start = end + 1;
    }
    return field;
}

std::vector<ParameterStillUsed> parametersStillUsed(const SceneJson& before, const SceneJson& after, const std::string& pointer) {
    std::vector<ParameterStillUsed> out;
    if (!after.contains("parameters") || !after["parameters"].is_object()) return out;
    const std::vector<std::string> now = namesAt(after, pointer);
    for (const std::string& name : namesAt(before, pointer)) {
        if (!after["parameters"].contains(name) || std::find(now.begin(), now.end(), name) != now.end()) continue;
        ParameterStillUsed used{name, {}};
        forEachExpression(after, "", [&](const std::string& where, const std::string& text) {
            if (where == "/parameters/" + name) return;  // its own value
            const std::vector<std::string> names = namesInExpression(text);
            if (std::find(names.begin(), names.end(), name) != names.end()) used.fields.push_back(fieldOfPointer(where));
        });
        if (!used.fields.empty()) out.push_back(std::move(used));
    }
    return out;
}

}  // namespace ll::ui
