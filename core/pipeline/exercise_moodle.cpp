// An exercise set as Moodle XML for STACK (core/pipeline/exercise_set.hpp): a question per
// task whose question variables draw the robot's numbers within the set's ranges, the
// model answer the derivation's with those numbers (exact fractions, so AlgEquiv compares
// exactly), one algebraic input, one potential response tree.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "core/pipeline/exercise_set.hpp"
#include "core/io/xml_text.hpp"
#include "core/present/message_text.hpp"

namespace ll {
namespace {

// HTML inside CDATA: "]]>" cannot stand there.
std::string cdata(const std::string& html) {
    std::string safe = html;
    for (std::size_t at; (at = safe.find("]]>")) != std::string::npos;) safe.replace(at, 3, "]]&gt;");
    return "<![CDATA[" + safe + "]]>";
}

// A double as an exact Maxima fraction of its shortest decimal: 0.8 → 8/10, 9.81 → 981/100.
std::string maximaNumber(double value) {
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    std::string text(buffer, end);
    if (text.find_first_of("eE") != std::string::npos) return text;  // 1e-05: Maxima reads it (a float)
    const std::size_t dot = text.find('.');
    if (dot == std::string::npos) return text;
    const bool negative = text[0] == '-';
    std::string digits = text.substr(negative ? 1 : 0, dot - (negative ? 1 : 0)) + text.substr(dot + 1);
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
    return std::string("(") + (negative ? "-" : "") + digits + "/1" + std::string(text.size() - dot - 1, '0') + ")";
}

std::string robotHtml(const Scene& scene, present::Language language) {
    std::ostringstream html;
    const auto words = [&](MessageId id) { return xmlEscaped(present::messageText(Message(id), language)); };
    const std::vector<RobotTableRow> rows = robotTable(scene);
    if (!rows.empty()) {
        html << "<p>" << words(scene.robot.convention == DhConvention::Modified ? MessageId::TitleDhModified : MessageId::TitleDhStandard)
             << "</p>\n<table border=\"1\" cellpadding=\"4\"><tr><th>" << words(MessageId::ExerciseJoint)
             << "</th><th>a</th><th>α</th><th>d</th><th>θ</th></tr>\n";
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const RobotTableRow& r = rows[i];
            html << "<tr><td>" << i + 1 << "</td><td>" << xmlEscaped(r.a) << "</td><td>" << xmlEscaped(r.alpha) << "</td><td>"
                 << xmlEscaped(r.d) << "</td><td>" << xmlEscaped(r.theta) << "</td></tr>\n";
        }
        html << "</table>\n<p>" << words(MessageId::ExerciseLinks) << "</p>\n<table border=\"1\" cellpadding=\"4\"><tr><th>"
             << words(MessageId::ExerciseJoint) << "</th><th>" << words(MessageId::ExerciseMass) << "</th><th>"
             << words(MessageId::ExerciseCom) << "</th><th>" << words(MessageId::ExerciseInertia) << "</th></tr>\n";
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const RobotTableRow& r = rows[i];
            html << "<tr><td>" << i + 1 << "</td><td>" << xmlEscaped(r.mass) << "</td><td>[" << xmlEscaped(r.com[0]) << ", "
                 << xmlEscaped(r.com[1]) << ", " << xmlEscaped(r.com[2]) << "]</td><td>";
            for (int k = 0; k < 6; ++k) html << (k ? ", " : "") << xmlEscaped(r.inertia[k]);
            html << "</td></tr>\n";
        }
        html << "</table>\n";
    } else if (scene.lagrangian) {
        html << "<p>E_kin = " << xmlEscaped(scene.lagrangian->kinetic) << "<br/>E_pot = " << xmlEscaped(scene.lagrangian->potential)
             << "</p>\n";
    }
    if (scene.effects.gravity) {
        const Eigen::Vector3d& g = *scene.effects.gravity;
        const std::string vector = "[" + shortNumber(g[0]) + ", " + shortNumber(g[1]) + ", " + shortNumber(g[2]) + "]";
        html << "<p>" << xmlEscaped(present::messageText(message(MessageId::ExerciseGravity, vector), language)) << "</p>\n";
    }
    return html.str();
}

