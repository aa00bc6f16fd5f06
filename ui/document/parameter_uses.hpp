#pragma once
// Where a scene's parameters are still used after one value was edited: typing 1.2 over
// the 2R's DH cell a = "a1" leaves a1 in link 1's COM ("lc1-a1"), which then means
// something else than the student may think. The window says so in a hint line.
#include <string>
#include <vector>

#include "ui/document/scene_json.hpp"

namespace ll::ui {

struct ParameterStillUsed {
    std::string parameter;            // "a1"
    std::vector<std::string> fields;  // where it is still used, as the loader names them ("robot.joints[0].com[0]")
};

// The parameters the value at `pointer` used in `before` and no longer uses in `after`,
// each with the other fields that still use it (none listed when no field does: nothing
// to say then). Whole names only, prose keys skipped (parameter_rename.hpp); the
// parameters' own values count as uses.
std::vector<ParameterStillUsed> parametersStillUsed(const SceneJson& before, const SceneJson& after, const std::string& pointer);

// "/robot/joints/1/com/0" → "robot.joints[1].com[0]": a JSON pointer as the loader names
// the field.
std::string fieldOfPointer(const std::string& pointer);

}  // namespace ll::ui
