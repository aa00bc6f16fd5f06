#pragma once
// The lab-report bundle (`lagrangelab report SCENE --out DIR`, File → Export → Lab
// report): everything a student hands in about one scene, in one folder —
//   derivation.pdf   the derivation typeset (ui/derivation_pages)
//   trajectory.csv   the run, one row per sample, every column's unit in the header
//   energy.svg       E_kin, E_pot, E (and W) over time, vector
//   joints.svg       q_i over time, vector
//   the scene file   as given, under its own name
//   slide.mp4        the composite slide video, 1280×720 (ui/composite_frame), when
//                    ffmpeg is there (else slide.png, the still at t = 0)
//   index.md         what each file is, the run's integrator, tolerances and energy drift
// Needs a QGuiApplication (fonts).
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/model/scene.hpp"
#include "core/present/display_document.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll::ui {

struct LabReportInput {
    Scene scene;                // as simulated
    std::string sceneFileName;  // "puma560.json": the copy's name
    std::string sceneText;      // the scene file's bytes
    SimulationResult simulation;
    std::shared_ptr<const present::DisplayDocument> display;  // the derivation, in the language shown
};

// Writes the bundle into `dir` (made when missing) and returns the files written, by
// name, in the index's order. Throws std::runtime_error naming the file that could not
// be written; ExportCancelled (ui/document/animation_export.hpp) when `cancel` was set.
std::vector<std::string> writeLabReport(const LabReportInput& input, const std::string& dir,
                                        const std::function<void(double)>& progress = {}, const std::atomic<bool>* cancel = nullptr);

}  // namespace ll::ui
