#include "core/model/actuation.hpp"

namespace ll {

std::string actuationText(const std::vector<int>& actuated, const std::vector<std::string>& coordinateNames, const ActuationWords& words) {
    std::string inputs;
    for (int j : actuated) inputs += (inputs.empty() ? "" : ", ") + coordinateNames.at(j);
    const std::size_t m = actuated.size(), n = coordinateNames.size();
    return (inputs.empty() ? words.noInputs : words.inputsOn + " " + inputs) +
           (m < n ? " (" + words.underactuated + ": m = " + std::to_string(m) + " < n = " + std::to_string(n) + ")"
                  : " (" + words.fullyActuated + ")");
}

}  // namespace ll
