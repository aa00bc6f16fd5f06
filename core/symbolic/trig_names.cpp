#include "core/symbolic/trig_names.hpp"

#include <algorithm>

namespace ll::symbolic {
namespace {

bool digitsOnly(const std::string& s) {
    return !s.empty() && s.size() < 7 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

std::string trigSymbolName(const TrigName& trig, int coordinateCount) {
    const bool joined = coordinateCount >= 10 || std::any_of(trig.indices.begin(), trig.indices.end(), [](int i) { return i >= 10; });
    std::string name(1, trig.kind);
    for (std::size_t k = 0; k < trig.indices.size(); ++k) {
        if (k > 0 && joined) name += '_';
        name += std::to_string(trig.indices[k]);
    }
    return name;
}

std::optional<TrigName> parseTrigName(const std::string& name, int coordinateCount) {
    if (name.size() < 2 || (name[0] != 'c' && name[0] != 's')) return std::nullopt;
    TrigName t{name[0], {}};
    const std::string rest = name.substr(1);
    if (rest.find('_') != std::string::npos) {
        for (std::size_t start = 0; start <= rest.size();) {
            const std::size_t end = std::min(rest.find('_', start), rest.size());
            const std::string piece = rest.substr(start, end - start);
            if (!digitsOnly(piece) || piece[0] == '0') return std::nullopt;
            t.indices.push_back(std::stoi(piece));
            start = end + 1;
        }
    } else {
        if (!digitsOnly(rest) || rest[0] == '0') return std::nullopt;
        if (rest.size() == 1 || coordinateCount >= 10) t.indices = {std::stoi(rest)};
        else
            for (char d : rest) {
                if (d == '0') return std::nullopt;
                t.indices.push_back(d - '0');
            }
    }
    for (std::size_t k = 1; k < t.indices.size(); ++k)
        if (t.indices[k] <= t.indices[k - 1]) return std::nullopt;
    if (coordinateCount > 0 && t.indices.back() > coordinateCount) return std::nullopt;
    return t;
}

}  // namespace ll::symbolic
