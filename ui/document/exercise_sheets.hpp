#pragma once
// The PDFs of an exercise set (`lagrangelab exercise`, `lagrangelab grade`), A4 portrait,
// set with the derivation's typesetter (Latin Modern, ui/paint/math_typesetter.hpp):
//   sheet.pdf      a student's robot drawn headless at q = 0 with its DH frames, its DH
//                  table (or, when step 0 is asked, an empty one to fill in from the
//                  picture), its links and numbers, the tasks with a box to write in each
//   solutions.pdf  for the lecturer: a page per student, the robot's numbers and the
//                  right answers typeset as the derivation prints them
//   feedback.pdf   after grading: per task what was read, right or wrong and the hints,
//                  never the right answer
// Every word in the set's language (core/model/messages/exercise.def). Needs a
// QGuiApplication (fonts); the picture an EGL context (ui/paint/headless_renderer.hpp).
#include <QImage>
#include <string>
#include <vector>

#include "core/model/scene.hpp"
#include "core/pipeline/answer_check.hpp"
#include "core/pipeline/exercise_set.hpp"
#include "core/present/display_tree.hpp"
#include "core/present/language.hpp"

namespace ll::ui {

// The robot at q = 0 with its DH frames, on white, width × height pixels.
QImage robotPicture(const Scene& scene, int width, int height);

struct SheetStudent {
    const ExerciseStudent* student = nullptr;
    Scene scene;     // the student's robot
    QImage picture;  // robotPicture of it (null: no picture)
};

// Each writer returns the page count, or throws std::runtime_error naming the file.
int writeExerciseSheet(const ExerciseSet& set, const SheetStudent& student, present::Language language, const std::string& path);

struct SolutionStudent {
    const ExerciseStudent* student = nullptr;
    Scene scene;
    std::vector<present::DisplayPtr> answers;  // "entry = right answer", in the set's order (exerciseAnswerDisplay)
};
int writeSolutions(const ExerciseSet& set, const std::vector<SolutionStudent>& students, present::Language language,
                   const std::string& path);

struct GradedTask {
    std::string entry;
    std::string typed;  // the answer as the file has it ("" unanswered)
    AnswerCheck check;  // not used when unanswered
};
int writeFeedback(const ExerciseSet& set, const ExerciseStudent& student, const Scene& scene, const std::vector<GradedTask>& tasks,
                  present::Language language, const std::string& path);

}  // namespace ll::ui
