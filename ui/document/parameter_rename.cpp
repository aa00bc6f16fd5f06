#include "ui/document/parameter_rename.hpp"

#include <algorithm>
#include <set>

namespace ll::ui {
namespace {

bool nameChar(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }

void rewrite(SceneJson& node, const std::string& from, const std::string& to) {
    if (node.is_string()) {
        node = renamedInExpression(node.get<std::string>(), from, to);
    } else if (node.is_array()) {
        for (SceneJson& item : node) rewrite(item, from, to);
    } else if (node.is_object()) {
        for (auto it = node.begin(); it != node.end(); ++it)
            if (!proseKey(it.key())) rewrite(it.value(), from, to);
    }
}

}  // namespace

bool proseKey(const std::string& key) {
    static const std::set<std::string> keys = {"format",      "name", "description", "source", "convention", "type",  "integrator",
                                               "recovery_of", "kind", "law",         "unit",   "shape",      "color", "axis"};
    return keys.count(key) > 0;
}

namespace {

// `text` cut into its words (runs of letters, digits and _) and what lies between them, in
// order: `word(w)` for each word, `other(c)` for each character between words.
template <class Word, class Other>
void splitWords(const std::string& text, Word&& word, Other&& other) {
    std::size_t i = 0;
    while (i < text.size()) {
        if (!nameChar(text[i])) {
            other(text[i++]);
            continue;
        }
        std::size_t end = i;
        while (end < text.size() && nameChar(text[end])) ++end;
        word(text.substr(i, end - i));
        i = end;
    }
}

// A number (1e1, 2.5's two words) is a word starting with a digit: never a name.
bool isName(const std::string& word) { return !(word[0] >= '0' && word[0] <= '9'); }

}  // namespace

std::vector<std::string> namesInExpression(const std::string& text) {
    std::vector<std::string> names;
    splitWords(
        text,
        [&](const std::string& word) {
            if (isName(word) && std::find(names.begin(), names.end(), word) == names.end()) names.push_back(word);
        },
        [](char) {});
    return names;
}

std::string renamedInExpression(const std::string& text, const std::string& from, const std::string& to) {
    std::string out;
    out.reserve(text.size());
    splitWords(
        text, [&](const std::string& word) { out += isName(word) && word == from ? to : word; }, [&](char c) { out += c; });
    return out;
}

SceneJson renamedParameter(const SceneJson& scene, const std::string& from, const std::string& to) {
    if (!scene.contains("parameters") || !scene["parameters"].is_object() || !scene["parameters"].contains(from)) return scene;
    SceneJson out = scene;
    SceneJson parameters = SceneJson::object();  // rebuilt in order, the renamed one in its place
    for (auto it = scene["parameters"].begin(); it != scene["parameters"].end(); ++it) {
        SceneJson value = it.value();
        rewrite(value, from, to);  // a parameter given as an expression of another
        parameters[it.key() == from ? to : it.key()] = value;
    }
    for (auto it = out.begin(); it != out.end(); ++it)
        if (it.key() != "parameters" && !proseKey(it.key())) rewrite(it.value(), from, to);
    out["parameters"] = parameters;
    return out;
}

}  // namespace ll::ui
