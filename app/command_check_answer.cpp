// `lagrangelab check-answer SCENE [--entry ENTRY --answer "…" | --answer-file F]
// [--format text|json] [--reveal] [--symbolic|--numeric]`: a student's own answer for one
// entry of the derivation (or many, from a JSON file {"b11": "…", "g2": "…"}, or those
// the scene's "exercise" section holds when neither is given), checked
// exactly (core/pipeline/answer_check.hpp): what was read, right or wrong, and why.
// Exit 0 when every answer is right, 1 when one is wrong, 2 when one is unreadable or
// names no entry (and for bad input).
#include <cstdio>
#include <fstream>
#include <iterator>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/pipeline/answer_check.hpp"
#include "core/pipeline/exercise_set.hpp"
#include "core/present/message_text.hpp"

namespace ll::cli {
namespace {

// The answers of an answer file (`lagrangelab exercise`'s template, or {"b11": "…"});
// `robot`: the fingerprint of the robot it names, when it names one.
std::vector<std::pair<std::string, std::string>> answersFromFile(const std::string& path, std::string& robot) {
    std::ifstream in(path);
    if (!in) throw UsageError(UsageId::AnswerFileUnreadable, path);
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::ordered_json json;
    try {
        json = nlohmann::ordered_json::parse(text.str());
    } catch (const nlohmann::json::parse_error& e) {
        throw UsageError(UsageId::AnswerFileNotJson, path, e.what());
    }
    if (json.is_object() && json.contains("robot") && json["robot"].is_string()) robot = json["robot"].get<std::string>();
    if (json.is_object() && json.contains("answers")) json = json["answers"];
    if (!json.is_object()) throw UsageError(UsageId::AnswerFileNotJson, path, json.type_name());
    std::vector<std::pair<std::string, std::string>> answers;
    for (const auto& [entry, answer] : json.items()) {
        if (!answer.is_string()) throw UsageError(UsageId::AnswerFileValue, path, entry);
        answers.emplace_back(entry, answer.get<std::string>());
    }
    return answers;
}

std::string words(const Message& m) { return present::messageText(m, presentation().language); }

void printText(const AnswerCheck& c) {
    if (c.verdict == AnswerVerdict::Unreadable) {
        std::printf("%s: %s: %s\n", c.entry.c_str(), words(Message(MessageId::AnswerUnreadable)).c_str(), words(c.problem).c_str());
        return;
    }
    std::printf("%s: %s\n", c.entry.c_str(), words(message(MessageId::AnswerReadAs, c.readAs)).c_str());
    const bool right = c.verdict == AnswerVerdict::Right;
    std::printf("%s: %s\n", c.entry.c_str(), words(Message(right ? MessageId::AnswerRight : MessageId::AnswerWrong)).c_str());
    if (c.writtenDifferently) std::printf("  %s\n", words(Message(MessageId::AnswerWrittenDifferently)).c_str());
    if (c.withValues) std::printf("  %s\n", words(Message(MessageId::AnswerWithValues)).c_str());
    if (c.sixtyDigits) std::printf("  %s\n", words(message(MessageId::AnswerComparedToDigits, c.points)).c_str());
    for (const Message& hint : c.hints) std::printf("  %s\n", words(hint).c_str());
    if (!c.rightAnswer.empty()) std::printf("  %s\n", words(message(MessageId::AnswerTheRightOne, c.rightAnswer)).c_str());
}

nlohmann::ordered_json json(const AnswerCheck& c) {
    nlohmann::ordered_json j;
    j["entry"] = c.entry;
    j["verdict"] = answerVerdictName(c.verdict);
    j["read_as"] = c.readAs;
    j["read_as_latex"] = c.readAsLatex;
    nlohmann::ordered_json hints = nlohmann::ordered_json::array();
    if (c.verdict == AnswerVerdict::Unreadable) hints.push_back(words(c.problem));
    if (c.writtenDifferently) hints.push_back(words(Message(MessageId::AnswerWrittenDifferently)));
    if (c.withValues) hints.push_back(words(Message(MessageId::AnswerWithValues)));
    for (const Message& hint : c.hints) hints.push_back(words(hint));
    j["hints"] = hints;
    nlohmann::ordered_json kinds = nlohmann::ordered_json::array();
    for (AnswerErrorKind k : c.kinds) kinds.push_back(answerErrorKindName(k));
    j["kinds"] = kinds;
    j["links"] = c.links;
    if (c.position) j["position"] = c.position;
    j["points"] = c.points;
    j["exact"] = !c.sixtyDigits;
    if (!c.rightAnswer.empty()) j["answer"] = c.rightAnswer;
    return j;
}

}  // namespace

int checkAnswerCommand(const Args& args) {
    const Options options(args, {"entry", "answer", "answer-file", "format"}, {"reveal", "symbolic", "numeric"});
    if (options.positional().size() != 1) throw UsageError(usageLine("check-answer"));
    const std::string format = options.text("format", "text");
    if (format != "text" && format != "json") throw UsageError(UsageId::ExpectedOneOf, "format", "text", "json", format);
    if (options.has("symbolic") && options.has("numeric")) throw UsageError(UsageId::ExcludeEachOther, "symbolic", "numeric");
    std::vector<std::pair<std::string, std::string>> answers;
    std::string robot;  // the answer file's robot, when it names one
    if (options.has("answer-file")) {
        if (options.has("answer") || options.has("entry"))
            throw UsageError(UsageId::ExcludeEachOther, "answer-file", options.has("answer") ? "answer" : "entry");
        answers = answersFromFile(options.text("answer-file"), robot);
    } else if (options.has("entry") || options.has("answer")) {
        if (!options.has("entry") || !options.has("answer")) throw UsageError(UsageId::AnswerNeeded);
        answers.emplace_back(options.text("entry"), options.text("answer"));
    }
    const Scene scene = loadSceneReportingWarnings(options.positional()[0]);
    if (!robot.empty()) {  // answers for another student's robot would be judged against the wrong one
        std::ifstream file(options.positional()[0], std::ios::binary);
        const std::string own = sceneFingerprint(std::string(std::istreambuf_iterator<char>(file), {}));
        if (robot != own) throw UsageError(UsageId::AnswerFileOtherRobot, options.text("answer-file"), robot, options.positional()[0], own);
    }
    if (answers.empty()) {  // the answers the scene holds (the window's exercise mode saves them there)
        for (const auto& [entry, answer] : scene.exercise.answers)
            if (!answer.empty()) answers.emplace_back(entry, answer);
        if (answers.empty()) throw UsageError(UsageId::AnswerNeeded);
    }
    const symbolic::ParameterMode mode = options.has("symbolic")  ? symbolic::ParameterMode::Textbook
                                         : options.has("numeric") ? symbolic::ParameterMode::Numeric
                                                                  : symbolic::ParameterMode::Parametric;
    const auto key = inSceneFile(options.positional()[0], [&] { return AnswerKey::build(scene, mode); });
    int exit = 0;
    for (const auto& [entry, answer] : answers) {
        const AnswerCheck c = key->check({entry, answer, options.has("reveal")});
        if (c.verdict == AnswerVerdict::Unreadable) exit = 2;
        else if (c.verdict == AnswerVerdict::Wrong && exit == 0) exit = 1;
        if (format == "json") std::cout << json(c).dump() << '\n';  // one object per line (JSON Lines)
        else printText(c);
    }
    return exit;
}

}  // namespace ll::cli
