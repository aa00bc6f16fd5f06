#include "core/model/quantity_units.hpp"

namespace ll {

std::string massMatrixUnit(bool revoluteJ, bool revoluteK) {
    const int lengths = (revoluteJ ? 1 : 0) + (revoluteK ? 1 : 0);
    return lengths == 2 ? "kg·m²" : lengths == 1 ? "kg·m" : "kg";
}

std::string coriolisUnit(bool revoluteI, bool revoluteJ) { return massMatrixUnit(revoluteI, revoluteJ) + "/s"; }

std::string forceUnit(bool revolute) { return revolute ? "N·m" : "N"; }
std::string coordinateUnit(bool revolute) { return revolute ? "rad" : "m"; }
std::string velocityUnit(bool revolute) { return revolute ? "rad/s" : "m/s"; }
std::string accelerationUnit(bool revolute) { return revolute ? "rad/s²" : "m/s²"; }

}  // namespace ll
