// Seeded mutation run (label `fuzz`): scenes from examples/ with a new user's mistakes
// (tests/scene_mutator.hpp: wrong types, NaN/inf/subnormal/huge numbers, deletions, key
// typos, broken expressions) through what `eval`, `derive` and `simulate` do, called
// in-process (the same core functions the commands call: loading, checkScene,
// evaluateScene, deriveDocument, prepareSimulation + simulate), and a sample through the
// real binary for exit codes and output files; then `render` with mutated options.
// The contract: bad input is InputError (exit 2) with short one-line messages each
// naming a field, a simulation that cannot go on is exit 3, nothing else is thrown, no
// non-finite number is ever a result, and an output file is whole or absent.
// LL_FUZZ_CASES overrides the number of scenes (default 10000).
#include "test_registry.hpp"
#include <QDir>
#include <QProcess>
#include <QTemporaryDir>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/scene_file.hpp"
#include "core/model/utf8_text.hpp"
#include "core/pipeline/scene_check.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "core/pipeline/scene_evaluation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/simulation/integrators.hpp"
#include "scene_mutator.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_mutation_fuzz {

using namespace ll;

namespace {

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    return content.str();
}

// What a failure says: the case, its mutations and the problem; the mutated scene is
// kept as mutation_failure.json in the working folder to reproduce it.
struct Failures {
    QStringList lines;
    void add(int index, const std::string& what, const std::string& text, const std::string& problem) {
        if (lines.isEmpty()) std::ofstream("mutation_failure.json") << text;
        if (lines.size() < 20)
            lines << QString("case %1 (%2): %3").arg(index).arg(QString::fromStdString(what), QString::fromStdString(validUtf8(problem)));
    }
};

// A refusal's messages: at least one error, each naming a field on one short line
// (`error: FIELD: what is wrong`, at most 200 bytes after the file's name), the why and
// the fix, if any, on one following `hint:` line.
std::string badDiagnostics(const std::vector<Diagnostic>& diagnostics) {
    if (!hasErrors(diagnostics)) return "refused without an error";
    for (const Diagnostic& d : diagnostics) {
        const std::string text = d.toString();
        std::string line = text.substr(0, text.find('\n'));
        if (const std::size_t file = line.find(".json: "); file != std::string::npos) line = "error: " + line.substr(file + 7);
        if (d.field.empty()) return "a message names no field: " + text;
        if (d.message.english().empty()) return "an empty message for " + d.field;
        if (d.message.english().find('\n') != std::string::npos || d.hint.english().find('\n') != std::string::npos)
            return "a message of several lines: " + text;
        if (line.size() > 200) return "a first line of " + std::to_string(line.size()) + " bytes: " + line;
        if (d.hint.english().size() > 700)
            return "a hint of " + std::to_string(d.hint.english().size()) + " bytes: " + d.hint.english().substr(0, 200);
        if (!isValidUtf8(text)) return "a message that is not UTF-8";
    }
    return "";
}

bool allFinite(const SceneEvaluation& e) {
    return e.terms.B.allFinite() && e.terms.C.allFinite() && e.terms.g.allFinite() && e.terms.Q.allFinite() && e.qdd.allFinite() &&
           std::isfinite(e.terms.Ekin) && std::isfinite(e.terms.Epot);
}

bool allFinite(const Trajectory& t) {
    for (std::size_t k = 0; k < t.size(); ++k)
        if (!std::isfinite(t.t[k]) || !t.q[k].allFinite() || !t.qd[k].allFinite() || !std::isfinite(t.Ekin[k]) ||
            !std::isfinite(t.Epot[k]) || !std::isfinite(t.E[k]) || !std::isfinite(t.work[k]))
            return false;
    return true;
}

struct Counts {
    int cases = 0, refused = 0, loaded = 0, evaluated = 0, evalRefused = 0, derived = 0, deriveRefused = 0, simulated = 0,
        simulationStopped = 0, simulateRefused = 0;
};

