// `lagrangelab exercise SCENE [SCENE…] --out DIR [--students list.csv | --count N] [--seed S]
// [--entries b11,g2,… | --steps 5-8] [--vary NAME=LOW..HIGH …] [--parametric]`: a robot per
// student (core/pipeline/exercise_set.hpp), from one scene or a family of them (a 2R and a
// 3R arm, a twist, a prismatic joint: one member per student), each in DIR/<id>/ with its
// scene, its sheet (ui/document/exercise_sheets.hpp) and an answer file to fill in; the lecturer's
// solutions.pdf, the set's exercise.json and moodle.xml (STACK) beside them.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <unistd.h>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/output_folder.hpp"
#include "app/progress_bar.hpp"
#include "app/scene_loading.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/scene_file.hpp"
#include "ui/document/exercise_sheets.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::cli {
namespace {

namespace fs = std::filesystem;

std::string joinedNames(const std::vector<std::string>& names, std::size_t most = 12) {
    std::string out;
    for (std::size_t i = 0; i < names.size() && i < most; ++i) out += (i ? ", " : "") + names[i];
    if (names.size() > most) out += ", …";
    return out;
}

bool validStudentId(const std::string& id) {
    if (id.empty() || id.size() > 64 || id == "." || id == "..") return false;
    return std::all_of(id.begin(), id.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'; });
}

// The first cell of a CSV line, unquoted and trimmed.
std::string firstCell(const std::string& line) {
    std::string cell;
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos) return "";
    if (line[i] == '"') {
        for (++i; i < line.size(); ++i) {
            if (line[i] == '"' && i + 1 < line.size() && line[i + 1] == '"') cell += '"', ++i;
            else if (line[i] == '"') break;
            else cell += line[i];
        }
        return cell;
    }
    cell = line.substr(i, line.find_first_of(",;\t", i) - i);
    while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\r')) cell.pop_back();
    return cell;
}

// Student ids from the first column of a CSV file; a header line ("student", "id", …),
// blank lines and # comments are passed over.
std::vector<std::string> studentsFromCsv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw UsageError(UsageId::StudentsFileUnreadable, path);
    std::vector<std::string> ids;
    std::map<std::string, int> firstLine;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a spreadsheet's byte-order mark
        const std::string id = firstCell(line);
        if (id.empty() || id[0] == '#') continue;
        std::string lower = id;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
        if (ids.empty() && firstLine.empty() && (lower == "student" || lower == "id" || lower == "student_id" || lower == "studerende"))
            continue;
        if (!validStudentId(id)) throw UsageError(UsageId::StudentIdInvalid, path, number, id);
        if (auto it = firstLine.find(id); it != firstLine.end()) throw UsageError(UsageId::DuplicateStudent, path, number, id, it->second);
        firstLine.emplace(id, number);
        ids.push_back(id);
    }
    if (ids.empty()) throw UsageError(UsageId::StudentsFileEmpty, path);
    return ids;
}

// --vary NAME=LOW..HIGH, each taken out of args (the option may be given many times).
std::vector<std::string> takeVary(Args& args) {
    std::vector<std::string> vary;
    for (std::size_t i = 0; i < args.size();) {
        if (args[i] == "--vary" && i + 1 < args.size()) {
            vary.push_back(args[i + 1]);
            args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(i) + 2);
        } else if (args[i].rfind("--vary=", 0) == 0) {
            vary.push_back(args[i].substr(7));
            args.erase(args.begin() + static_cast<long>(i));
        } else {
            ++i;
        }
    }
    return vary;
}

// A scene of the set (one, or each member of a family) with the key its tasks are checked against.
struct FamilyMember {
    std::string path;
    Scene scene;
    std::shared_ptr<const AnswerKey> key;
};

