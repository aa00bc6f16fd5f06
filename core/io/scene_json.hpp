#pragma once
// A scene file's JSON, shared by its reader (core/io/scene_reader.cpp) and its writer
// (core/io/scene_writer.cpp): the JSON type, which keeps the file's key order; field
// paths as a student reads them; and the text itself, parsed with every duplicate key
// reported and a syntax error placed at its line and column, written back compactly.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/model/diagnostics.hpp"

namespace ll::scene_json {

// ordered_json keeps the file's key order: parameters may use the ones before them.
using Json = nlohmann::ordered_json;
using Keys = std::vector<std::string>;

inline constexpr const char* kFormat = "lagrangelab-scene/1";
// Field of problems with the whole text (JSON syntax) in parseScene; loadScene names the file instead.
inline constexpr const char* kDocument = "scene";

inline std::string child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

inline std::string item(const std::string& path, std::size_t index0) { return path + "[" + std::to_string(index0) + "]"; }

inline std::string joined(const Keys& keys) {
    std::string text;
    for (const std::string& key : keys) text += (text.empty() ? "" : ", ") + key;
    return text;
}

// The offending value as the student wrote it, with its type where the text does not show it.
inline Message describe(const Json& value) {
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    if (value.is_string()) return message(MessageId::DescribedString, text);
    if (value.is_number()) return message(MessageId::DescribedNumber, text);
    return literal(text);
}

// The choices as a message lists them: "\"a\"", "\"a\" or \"b\"", "\"a\", \"b\" or \"c\"".
inline Message alternatives(const Keys& choices) {
    std::string first;
    for (std::size_t i = 0; i + 1 < choices.size(); ++i) first += (i == 0 ? "\"" : ", \"") + choices[i] + "\"";
    const std::string last = choices.empty() ? std::string() : "\"" + choices.back() + "\"";
    return first.empty() ? literal(last) : message(MessageId::ChoiceOr, first, last);
}

// "expected <what>, got <the value>".
inline Message expectedGot(Message what, const Json& value) { return message(MessageId::JsonExpectedGot, std::move(what), describe(value)); }

inline Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy) {
    return (Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

// Inverse of rotationFromRpy; at pitch = ±π/2 only roll - yaw (or roll + yaw) is
// determined, and yaw = 0 is chosen.
inline Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R) {
    const double cosPitch = std::hypot(R(0, 0), R(1, 0));
    const double pitch = std::atan2(-R(2, 0), cosPitch);
    if (cosPitch < 1e-12) return {std::atan2(-R(1, 2), R(1, 1)), pitch, 0.0};
    return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
}

// The text as a JSON object. Duplicate keys are appended to `duplicates` (nlohmann would
// keep the last one silently). Throws InputError naming kDocument: the text is not UTF-8
// (named by the first byte that is not), not JSON (where, and why), or no object.
Json parseJson(const std::string& text, std::vector<Diagnostic>& duplicates);

// Appends `value` as text at `indent`: 2-space indent, short arrays and small entries
// on one line.
void writePretty(std::string& out, const Json& value, std::size_t indent);

}  // namespace ll::scene_json
