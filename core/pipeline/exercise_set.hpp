#pragma once
// A set of exercises made from one scene (`lagrangelab exercise`, issue 47 part 4): a robot
// per student, its numbers drawn from ranges and rounded to decimals a student can work
// with, the same tasks (entries of the derivation) for everyone, and a fingerprint of each
// student's robot so that grading can tell an answer file for another robot or set.
//
//   ExerciseSpec spec{{{"planar_2r.json", sceneText, ranges}}, {"s01", "s02"}, 7};
//   ExerciseSet set = makeExerciseSet(spec);     // deterministic: the same spec, the same robots
//   set.manifest()                               // exercise.json; ExerciseSet::fromManifest reads it back
//
// Plain data, no GiNaC in this header; what needs the derivation (which entries a step
// has, the right answers in Maxima's syntax) takes an AnswerKey.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/model/scene.hpp"
#include "core/pipeline/answer_check.hpp"
#include "core/present/display_tree.hpp"
#include "core/present/language.hpp"

namespace ll {

// A parameter's values drawn uniformly in [low, high], on a grid of `decimals` decimals.
struct ParameterRange {
    std::string name;
    double low = 0, high = 0;
    int decimals = 2;  // set by roundedRange
};

// The range with its decimals chosen so that about 10 to 100 values lie in it (0.64..0.96:
// two decimals), its ends moved onto that grid.
ParameterRange roundedRange(const std::string& name, double low, double high);

// The ranges used when none is given: ±20 % of every parameter the robot's links (a, d,
// mass, centre of mass, inertia) or a typed Lagrangian's energies and forces use, in the
// scene's order. Parameters of angles, drawing sizes and gravity are left as they are.
std::vector<ParameterRange> defaultRanges(const Scene& scene);

// The parameters the robot's links or a typed Lagrangian's energies and forces use, in the
// scene's order: what a sheet lists with their values.
std::vector<std::string> usedParameters(const Scene& scene);

// Each parameter's unit as its fields give it ("m", "kg", "kg·m²"), when they agree.
std::map<std::string, std::string> parameterUnits(const Scene& scene);

// The robot as a sheet and a quiz show it: each DH row and link as the scene file gives
// it, a field typed as an expression of the parameters shown as typed ("lc1-a1"), a number
// as a short decimal (an angle a multiple of π/12 as "π/2"); the joint variable added to θ
// or d ("q1", "0.3 + q2").
struct RobotTableRow {
    bool prismatic = false;
    std::string a, alpha, d, theta;
    std::string mass;
    std::array<std::string, 3> com;
    std::array<std::string, 6> inertia;  // xx, yy, zz, xy, xz, yz
};
std::vector<RobotTableRow> robotTable(const Scene& scene);
// A number as a sheet shows it: at most six significant digits, no trailing zeros.
std::string shortNumber(double value);

struct ExerciseStudent {
    std::string id;
    std::string scene;                                   // the family member it was drawn from (its file name)
    std::vector<std::pair<std::string, double>> values;  // the drawn parameters, in the ranges' order
    std::string sceneText;                               // the student's scene file
    std::string fingerprint;                             // sceneFingerprint(sceneText)
};

// A scene file the set is made from: its name, its JSON, and the ranges its parameters
// are drawn from.
struct ExerciseScene {
    std::string file, text;
    std::vector<ParameterRange> ranges;
};

struct ExerciseSpec {
    // One scene, or a family (a 2R and a 3R arm, one with a twist, one with a prismatic
    // joint): each student gets one of them, drawn from the seed and the id, with its
    // parameters drawn from its ranges.
    std::vector<ExerciseScene> scenes;
    std::vector<std::string> students;
    std::uint64_t seed = 1;
    std::vector<std::string> entries;  // entry ids (AnswerKey::entries' spelling)
    bool dhTable = false;              // step 0 asked: the DH table read from the picture
    symbolic::ParameterMode mode = symbolic::ParameterMode::Numeric;
};

struct ExerciseSet {
    std::string name;  // the first scene's name
    struct Member {
        std::string file;
        std::vector<ParameterRange> ranges;
    };
    std::vector<Member> scenes;  // the family (one for a single scene), without the texts
    std::uint64_t seed = 1;
    symbolic::ParameterMode mode = symbolic::ParameterMode::Numeric;
    std::vector<std::string> entries;
    bool dhTable = false;
    std::vector<ExerciseStudent> students;

