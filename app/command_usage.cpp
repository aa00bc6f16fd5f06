#include "app/command_usage.hpp"

#include <array>

namespace ll::cli {
namespace {

struct CommandText {
    const char* name;
    const char* synopsis;  // after "lagrangelab <name> "; '\n' between lines
    const char* summary;
};

constexpr std::array<CommandText, 18> commands{{
    {"eval", "SCENE --q v1,... --qd v1,... [--t T] [--tau v1,...]", "B, C, g, Q, q̈, E_kin, E_pot at one state, as JSON"},
    {"simulate",
     "SCENE [--duration T] [--integrator NAME] [--abs-tol X] [--rel-tol X] [--dt X]\n"
     "[--output-rate HZ] [--out FILE.csv|FILE.json]",
     "integrate the equations of motion; trajectory to --out or CSV on stdout, summary on stderr"},
    {"derive",
     "SCENE [--format text|latex|json|pdf|svg|png] [--out FILE] [--steps 0-9] [--symbolic] [--numeric] [--timings]\n"
     "[--form auto|structured|expanded] [--entry B11,C23,g4] [--verify] [--lang da|en]\n"
     "[--notation notes|siciliano|spong|craig]",
     "the model step by step as the course notes derive it (symbolic, GiNaC); structured\n"
     "(named link quantities) for large robots, single entries expanded on demand"},
    {"codegen", "SCENE --lang c|python [--out FILE] [--numeric]",
     "the structured model as C99 (math.h only) or Python (standard library) functions for\n"
     "B(q), C(q, qd), g(q) and the forward dynamics"},
    {"render",
     "SCENE --out FILE.mp4|.webm|.gif|.png|FOLDER [--duration T] [--fps F] [--size WxH]\n"
     "[--camera front|side|top|iso|az,el[,dist]] [--speed X] [--overlay time,energy,name|none]\n"
     "[--trail on|off] [--frames on|off] [--at T] [--msaa auto|edges|0|2|4|8] [--layout view|composite] [--step N]",
     "simulate and render the 3D scene headless (no X server needed) to a video, a still or PNG frames;\n"
     "--layout composite: one slide with the 3D view, derivation step N's key equation (default 8) and\n"
     "the energy plot with a moving cursor"},
    {"report", "SCENE --out DIR [--duration T] [--lesson LESSON] [--lang da|en] [--notation notes|siciliano|spong|craig]",
     "the lab-report bundle in one folder: derivation.pdf, trajectory.csv (units in its header),\n"
     "energy.svg and joints.svg, the scene file, slide.mp4 (the composite slide) and index.md;\n"
     "--lesson: the lesson's stills in lesson/, shown in index.md (needs a display)"},
    {"check", "SCENE [--duration T] [--format text|json]",
     "the model's properties along a simulated run: B positive definite and its condition, Ḃ − 2C\n"
     "skew, power balance, Newton–Euler against B q̈ + C q̇ + g, energy; exit 1 when one fails"},
    {"compare-laws", "SCENE [--duration T] [--format text|json] [--out FILE.svg|png]",
     "a controlled scene run under each law (pd, pd_gravity, computed_torque, feedforward) with its own\n"
     "gains, reference and controller model: RMS and largest error, largest torque, the actuators' work\n"
     "and the time saturated; a law the robot cannot carry out says why; --out: the plot against time"},
    {"check-answer",
     "SCENE [--entry ENTRY --answer \"...\" | --answer-file FILE.json] [--format text|json] [--reveal]\n"
     "[--symbolic] [--numeric] [--lang da|en]",
     "a student's own answer for an entry of the derivation (b11, c121, g2, T_2^0(1,4), p_c2(1), E_kin,\n"
     "equation1, dL/dx_dot) checked exactly: what was read, right or wrong, and which link, term or\n"
     "slip (without an answer given: those the scene's \"exercise\" section holds); exit 0 right,\n"
     "1 wrong, 2 unreadable"},
    {"exercise",
     "SCENE [SCENE...] --out DIR --students FILE.csv | --count N [--seed S] [--entries b11,g2,... | --steps 5-8]\n"
     "[--vary NAME=LOW..HIGH ...] [--parametric] [--lang da|en]",
     "exercise sheets: a robot per student (one of the scenes given, its numbers drawn within the ranges,\n"
     "both from the seed), each with sheet.pdf, scene.json and answers.json to fill in; solutions.pdf,\n"
     "exercise.json and moodle.xml (STACK)"},
    {"grade", "DIR ANSWERS... [--out DIR] [--lang da|en]",
     "every answer file checked against its own student's robot of the exercise set in DIR:\n"
     "grades.csv (student, entry, verdict, hint) and a feedback.pdf per student"},
    {"import", "ROBOT.urdf --out SCENE.json [--base LINK] [--tip LINK] [--convention standard|modified]",
     "a URDF robot as a scene: the DH table found from the joint axes by the textbook's rules (each frame's\n"
     "case on stderr), each link's mass, centre of mass and inertia (fixed links lumped in) in its DH frame"},
    {"export-urdf", "SCENE --out ROBOT.urdf",
     "a robot scene as URDF: a link per DH link with its inertial, a joint per DH row, friction as\n"
     "<dynamics>; import gives the same B, C and g back"},
    {"lesson", "LESSON.lesson --out DIR [--format pdf|png|mp4] [--size WxH] [--notes] | --embed OUT.lesson",
     "a lesson's views as the presented window shows them (16:9, 1920x1080 unless --size): lesson.pdf with\n"
     "a page per view (--notes: its title and speaker's note below), a PNG per view, or an MP4 per view\n"
     "that plays; --embed: the lesson with every view's scene inside it (needs a display: xvfb-run)"},
    {"integrators", "", "the integrators with order, kind and when to use each"},
    {"accuracy",
     "SCENE [--integrators a,b,...] [--tolerances 1e-3..1e-12] [--steps dt1,dt2,...] [--duration T]\n"
     "[--repeats N] [--reference-tol X] [--out plot.svg|png] [--csv FILE]",
     "work-precision: error, energy drift, CPU time, evaluations and steps per integrator and setting"},
    {"help", "[COMMAND]", "this overview, or the usage of COMMAND (also: lagrangelab COMMAND --help)"},
    {"version", "", "the program's version, `lagrangelab X.Y.Z` (also: lagrangelab --version)"},
}};

const CommandText* find(const std::string& name) {
    for (const CommandText& c : commands)
        if (name == c.name) return &c;
    return nullptr;
}

// "name synopsis", its continuation lines aligned under the first argument when the
// first line starts `column` characters in; column < 0: on one line.
std::string synopsis(const CommandText& c, int column) {
    const std::string name = c.name;
    std::string s = name + (*c.synopsis ? " " : "");
    for (const char* p = c.synopsis; *p; ++p)
        s += *p != '\n' ? std::string(1, *p) : column < 0 ? " " : "\n" + std::string(column + name.size() + 1, ' ');
    return s;
}

// Every line of text, indented by `indent`.
std::string indented(const std::string& text, const std::string& indent) {
    std::string out = indent;
    for (char ch : text) {
        out += ch;
        if (ch == '\n') out += indent;
    }
    return out + "\n";
}

}  // namespace

const char* projectVersion() { return LL_VERSION; }

std::string overviewUsage() {
    std::string s = "usage: lagrangelab <command> [arguments]\n       lagrangelab --version\n"
                    "       lagrangelab [SCENE] [--screenshot FILE.png [--play SECONDS] [--step N] [--teach q1,q2,...]] [--size WxH]\n"
                    "           the window (default scene: examples/double_pendulum.json; 1280x800 unless --size);\n"
                    "           with --screenshot it plays, shows a derivation step or poses the robot (--teach: one\n"
                    "           value per joint, radians or metres), saves the whole window and exits;\n"
                    "           [--select ENTRY] [--pick-link I] [--at T] [--tab NAME]\n"
                    "           [--joint J] [--derivation typeset|text|entries|exercise] picture a picked entry or\n"
                    "           link, a time, the Torques or Properties tab, an exercise's answers judged; --present\n"
                    "           starts in presentation mode (full screen, or\n"
                    "           --size with --screenshot); --dh-step I,K the DH step-through at joint I after K of its\n"
                    "           four elementary motions, --dh-dimensions every DH parameter drawn on the robot,\n"
                    "           --dh-from-axes I,K the DH frames found from the joint axes: frame I after K of\n"
                    "           its rules (z, origin, x, y; 0,0 the axes alone); --tracking error|torque|lyapunov|rate\n"
                    "           the Tracking tab of a robot with a controller; --view FILE[#NAME] opens a saved view\n"
                    "           (a view file, a lesson's view by name or number, a scene's named view) and\n"
                    "           --save-view FILE.json writes the view the options set up (docs/user/views-and-lessons.md)\n"
                    "\ncommands:\n";
    for (const CommandText& c : commands) s += "  " + synopsis(c, 2) + "\n" + indented(c.summary, "      ");
    return s + "\nexit codes: 0 success, 2 bad input, 3 simulation stopped early\n";
}

std::string commandUsage(const std::string& command) {
    const CommandText* c = find(command);
    if (!c) return "";
    const std::string usage = "usage: lagrangelab ";
    return usage + synopsis(*c, static_cast<int>(usage.size())) + "\n\n" + indented(c->summary, "  ");
}

UsageMessage usageLine(const std::string& command) { return usageMessage(UsageId::Usage, synopsisLine(command)); }

std::string synopsisLine(const std::string& command) {
    const CommandText* c = find(command);
    return c ? synopsis(*c, -1) : command;
}

std::string commandNames() {
    std::string names;
    for (const CommandText& c : commands) names += (names.empty() ? "" : ", ") + std::string(c.name);
    return names;
}

}  // namespace ll::cli
