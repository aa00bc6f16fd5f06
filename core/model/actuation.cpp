#include "core/model/actuation.hpp"

namespace ll {

std::string actuationText(const std::vector<int>& actuated, const std::vector<std::string>& coordinateNames) {
    std::string inputs;
    for (int j : actuated) inputs += (inputs.empty() ? "" : ", ") + coordinateNames.at(j);
    const std::size_t m = actuated.size(), n = coordinateNames.size();
    return (inputs.empty() ? std::string("no inputs") : "inputs on " + inputs) +
           (m < n ? " (underactuated: m = " + std::to_string(m) + " < n = " + std::to_string(n) + ")" : " (fully actuated)");
}

}  // namespace ll
