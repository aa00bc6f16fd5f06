#include "ui/document/lab_report.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/io/atomic_file.hpp"
#include "core/io/trajectory_file.hpp"
#include "ui/document/animation_export.hpp"
#include "ui/paint/derivation_pages.hpp"
#include "ui/paint/ffmpeg_encoder.hpp"
#include "ui/paint/plot_svg.hpp"

namespace ll::ui {
namespace fs = std::filesystem;

std::vector<std::string> writeLabReport(const LabReportInput& in, const std::string& dirPath, const std::function<void(double)>& progress,
                                        const std::atomic<bool>* cancel) {
    const fs::path dir(dirPath);
    std::error_code error;
    fs::create_directories(dir, error);
    if (!fs::is_directory(dir)) throw std::runtime_error(dirPath + ": cannot make the folder (" + error.message() + ")");
    const auto step = [&](double f) {
        if (cancel && cancel->load()) throw ExportCancelled();
        if (progress) progress(f);
    };
    const Trajectory& tr = in.simulation.trajectory;
    std::vector<std::string> files;

    step(0.0);
    if (in.display) {
        std::string reason;
        if (!writePdf(*in.display, QString::fromStdString((dir / "derivation.pdf").string()), reason))
            throw std::runtime_error((dir / "derivation.pdf").string() + ": " + reason);
        files.push_back("derivation.pdf");
    }
    step(0.3);

    const std::vector<std::string> units = coordinateUnits(in.scene);
    saveFileAtomically((dir / "trajectory.csv").string(), [&](std::ostream& out) { writeTrajectoryCsv(tr, out, {}, &units); },
                       Backup::None);
    files.push_back("trajectory.csv");

    std::vector<PlotCurve> energy{{"E_kin", QColor(34, 139, 34), tr.Ekin},
                                  {"E_pot", QColor(30, 90, 200), tr.Epot},
                                  {"E", QColor(128, 0, 160), tr.E}};
    if (hasNonConservativeForces(in.scene)) energy.push_back({"W", QColor(200, 40, 40), tr.work});
    writePlotSvg((dir / "energy.svg").string(), QString::fromStdString(in.scene.name), "energy [J]", tr.t, energy);
    files.push_back("energy.svg");
    std::vector<PlotCurve> joints;
    const std::set<std::string> distinct(units.begin(), units.end());
    for (int i = 0; i < tr.n; ++i) {
        PlotCurve c{QString::fromStdString(tr.coordinateName(i) + (units[static_cast<std::size_t>(i)].empty() || distinct.size() == 1
                                                                       ? ""
                                                                       : " [" + units[static_cast<std::size_t>(i)] + "]")),
                    QColor::fromHsvF(std::fmod(0.6 + 0.17 * i, 1.0), 0.75, 0.8),
                    {}};
        c.values.reserve(tr.size());
        for (const Eigen::VectorXd& q : tr.q) c.values.push_back(q[i]);
        joints.push_back(std::move(c));
    }
    const QString axis = distinct.size() == 1 && !units.front().empty() ? QString("q [%1]").arg(QString::fromStdString(units.front()))
                         : distinct.size() == 1                         ? QString("q")
                                                                        : QString("q [rad or m]");
    writePlotSvg((dir / "joints.svg").string(), QString::fromStdString(in.scene.name), axis, tr.t, joints);
    files.push_back("joints.svg");

    const std::string sceneName = in.sceneFileName.empty() ? "scene.json" : fs::path(in.sceneFileName).filename().string();
    saveFileAtomically((dir / sceneName).string(), in.sceneText, Backup::None);
    files.push_back(sceneName);
    step(0.35);

    ExportSettings slide;
    const bool video = FfmpegEncoder::available();
    slide.out = (dir / (video ? "slide.mp4" : "slide.png")).string();
    slide.kind = video ? OutputKind::Mp4 : OutputKind::Still;
    slide.duration = tr.t.empty() ? 0 : tr.t.back() - tr.t.front();
    slide.composite = true;
    if (in.display) {
        if (const present::DisplayStep* equations = in.display->step(8))
            slide.step = std::make_shared<const present::DisplayStep>(*equations);
        slide.language = in.display->language;
    }
    exportAnimation(
        in.scene, tr, slide, [&](double f) { step(0.35 + 0.6 * f); }, cancel);
    files.push_back(fs::path(slide.out).filename().string());

    // The index: what each file is, and the run that made them.
    const auto& stats = in.simulation.stats;
    double drift = 0;
    for (std::size_t k = 0; k < tr.size(); ++k) drift = std::max(drift, std::abs(tr.E[k] - tr.E.front() - tr.work[k]));
    std::ostringstream md;
    md << "# Lab report: " << in.scene.name << "\n\n";
    md << "Made by LagrangeLab from `" << sceneName << "`: " << tr.n << " coordinate" << (tr.n == 1 ? "" : "s") << ", " << slide.duration
       << " s simulated with " << stats.integrator << " (" << stats.steps << " steps); the energy balance E(t) − E(0) = W(t) holds to "
       << drift << " J at worst.\n\n";
    md << "| File | What it holds |\n|---|---|\n";
    const auto describe = [&](const std::string& f) -> std::string {
        if (f == "derivation.pdf") return "The derivation step by step as the course notes make it, typeset.";
        if (f == "trajectory.csv")
            return "The run: one row per sample, t [s], the coordinates, their velocities, E_kin, E_pot, E and W [J]; units in the header.";
        if (f == "energy.svg")
            return "Kinetic, potential and total energy over time (and W, the work of friction and inputs, when the scene has them).";
        if (f == "joints.svg") return "The coordinates over time.";
        if (f == sceneName) return "The scene file as given: open it in LagrangeLab to run it again.";
        if (f == "slide.mp4")
            return "One slide: the 3D view beside the equations of motion and the energy plot with a moving cursor, 1280×720.";
        if (f == "slide.png")
            return "One slide at t = 0 (ffmpeg was not installed, so no video): the 3D view, the equations of motion, the energy plot.";
        return "";
    };
    for (const std::string& f : files) md << "| [" << f << "](" << f << ") | " << describe(f) << " |\n";
    saveFileAtomically((dir / "index.md").string(), md.str(), Backup::None);
    files.push_back("index.md");
    step(1.0);
    return files;
}

}  // namespace ll::ui