    const ExerciseStudent* student(const std::string& id) const;
    // exercise.json: format, the scenes with their ranges, seed, mode, entries, and per
    // student its id, scene, values, fingerprint and folder.
    nlohmann::ordered_json manifest() const;
    // The students' scene texts are read by `sceneText(id)` (from their folders). Throws
    // std::invalid_argument naming what is missing or wrong.
    static ExerciseSet fromManifest(const nlohmann::json& manifest, const std::function<std::string(const std::string&)>& sceneText);
};

// Draws every student's robot: the family member and each value from the seed and the
// student's id, so a student keeps the robot when others are added; two students never share a robot when
// the ranges allow otherwise. The parameters not drawn keep their values, to six
// significant digits (0.16666666666666666 becomes 0.166667): a sheet shows them so, and
// answers are checked exactly against the student's scene. Throws InputError when the scene does not load.
ExerciseSet makeExerciseSet(const ExerciseSpec& spec);

// 16 hex digits identifying a scene file's content (FNV-1a over its JSON, keys sorted,
// every number as the value it stands for (2 and 2.0 alike), without its "exercise" section): the same robot, the same
// fingerprint, whatever the spacing and the answers saved in it.
std::string sceneFingerprint(const std::string& sceneText);

// The answer file a student fills in: {"lagrangelab_answers": 1, "student", "seed",
// "robot", "answers": {entry: ""}} (answers as check-answer --answer-file reads them).
nlohmann::ordered_json answerTemplate(const ExerciseSet& set, const ExerciseStudent& student);

// The tasks of derivation steps first..last: every entry those steps show but the
// trivial ones (constants of a matrix, zeros), the lower triangle of B and the
// Christoffel symbols (C's entries are asked instead).
std::vector<std::string> entriesOfSteps(const AnswerKey& key, int first, int last);
// The tasks when none are named: B's upper triangle, g and C, where not zero.
std::vector<std::string> defaultEntries(const AnswerKey& key);

// An entry's name in LaTeX as a sheet sets it: b11 → b_{11}, E_kin → E_{kin}, T_2^0(1,4) →
// T_{2,14}^{0} (the matrix's label with the entry's indices added, as the derivation's
// pages name entries), p_c2(1) → p_{c2,1}; anything else as it is.
std::string entryLatex(const std::string& id);

// An entry's right answer as the derivation typesets it: "b11 = …" (the trig shorthand,
// the scene's decimals), an equation of motion as itself; null for an unknown id.
present::DisplayPtr exerciseAnswerDisplay(const AnswerKey& key, const std::string& id);

// An entry's right answer in Maxima's syntax (cos(q2), qd1, exact fractions, %pi), for
// STACK; "" for an unknown id.
std::string maximaAnswer(const AnswerKey& key, const std::string& id);

// The set as Moodle XML: one STACK question per task, its parameters drawn by STACK
// within the set's ranges (question variables), the model answer the derivation's in
// Maxima's syntax, one algebraic input and a potential response tree testing AlgEquiv;
// for a family, a question per member and task. Each member with the key of its scene
// derived with its parameters as symbols; the words in `language`.
struct MoodleScene {  // a member of the set's family (set.scenes, in the same order)
    const Scene* scene = nullptr;
    const AnswerKey* parametric = nullptr;
};
std::string moodleXml(const ExerciseSet& set, const std::vector<MoodleScene>& family, present::Language language);

}  // namespace ll
