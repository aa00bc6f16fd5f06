#pragma once
// Writing a simulated trajectory: CSV (one row per sample: t, q1..qn, qd1..qdn,
// Ekin, Epot, E, W) or JSON (the same columns as arrays, plus the run's statistics;
// for a fixed-step method also its step grid and how many samples were interpolated).
#include <ostream>
#include <string>

#include "core/simulation/trajectory.hpp"

namespace ll {

void writeTrajectoryCsv(const Trajectory& trajectory, std::ostream& out);
void writeTrajectoryJson(const SimulationResult& result, std::ostream& out);

// Chooses the format by extension (.csv or .json) and writes atomically
// (saveFileAtomically, no .bak). Throws std::runtime_error naming the path.
void saveTrajectory(const SimulationResult& result, const std::string& path);

}  // namespace ll
