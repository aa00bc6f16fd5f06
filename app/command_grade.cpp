// `lagrangelab grade DIR ANSWERS… [--out DIR2]`: every answer file (or every .json file in a
// folder given) checked against its own student's robot from the exercise set in DIR
// (exercise.json, made by `lagrangelab exercise`): grades.csv (student, entry, verdict,
// hint) and a feedback PDF per student (ui/document/exercise_sheets.hpp), and a summary
// line. A file that is not an answer file of this set, names another robot or seed, or
// answers a task the set has not: one line naming the file and the field, exit 2, before
// anything is graded or written.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/output_folder.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/scene_file.hpp"
#include "core/present/message_text.hpp"
#include "ui/document/exercise_sheets.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::cli {
namespace {

namespace fs = std::filesystem;

std::string fileText(const fs::path& path, bool& ok) {
    std::ifstream in(path, std::ios::binary);
    ok = static_cast<bool>(in);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

ExerciseSet readExerciseSet(const std::string& dir) {
    const fs::path manifestPath = fs::path(dir) / "exercise.json";
    bool ok = false;
    const std::string text = fileText(manifestPath, ok);
    if (!ok) throw UsageError(UsageId::GradeNoManifest, dir);
    try {
        ExerciseSet set = ExerciseSet::fromManifest(nlohmann::json::parse(text), [&](const std::string& folder) {
            bool read = false;
            std::string scene = fileText(fs::path(dir) / folder / "scene.json", read);
            if (!read) throw std::invalid_argument((fs::path(dir) / folder / "scene.json").string() + ": cannot be read");
            return scene;
        });
        for (const ExerciseStudent& s : set.students)  // a scene edited since: its answers would be judged against another robot
            if (sceneFingerprint(s.sceneText) != s.fingerprint)
                throw std::invalid_argument((fs::path(dir) / s.id / "scene.json").string() + " is not the robot the set made (" +
                                            s.fingerprint + ")");
        return set;
    } catch (const nlohmann::json::exception& e) {
        throw UsageError(UsageId::GradeManifestBad, manifestPath.string(), e.what());
    } catch (const std::invalid_argument& e) {
        throw UsageError(UsageId::GradeManifestBad, manifestPath.string(), e.what());
    }
}

// The answer files named: files as given, folders by every .json file below them but the
// set's own (exercise.json, scene.json), in name order.
std::vector<fs::path> answerFiles(const std::vector<std::string>& given) {
    std::vector<fs::path> files;
    for (const std::string& g : given) {
        if (!fs::is_directory(g)) {
            files.emplace_back(g);
            continue;
        }
        std::vector<fs::path> found;
        for (const auto& entry : fs::recursive_directory_iterator(g))
            if (entry.is_regular_file() && entry.path().extension() == ".json" && entry.path().filename() != "exercise.json" &&
                entry.path().filename() != "scene.json")
                found.push_back(entry.path());
        if (found.empty()) throw UsageError(UsageId::GradeNoAnswerFiles, g);
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

struct Submission {
    std::string file;
    const ExerciseStudent* student = nullptr;
    std::map<std::string, std::string> answers;
};

// The answers of a student's tasks, checked against the set's tasks.
void readAnswers(const std::string& name, const nlohmann::json& answers, const ExerciseSet& set, Submission& s) {
    if (!answers.is_object()) throw UsageError(UsageId::GradeAnswerNotJson, name, std::string("\"answers\": ") + answers.type_name());
    std::string tasks;
    for (const std::string& e : set.entries) tasks += (tasks.empty() ? "" : ", ") + e;
    for (const auto& [entry, answer] : answers.items()) {
        if (std::find(set.entries.begin(), set.entries.end(), entry) == set.entries.end())
            throw UsageError(UsageId::GradeUnknownEntry, name, entry, tasks);
        if (!answer.is_string()) throw UsageError(UsageId::GradeAnswerNotString, name, entry);
        s.answers[entry] = answer.get<std::string>();
    }
}

// A student's scene.json handed in with the answers the window's exercise mode saved in it:
// the student is the one whose robot it is (no two share one).
Submission handedInScene(const std::string& name, const std::string& text, const nlohmann::json& json, const ExerciseSet& set) {
    Submission s;
    s.file = name;
    const std::string robot = sceneFingerprint(text);
    for (const ExerciseStudent& student : set.students)
        if (student.fingerprint == robot) s.student = &student;
    if (!s.student) throw UsageError(UsageId::GradeSceneNoStudent, name, robot);
    const nlohmann::json& exercise = json["exercise"];
    if (exercise.is_object() && exercise.contains("answers")) readAnswers(name, exercise["answers"], set, s);
    return s;
}

Submission readSubmission(const fs::path& path, const ExerciseSet& set) {
    const std::string name = path.string();
    bool ok = false;
    const std::string text = fileText(path, ok);
    if (!ok) throw UsageError(UsageId::GradeAnswerUnreadable, name);
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw UsageError(UsageId::GradeAnswerNotJson, name, e.what());
    }
    if (!json.is_object()) throw UsageError(UsageId::GradeAnswerNotJson, name, json.type_name());
    if (json.contains("format") && json.contains("exercise")) return handedInScene(name, text, json, set);
    for (const char* field : {"student", "seed", "robot", "answers"})
        if (!json.contains(field)) throw UsageError(UsageId::GradeMissingField, name, field);
    Submission s;
    s.file = name;
    const std::string id = json["student"].is_string() ? json["student"].get<std::string>() : json["student"].dump();
    s.student = set.student(id);
    if (!s.student) throw UsageError(UsageId::GradeUnknownStudent, name, id);
    const nlohmann::json& seed = json["seed"];
    if (!seed.is_number_unsigned() || seed.get<std::uint64_t>() != set.seed)
        throw UsageError(UsageId::GradeWrongSeed, name, seed.dump(), std::to_string(set.seed));
    const std::string robot = json["robot"].is_string() ? json["robot"].get<std::string>() : json["robot"].dump();
    if (robot != s.student->fingerprint) throw UsageError(UsageId::GradeWrongRobot, name, robot, id, s.student->fingerprint);
    readAnswers(name, json["answers"], set, s);
    return s;
}

// A CSV field, quoted when it holds a comma, a quote, a line break or edge spaces (RFC 4180).
std::string csvField(const std::string& text) {
    const bool quote = text.find_first_of(",\"\r\n") != std::string::npos || (!text.empty() && (text.front() == ' ' || text.back() == ' '));
    if (!quote) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// One task judged: the verdict by `exact`, the key with the parameters as symbols and their
// values exact (1.1 is 11/10), so numbers typed from the sheet are compared exactly; when
// wrong, the hints of `numeric` (the derivation with the numbers in, whose feedback speaks of
// numbers: "only the sign") where it reads the answer. A numeric set expects numbers, so
// "right, with the values in place of the names" is no news there.
AnswerCheck judged(const AnswerKey& exact, const AnswerKey* numeric, const std::string& entry, const std::string& typed) {
    AnswerCheck c = exact.check({entry, typed, false});
    if (!numeric) return c;
    c.withValues = false;
    if (c.verdict != AnswerVerdict::Wrong) return c;
    const AnswerCheck n = numeric->check({entry, typed, false});
    if (n.verdict == AnswerVerdict::Unreadable) return c;  // names: the exact key's hints
    c.hints = n.verdict == AnswerVerdict::Wrong ? n.hints : std::vector<Message>{};
    c.kinds = n.kinds;
    c.links = n.links;
    return c;
}

std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

}  // namespace

int gradeCommand(const Args& args) {
    const Options options(args, {"out"});
    if (options.positional().size() < 2) throw UsageError(UsageId::GradeNeedsAnswers);
    const std::string dir = options.positional()[0];
    const ExerciseSet set = readExerciseSet(dir);
    const std::vector<fs::path> files = answerFiles({options.positional().begin() + 1, options.positional().end()});
    // Every file read and checked before anything is graded: bad input stops the whole run.
    std::vector<Submission> submissions;
    std::map<std::string, std::string> fileOf;
    for (const fs::path& f : files) {
        Submission s = readSubmission(f, set);
        if (auto [it, inserted] = fileOf.emplace(s.student->id, s.file); !inserted)
            throw UsageError(UsageId::GradeStudentTwice, s.file, s.student->id, it->second);
        submissions.push_back(std::move(s));
    }
    const std::string out = options.text("out", dir);
    prepareOutputFolder(out);

    const present::Language language = presentation().language;
    const auto words = [&](const Message& m) { return present::messageText(m, language); };
    const auto app = makeGuiApplication();
    if (!ui::mathFontsAvailable()) throw std::runtime_error("the Latin Modern fonts are missing: install fonts-lmodern");
    std::ostringstream csv;
    csv << "student,entry,verdict,hint\n";
    int right = 0, wrong = 0, unreadable = 0, unanswered = 0;
    std::vector<std::string> feedbackFiles;
    for (const Submission& s : submissions) {
        const Scene scene = parseScene(s.student->sceneText);
        const bool numbers = set.mode == symbolic::ParameterMode::Numeric;
        const auto key = AnswerKey::build(scene, numbers ? symbolic::ParameterMode::Parametric : set.mode);
        const auto numericKey = numbers ? AnswerKey::build(scene, symbolic::ParameterMode::Numeric) : nullptr;
        std::vector<ui::GradedTask> tasks;
        for (const std::string& entry : set.entries) {
            ui::GradedTask task;
            task.entry = entry;
            const auto it = s.answers.find(entry);
            task.typed = it == s.answers.end() ? "" : trimmed(it->second);
            std::string verdict = "unanswered", hint;
            if (!task.typed.empty()) {
                task.check = judged(*key, numericKey.get(), entry, task.typed);
                verdict = answerVerdictName(task.check.verdict);
                if (task.check.verdict == AnswerVerdict::Unreadable) hint = words(task.check.problem);
                for (const Message& h : task.check.hints) hint += (hint.empty() ? "" : " ") + words(h);
            }
            (verdict == "right" ? right : verdict == "wrong" ? wrong : verdict == "unreadable" ? unreadable : unanswered)++;
            csv << csvField(s.student->id) << ',' << csvField(entry) << ',' << verdict << ',' << csvField(hint) << '\n';
            tasks.push_back(std::move(task));
        }
        const fs::path folder = fs::path(out) / s.student->id;
        fs::create_directories(folder);
        ui::writeFeedback(set, *s.student, scene, tasks, language, (folder / "feedback.pdf").string());
        feedbackFiles.push_back((folder / "feedback.pdf").string());
    }
    const fs::path grades = fs::path(out) / "grades.csv";
    saveFileAtomically(grades.string(), csv.str(), Backup::None);
    std::printf("%s\n", words(message(MessageId::ExerciseGradeSummary, static_cast<int>(submissions.size()),
                                      static_cast<int>(submissions.size() * set.entries.size()), right, wrong, unreadable, unanswered))
                            .c_str());
    std::string missing;  // the students of the set with no answer file among those given
    int without = 0;
    for (const ExerciseStudent& student : set.students)
        if (!fileOf.count(student.id)) missing += (without++ ? ", " : "") + student.id;
    if (without)
        std::printf("%s\n",
                    words(message(MessageId::ExerciseNotHandedIn, without, static_cast<int>(set.students.size()), missing)).c_str());
    std::printf("%s\n", grades.string().c_str());
    for (const std::string& f : feedbackFiles) std::printf("%s\n", f.c_str());
    return 0;
}

}  // namespace ll::cli