// Each member's ranges: the --vary ranges of its parameters (a name no member has is an
// error), or, without --vary, ±20 % of its own link parameters.
std::vector<std::vector<ParameterRange>> rangesFrom(const std::vector<std::string>& texts, const std::vector<FamilyMember>& family) {
    std::vector<ParameterRange> given;
    std::vector<std::string> names;  // every member's, once
    for (const FamilyMember& m : family)
        for (const auto& [name, value] : m.scene.parameters)
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    for (const std::string& text : texts) {
        const std::size_t equals = text.find('='), dots = text.find("..");
        if (equals == std::string::npos || dots == std::string::npos || dots < equals) throw UsageError(UsageId::VaryExpected, text);
        const std::string name = text.substr(0, equals);
        double low = 0, high = 0;
        try {
            low = parseNumber("vary", text.substr(equals + 1, dots - equals - 1));
            high = parseNumber("vary", text.substr(dots + 2));
        } catch (const UsageError&) {
            throw UsageError(UsageId::VaryExpected, text);
        }
        if (std::find(names.begin(), names.end(), name) == names.end())
            throw UsageError(UsageId::VaryUnknown, text, name, joinedNames(names));
        if (low > high) throw UsageError(UsageId::VaryEmptyRange, text, text.substr(equals + 1, dots - equals - 1), text.substr(dots + 2));
        std::erase_if(given, [&](const ParameterRange& r) { return r.name == name; });
        given.push_back(roundedRange(name, low, high));
    }
    std::vector<std::vector<ParameterRange>> ranges;
    bool any = false;
    for (const FamilyMember& m : family) {
        std::vector<ParameterRange> own = texts.empty() ? defaultRanges(m.scene) : std::vector<ParameterRange>{};
        for (const ParameterRange& r : given)
            if (std::any_of(m.scene.parameters.begin(), m.scene.parameters.end(), [&](const auto& p) { return p.first == r.name; }))
                own.push_back(r);
        any = any || !own.empty();
        ranges.push_back(std::move(own));
    }
    if (!any) throw UsageError(UsageId::VaryNothing, family.front().path);
    return ranges;
}

std::uint64_t seedFrom(const std::string& text) {
    std::uint64_t seed = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), seed);
    if (error != std::errc() || end != text.data() + text.size() || text.empty()) throw UsageError(UsageId::SeedExpected, text);
    return seed;
}

// The tasks: --entries validated against every member's derivation, or the entries of
// --steps, or the default ones, that every member has. Step 0 asks for the DH table itself
// (`dhTable`).
std::vector<std::string> tasksFrom(const Options& options, const std::vector<FamilyMember>& family, bool& dhTable) {
    const AnswerKey& first = *family.front().key;
    const auto common = [&](std::vector<std::string> ids) {
        std::erase_if(ids, [&](const std::string& id) {
            return std::any_of(family.begin(), family.end(), [&](const FamilyMember& m) { return m.key->entryId(id).empty(); });
        });
        return ids;
    };
    std::vector<std::string> ids;
    if (options.has("entries")) {
        std::stringstream list(options.text("entries"));
        for (std::string typed; std::getline(list, typed, ',');) {
            typed.erase(0, typed.find_first_not_of(' '));
            typed.erase(typed.find_last_not_of(' ') + 1);
            if (typed.empty()) continue;
            for (const FamilyMember& m : family)
                if (m.key->entryId(typed).empty())
                    throw UsageError(UsageId::ExerciseUnknownEntry, m.scene.name, typed, joinedNames(defaultEntries(*m.key), 8));
            const std::string id = first.entryId(typed);
            if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
        }
        return ids;
    }
    if (options.has("steps")) {
        const std::string text = options.text("steps");
        int from = 0, to = 0;
        const std::size_t dash = text.find('-');
        try {
            from = std::stoi(text.substr(0, dash));
            to = dash == std::string::npos ? from : std::stoi(text.substr(dash + 1));
        } catch (const std::exception&) {
            throw UsageError(UsageId::StepsExpected, text);
        }
        if (from < 0 || to > 8 || from > to) throw UsageError(UsageId::StepsOutOfRange, text);
        dhTable =
            from == 0 && std::none_of(family.begin(), family.end(), [](const FamilyMember& m) { return m.scene.lagrangian.has_value(); });
        ids = common(entriesOfSteps(first, std::max(from, 1), to));
        if (ids.empty() && !dhTable) throw UsageError(UsageId::StepsNoEntries, text, family.front().scene.name);
        return ids;
    }
    return common(defaultEntries(first));
}

}  // namespace