// One mutated scene through load, check, eval (initial and a random state), derive on
// small robots and a short simulation. Returns "" or what broke the contract.
std::string runInProcess(const std::string& text, int index, std::mt19937& rng, Counts& counts) {
    Scene scene;
    try {
        scene = parseScene(text);
    } catch (const InputError& e) {
        ++counts.refused;
        return badDiagnostics(e.diagnostics());
    }
    const std::vector<Diagnostic> checked = checkScene(scene);
    if (hasErrors(checked)) {
        ++counts.refused;
        return badDiagnostics(checked);
    }
    ++counts.loaded;
    const int n = scene.dof();

    // eval at the initial state and at a random one (sometimes huge).
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double scale = rng() % 10 == 0 ? 1e200 : 3.0;
    Eigen::VectorXd q(n), qd(n);
    for (int i = 0; i < n; ++i) q[i] = scale * unit(rng), qd[i] = scale * unit(rng);
    for (const auto& [qs, qds] : {std::pair{scene.initial.q, scene.initial.qd}, std::pair{q, qd}}) {
        try {
            const SceneEvaluation e = evaluateScene(scene, qs, qds, 0.5);
            if (!allFinite(e)) return "eval returned a non-finite number";
            ++counts.evaluated;
        } catch (const InputError& e) {
            ++counts.evalRefused;
            if (std::string bad = badDiagnostics(e.diagnostics()); !bad.empty()) return "eval: " + bad;
        }
    }

    // derive on small systems, in a mode and format picked by the case.
    if (n <= 3 && index % 4 == 0) {
        DocumentRequest request;
        request.mode = static_cast<symbolic::ParameterMode>(rng() % 3);
        request.format = static_cast<present::DocumentFormat>(rng() % 3);
        try {
            const DerivedDocument d = deriveDocument(scene, request);
            if (d.document.empty() || !isValidUtf8(d.document)) return "derive gave an empty or non-UTF-8 document";
            if (request.format == present::DocumentFormat::Json) {
                const auto json = nlohmann::json::parse(d.document, nullptr, false);
                if (json.is_discarded()) return "derive --format json is not JSON";
            }
            ++counts.derived;
        } catch (const InputError& e) {
            ++counts.deriveRefused;
            if (std::string bad = badDiagnostics(e.diagnostics()); !bad.empty()) return "derive: " + bad;
        }
    }

    // a short simulation with the scene's integrator and tolerances.
    if (index % 3 == 0) {
        SimulationSettings settings = scene.simulation;
        settings.duration = std::min(settings.duration, 0.05);
        settings.outputRate = std::min(settings.outputRate, 200.0);
        // A mutated gain can make a controlled arm stiff where the stiffness monitor is slow
        // to see it (K_p = 1e15 on the 2R: 668,000 dopri5 steps first); the contract is the
        // same after 200,000 steps (a one-line stop), and 10,000 cases stay in the budget.
        settings.maxSteps = std::min(settings.maxSteps, 200'000L);
        const IntegratorInfo* integrator = findIntegrator(settings.integrator);
        if (integrator && !integrator->adaptive) settings.dt = std::max(settings.dt, settings.duration / 2000);
        try {
            const SimulationResult r = simulate(scene, settings);
            if (!allFinite(r.trajectory)) return "simulate recorded a non-finite number";
            if (r.status == SimulationStatus::Failed) {
                ++counts.simulationStopped;
                if (r.message.empty() || r.message.english().find('\n') != std::string::npos) return "a stop without a one-line reason";
            } else {
                ++counts.simulated;
            }
        } catch (const InputError& e) {
            ++counts.simulateRefused;
            if (std::string bad = badDiagnostics(e.diagnostics()); !bad.empty()) return "simulate: " + bad;
        }
    }
    return "";
}

struct Run {
    int exitCode = -1;
    QByteArray out, err;
};

Run runCli(const QStringList& args, const QString& workingDir) {
    QProcess p;
    p.setWorkingDirectory(workingDir);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("DISPLAY");
    p.setProcessEnvironment(env);
    p.start(LL_CLI, args);
    Run r;
    if (!p.waitForFinished(120000)) {  // a run that hangs is a failure too (exit -1)
        p.kill();
        p.waitForFinished();
        r.err = "did not finish in 120 s";
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// The CLI's contract on one run: exit 0, 2 or 3; on 2, every line of stderr is a short
// `warning:`/`error:` line and one error names a field (`error: FILE: field: …` or an
// option); no non-finite number in what it printed as a result.
std::string badCliRun(const Run& r, bool resultOnStdout) {
    if (r.exitCode != 0 && r.exitCode != 2 && r.exitCode != 3)
        return "exit " + std::to_string(r.exitCode) + ": " + r.err.right(300).toStdString();
    const QString err = QString::fromUtf8(r.err);
    if (!isValidUtf8(r.err.toStdString())) return "stderr is not UTF-8";
    if (r.exitCode == 2) {
        bool named = false;
        for (const QString& line : err.split('\n', Qt::SkipEmptyParts)) {
            if (!line.startsWith("error: ") && !line.startsWith("warning: ") && !line.startsWith("hint: ") && !line.startsWith("usage:") &&
                !line.startsWith(' ') && !line.startsWith("QStandardPaths"))
                return "an unexpected stderr line: " + line.left(200).toStdString();
            if (line.size() > 800) return "an error line of " + std::to_string(line.size()) + " characters";
            if (line.startsWith("error: ") && line.count(": ") >= 2) named = true;
            if (line.startsWith("error: --")) named = true;  // a command-line option is the field
        }
        if (!named) return "exit 2 naming no field: " + err.left(300).toStdString();
    }
    if (resultOnStdout) {
        static const QRegularExpression nonFinite("\\b(inf|nan|null)\\b", QRegularExpression::CaseInsensitiveOption);
        const QString out = QString::fromUtf8(r.out);
        if (nonFinite.match(out).hasMatch()) return "a non-finite result on stdout: " + out.left(300).toStdString();
    }
    return "";
}

// A folder holds `name` whole (CSV rows of equal width, finite) or nothing, and no
// temporary file.
std::string badOutputFile(const QString& folder, const QString& name) {
    const QStringList entries = QDir(folder).entryList(QDir::Files | QDir::NoDotAndDotDot);
    for (const QString& e : entries)
        if (e != name && e != "scene.json") return "a stray file is left: " + e.toStdString();
    if (!entries.contains(name)) return "";
    QFile f(QDir(folder).filePath(name));
    if (!f.open(QIODevice::ReadOnly)) return "cannot read the output";
    const QList<QByteArray> rows = f.readAll().split('\n');
    if (rows.isEmpty() || !rows.last().isEmpty()) return "the output does not end with a newline (half written?)";
    const int columns = rows.first().count(',');
    for (int i = 1; i + 1 < rows.size(); ++i) {
        if (rows[i].count(',') != columns) return "a row of another width (half written?)";
        if (rows[i].contains("inf") || rows[i].contains("nan")) return "a non-finite number in the output";
    }
    return "";
}

std::vector<std::filesystem::path> exampleFiles() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

class TestMutationFuzz : public QObject {
    Q_OBJECT
private slots:
    void mutatedScenesKeepTheContract() {
        const std::vector<std::filesystem::path> files = exampleFiles();
        QVERIFY(files.size() > 20);
        std::vector<std::string> originals;
        for (const auto& f : files) originals.push_back(readFile(f));
        const int cases = qEnvironmentVariableIsSet("LL_FUZZ_CASES") ? qEnvironmentVariableIntValue("LL_FUZZ_CASES") : 10000;
        const int cliEvery = 100;  // about 100 of the 10,000 also through the binary
        test::SceneMutator mutator(20261123);
        Counts counts;
        Failures failures;
        int cliRuns = 0;
        QTemporaryDir dir;
        for (int index = 0; index < cases; ++index) {
            const std::size_t file = index % originals.size();
            std::string what;
            const std::string text = mutator.mutate(originals[file], what);
            what = files[file].filename().string() + ": " + what;
            ++counts.cases;
            try {
                if (std::string problem = runInProcess(text, index, mutator.rng(), counts); !problem.empty())
                    failures.add(index, what, text, problem);
            } catch (const std::exception& e) {  // not InputError: the CLI would say exit 1 or worse
                failures.add(index, what, text, std::string("threw ") + typeid(e).name() + ": " + e.what());
            }
            if (index % cliEvery != 0) continue;

            // The same scene through the binary: eval, derive, or simulate to a file.
            const QString folder = dir.filePath(QString("case%1").arg(index));
            QDir().mkpath(folder);
            const QString scenePath = folder + "/scene.json";
            std::ofstream(scenePath.toStdString(), std::ios::binary) << text;
            int command = (index / cliEvery) % 3;
            if (command == 1) {  // derive on small systems only, as in-process (a 7-joint arm takes a minute)
                try {
                    if (parseScene(text).dof() > 3) command = 0;
                } catch (const InputError&) {
                }
            }
            Run r;
            std::string problem;
            if (command == 0) {
                r = runCli({"eval", scenePath}, folder);
                problem = badCliRun(r, true);
            } else if (command == 1) {
                r = runCli({"derive", scenePath, "--format", "json", "--numeric"}, folder);
                problem = badCliRun(r, false);
            } else {
                // --dt: a fixed step mutated to 1e-300 would take 20 million steps (the
                // in-process run clamps it the same way).
                r = runCli({"simulate", scenePath, "--duration", "0.05", "--dt", "0.001", "--out", folder + "/out.csv"}, folder);
                problem = badCliRun(r, false);
                if (problem.empty()) problem = badOutputFile(folder, "out.csv");
                if (problem.empty() && r.exitCode == 0 && !QFile::exists(folder + "/out.csv")) problem = "exit 0 without the file";
            }
            ++cliRuns;
            if (!problem.empty()) failures.add(index, what + " [cli]", text, problem);
        }
        qInfo("mutation fuzz: %d mutated scenes in-process (%d refused, %d loaded; eval %d answered, %d refused; "
              "derive %d, %d refused; simulate %d completed, %d stopped (exit 3), %d refused), %d through the CLI",
              counts.cases, counts.refused, counts.loaded, counts.evaluated, counts.evalRefused, counts.derived, counts.deriveRefused,
              counts.simulated, counts.simulationStopped, counts.simulateRefused, cliRuns);
        QVERIFY2(failures.lines.isEmpty(), qPrintable(failures.lines.join('\n')));
        // The run explores both sides of every check.
        QVERIFY(counts.refused > cases / 10);
        QVERIFY(counts.loaded > cases / 10);
        QVERIFY(counts.evalRefused > 0 && counts.derived > 0 && counts.simulated > 0);
    }

    // `render` with mutated options: each run exits 0, 2 or 3, names the option it
    // refuses, and leaves its output whole or absent.
    void mutatedRenderOptions() {
        const int runs = qEnvironmentVariableIsSet("LL_FUZZ_RENDERS") ? qEnvironmentVariableIntValue("LL_FUZZ_RENDERS") : 200;
        std::mt19937 rng(1123);
        const auto pick = [&](const std::vector<QString>& options) { return options[rng() % options.size()]; };
        const std::vector<QString> sizes = {"32x24", "0x0", "x", "64x", "-32x24", "33x24", "9000x10", "32x24x1", "1e3x2", "abc", ""};
        const std::vector<QString> numbers = {"0.1", "0", "-1", "nan", "inf", "1e-310", "1e308", "abc", "", "2", "0.05", "60"};
        const std::vector<QString> cameras = {"front", "iso", "0,90", "10,20,1e300", "nan,0", "spin", "1,2,3,4", ""};
        const std::vector<QString> overlays = {"none", "time,energy,name", "time,time", "energy,", "all", ""};
        const std::vector<QString> extensions = {"png", "gif", "mp4", "webm", "txt", "", "PNG"};
        const std::vector<QString> scenes = {"simple_pendulum.json", "planar_2r.json", "mass_spring_pair_lagrangian.json", "missing.json"};
        QTemporaryDir dir;
        int exits[4] = {0, 0, 0, 0};
        QStringList problems;
        for (int i = 0; i < runs; ++i) {
            const QString folder = dir.filePath(QString("render%1").arg(i));
            QDir().mkpath(folder);
            const QString extension = pick(extensions);
            const QString out = folder + "/out" + (extension.isEmpty() ? "" : "." + extension);
            // Start from a cheap valid still and mutate one to three options.
            QMap<QString, QString> options{{"--out", out},   {"--size", "32x24"}, {"--duration", "0.1"},
                                           {"--at", "0.05"}, {"--msaa", "0"},     {"--fps", "10"}};
            const int mutations = 1 + static_cast<int>(rng() % 3);
            for (int m = 0; m < mutations; ++m) {
                switch (rng() % 10) {
                    case 0: options["--size"] = pick(sizes); break;
                    case 1: options["--fps"] = pick(numbers); break;
                    case 2: options["--duration"] = pick(numbers); break;
                    case 3: options["--at"] = pick(numbers); break;
                    case 4: options["--camera"] = pick(cameras); break;
                    case 5: options["--overlay"] = pick(overlays); break;
                    case 6: options["--speed"] = pick(numbers); break;
                    case 7: options["--msaa"] = pick({"0", "2", "3", "-4", "x"}); break;
                    case 8: options[pick({"--trail", "--frames"})] = pick({"on", "off", "maybe", ""}); break;
                    default: options[pick({"--colour", "--sizes", "-at", "--"})] = "1"; break;
                }
            }
            // A video must not run long: keep durations and rates small unless mutated to junk.
            if (extension != "png" && extension != "PNG") options.remove("--at");
            QStringList args{"render", QString(LL_EXAMPLES_DIR) + "/" + pick(scenes)};
            for (auto it = options.begin(); it != options.end(); ++it) args << it.key() << it.value();
            const Run r = runCli(args, folder);
            std::string problem = badCliRun(r, false);
            // Only the target may be left, whole: a still or video that decodes is beyond
            // this test, a non-empty file of the asked name is what a rename leaves.
            for (const QString& e : QDir(folder).entryList(QDir::AllEntries | QDir::NoDotAndDotDot))
                if (folder + "/" + e != out) problem = "a stray file is left: " + e.toStdString();
            if (r.exitCode != 0 && QFileInfo(out).isFile()) problem = "a failed render left " + out.toStdString();
            if (r.exitCode == 0 && QFileInfo(out).isFile() && QFileInfo(out).size() == 0) problem = "an empty output";
            if (r.exitCode >= 0 && r.exitCode <= 3) ++exits[r.exitCode];
            if (!problem.empty() && problems.size() < 20) problems << args.mid(1).join(' ') + ": " + QString::fromStdString(problem);
        }
        qInfo("render option mutations: %d runs (exit 0: %d, 2: %d, 3: %d)", runs, exits[0], exits[2], exits[3]);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
        QVERIFY(exits[0] > 0 && exits[2] > runs / 4);
    }
};

LL_TEST_APPLESS_MAIN(TestMutationFuzz)

}  // namespace test_mutation_fuzz
#include "test_mutation_fuzz.moc"