// One STACK question: its name, text (HTML), question variables with the model answer ta,
// the note that tells its variants apart.
void writeQuestion(std::ostream& xml, const std::string& name, const std::string& html, const std::string& variables,
                   const std::string& note, std::uint64_t seed, const std::function<std::string(const Message&)>& words) {
    xml << "<question type=\"stack\">\n"
        << "  <name><text>" << xmlEscaped(name) << "</text></name>\n"
        << "  <questiontext format=\"html\"><text>" << cdata(html) << "</text></questiontext>\n"
        << "  <generalfeedback format=\"html\"><text></text></generalfeedback>\n"
        << "  <defaultgrade>1</defaultgrade>\n  <penalty>0.1</penalty>\n  <hidden>0</hidden>\n  <idnumber></idnumber>\n"
        << "  <stackversion><text></text></stackversion>\n"
        << "  <questionvariables><text>" << xmlEscaped(variables) << "</text></questionvariables>\n"
        << "  <specificfeedback format=\"html\"><text>[[feedback:prt1]]</text></specificfeedback>\n"
        << "  <questionnote><text>{@[" << xmlEscaped(note) << "]@}</text></questionnote>\n"
        << "  <questionsimplify>1</questionsimplify>\n  <assumepositive>0</assumepositive>\n  <assumereal>1</assumereal>\n"
        << "  <prtcorrect format=\"html\"><text>" << xmlEscaped(words(Message(MessageId::ExerciseMoodleRight))) << "</text></prtcorrect>\n"
        << "  <prtpartiallycorrect format=\"html\"><text></text></prtpartiallycorrect>\n"
        << "  <prtincorrect format=\"html\"><text>" << xmlEscaped(words(Message(MessageId::ExerciseMoodleWrong)))
        << "</text></prtincorrect>\n"
        << "  <multiplicationsign>dot</multiplicationsign>\n  <sqrtsign>1</sqrtsign>\n  <complexno>i</complexno>\n"
        << "  <inversetrig>cos-1</inversetrig>\n  <logicsymbol>lang</logicsymbol>\n  <matrixparens>[</matrixparens>\n"
        << "  <variantsselectionseed>" << seed << "</variantsselectionseed>\n"
        << "  <input>\n    <name>ans1</name>\n    <type>algebraic</type>\n    <tans>ta</tans>\n    <boxsize>60</boxsize>\n"
        << "    <strictsyntax>1</strictsyntax>\n    <insertstars>0</insertstars>\n    <syntaxhint></syntaxhint>\n"
        << "    <syntaxattribute>0</syntaxattribute>\n    <forbidwords></forbidwords>\n    <allowwords></allowwords>\n"
        << "    <forbidfloat>0</forbidfloat>\n    <requirelowestterms>0</requirelowestterms>\n"
        << "    <checkanswertype>0</checkanswertype>\n    <mustverify>1</mustverify>\n    <showvalidation>1</showvalidation>\n"
        << "    <options></options>\n  </input>\n"
        << "  <prt>\n    <name>prt1</name>\n    <value>1.0000000</value>\n    <autosimplify>1</autosimplify>\n"
        << "    <feedbackstyle>1</feedbackstyle>\n    <feedbackvariables><text></text></feedbackvariables>\n"
        << "    <node>\n      <name>0</name>\n      <description></description>\n      <answertest>AlgEquiv</answertest>\n"
        << "      <sans>ans1</sans>\n      <tans>ta</tans>\n      <testoptions></testoptions>\n      <quiet>0</quiet>\n"
        << "      <truescoremode>=</truescoremode>\n      <truescore>1.0000000</truescore>\n      <truepenalty></truepenalty>\n"
        << "      <truenextnode>-1</truenextnode>\n      <trueanswernote>prt1-1-T</trueanswernote>\n"
        << "      <truefeedback format=\"html\"><text></text></truefeedback>\n"
        << "      <falsescoremode>=</falsescoremode>\n      <falsescore>0.0000000</falsescore>\n      <falsepenalty></falsepenalty>\n"
        << "      <falsenextnode>-1</falsenextnode>\n      <falseanswernote>prt1-1-F</falseanswernote>\n"
        << "      <falsefeedback format=\"html\"><text></text></falsefeedback>\n    </node>\n  </prt>\n"
        << "</question>\n";
}

}  // namespace

std::string moodleXml(const ExerciseSet& set, const std::vector<MoodleScene>& family, present::Language language) {
    const std::function<std::string(const Message&)> words = [&](const Message& m) { return present::messageText(m, language); };
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n";
    xml << "<question type=\"category\">\n  <category><text>$course$/top/"
        << xmlEscaped(words(message(MessageId::ExerciseMoodleCategory, set.name))) << "</text></category>\n</question>\n";
    for (std::size_t k = 0; k < family.size(); ++k) {
        const MoodleScene& member = family[k];
        const Scene& scene = *member.scene;
        std::map<std::string, const ParameterRange*> varied;
        for (const ParameterRange& r : set.scenes.at(k).ranges) varied[r.name] = &r;
        const std::map<std::string, std::string> units = parameterUnits(scene);
        // The question variables: each varied parameter drawn on its grid, the others their value.
        std::ostringstream variables, note, values;
        for (const auto& [name, value] : scene.parameters) {
            if (auto it = varied.find(name); it != varied.end()) {
                const ParameterRange& r = *it->second;
                const double scale = std::pow(10.0, r.decimals);
                const long long lo = std::llround(r.low * scale), hi = std::llround(r.high * scale);
                variables << name << ": (" << lo << " + rand(" << hi - lo + 1 << "))/" << static_cast<long long>(scale) << ";\n";
                note << (note.tellp() > 0 ? ", " : "") << name;
            } else {
                variables << name << ": " << maximaNumber(std::stod(shortNumber(value))) << ";\n";  // as the sheets have it
            }
            const auto unit = units.find(name);
            values << (values.tellp() > 0 ? ", " : "") << name << " = {@float(" << name << ")@}"
                   << (unit != units.end() ? "\u00a0" + unit->second : "");
        }
        const std::string robot = robotHtml(scene, language);
        const std::string title = family.size() == 1 ? set.name : scene.name;
        for (const std::string& entry : set.entries) {
            std::ostringstream text;
            text << "<p>" << xmlEscaped(words(message(MessageId::ExerciseMoodleTask, entry))) << "</p>\n"
                 << robot << "<p>" << xmlEscaped(words(Message(MessageId::ExerciseParameters))) << ": " << values.str() << "</p>\n"
                 << "<p>\\(" << entryLatex(entry) << " = \\) [[input:ans1]] [[validation:ans1]]</p>\n";
            writeQuestion(xml, title + ": " + entry, text.str(), variables.str() + "ta: " + maximaAnswer(*member.parametric, entry) + ";",
                          note.str(), set.seed, words);
        }
    }
    xml << "</quiz>\n";
    return xml.str();
}

}  // namespace ll