int exerciseCommand(const Args& given) {
    Args args = given;
    const std::vector<std::string> vary = takeVary(args);
    const Options options(args, {"out", "students", "count", "seed", "entries", "steps"}, {"parametric"});
    if (options.positional().empty() || !options.has("out")) throw UsageError(usageLine("exercise"));
    if (options.has("students") && options.has("count")) throw UsageError(UsageId::ExcludeEachOther, "students", "count");
    if (options.has("entries") && options.has("steps")) throw UsageError(UsageId::ExcludeEachOther, "entries", "steps");
    if (!options.has("students") && !options.has("count")) throw UsageError(UsageId::ExerciseNeedsStudents);
    const std::string out = options.text("out");

    std::vector<std::string> students;
    if (options.has("students")) {
        students = studentsFromCsv(options.text("students"));
    } else {
        const std::string text = options.text("count");
        int count = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
        if (error != std::errc() || end != text.data() + text.size() || count < 1 || count > 500)
            throw UsageError(UsageId::CountOutOfRange, text);
        const int width = std::max(2, static_cast<int>(std::to_string(count).size()));
        for (int i = 1; i <= count; ++i) {
            std::string number = std::to_string(i);
            students.push_back("s" + std::string(static_cast<std::size_t>(width) - number.size(), '0') + number);
        }
    }
    const std::uint64_t seed = options.has("seed") ? seedFrom(options.text("seed")) : 1;

    ExerciseSpec spec;
    spec.students = students;
    spec.seed = seed;
    spec.mode = options.has("parametric") ? symbolic::ParameterMode::Parametric : symbolic::ParameterMode::Numeric;
    std::vector<FamilyMember> family;
    for (const std::string& path : options.positional()) {  // one scene, or a family of them
        FamilyMember member{path, loadSceneReportingWarnings(path), nullptr};
        requireValidSceneFrom(member.scene, path);
        member.key = inSceneFile(path, [&] { return AnswerKey::build(member.scene, spec.mode); });
        std::ifstream file(path, std::ios::binary);
        spec.scenes.push_back({fs::path(path).filename().string(), std::string(std::istreambuf_iterator<char>(file), {}), {}});
        family.push_back(std::move(member));
    }
    const std::vector<std::vector<ParameterRange>> ranges = rangesFrom(vary, family);
    for (std::size_t k = 0; k < family.size(); ++k) spec.scenes[k].ranges = ranges[k];
    spec.entries = tasksFrom(options, family, spec.dhTable);
    prepareOutputFolder(out);

    const bool tty = ::isatty(STDERR_FILENO);
    ProgressBar bar(tty);
    const ExerciseSet set = inSceneFile(family.front().path, [&] { return makeExerciseSet(spec); });
    const auto app = makeGuiApplication();
    if (!ui::mathFontsAvailable()) throw std::runtime_error("the Latin Modern fonts are missing: install fonts-lmodern");
    const present::Language language = presentation().language;
    std::vector<std::string> written;
    std::vector<ui::SolutionStudent> solutions;
    bool pictures = true;
    for (std::size_t k = 0; k < set.students.size(); ++k) {
        const ExerciseStudent& student = set.students[k];
        const fs::path folder = fs::path(out) / student.id;
        fs::create_directories(folder);
        saveFileAtomically((folder / "scene.json").string(), student.sceneText, Backup::None);
        ui::SheetStudent sheet{&student, parseScene(student.sceneText), {}};
        if (pictures) {
            try {
                sheet.picture = ui::robotPicture(sheet.scene, 1200, 760);
            } catch (const std::exception& e) {  // no EGL: sheets without the picture, said once
                std::fprintf(stderr, "warning: the sheets have no picture of the robot: %s\n", e.what());
                pictures = false;
            }
        }
        ui::writeExerciseSheet(set, sheet, language, (folder / "sheet.pdf").string());
        saveFileAtomically((folder / "answers.json").string(), answerTemplate(set, student).dump(2) + "\n", Backup::None);
        const auto own = inSceneFile(folder.string(), [&] { return AnswerKey::build(sheet.scene, set.mode); });
        ui::SolutionStudent solution{&student, sheet.scene, {}};
        for (const std::string& entry : set.entries) solution.answers.push_back(exerciseAnswerDisplay(*own, entry));
        solutions.push_back(std::move(solution));
        for (const char* name : {"scene.json", "sheet.pdf", "answers.json"}) written.push_back((folder / name).string());
        bar(0.9 * double(k + 1) / double(set.students.size()));
    }
    ui::writeSolutions(set, solutions, language, (fs::path(out) / "solutions.pdf").string());
    written.push_back((fs::path(out) / "solutions.pdf").string());
    std::vector<std::shared_ptr<const AnswerKey>> parametric;  // the STACK questions' model answers, in names
    std::vector<MoodleScene> quiz;
    for (const FamilyMember& m : family) {
        parametric.push_back(inSceneFile(m.path, [&] { return AnswerKey::build(m.scene, symbolic::ParameterMode::Parametric); }));
        quiz.push_back({&m.scene, parametric.back().get()});
    }
    saveFileAtomically((fs::path(out) / "moodle.xml").string(), moodleXml(set, quiz, language), Backup::None);
    written.push_back((fs::path(out) / "moodle.xml").string());
    saveFileAtomically((fs::path(out) / "exercise.json").string(), set.manifest().dump(2) + "\n", Backup::None);
    written.push_back((fs::path(out) / "exercise.json").string());
    bar(1.0);
    for (const std::string& f : written) std::printf("%s\n", f.c_str());
    return 0;
}

}  // namespace ll::cli
