#pragma once
// Indices written after a name as the textbook writes them: side by side (b23), or with
// commas once one has two digits (b7,10; β_{7,10}). The one rule for the structured
// form's names, the labels and the notes beside them.
#include <initializer_list>
#include <string>
#include <vector>

namespace ll::symbolic {

// Indices side by side as the textbook writes them (b23), or with commas once one has
// two digits (b7,10; β_{7,10}): the labels' and the notes' one rule.
inline std::string joined(const std::vector<std::string>& indices) {
    bool wide = false;
    for (const std::string& i : indices) wide = wide || i.size() > 1;
    std::string out;
    for (const std::string& i : indices) {
        if (wide && !out.empty()) out += ',';
        out += i;
    }
    return out;
}

// The same for indices counted from 0, written from 1.
inline std::string indexList(std::initializer_list<int> zeroBased) {
    std::vector<std::string> indices;
    for (int i : zeroBased) indices.push_back(std::to_string(i + 1));
    return joined(indices);
}

}  // namespace ll::symbolic
