#pragma once
// A derivation as JSON: the system, the parameter mode, the form when one was chosen,
// the coordinates, every step's items with name, LaTeX, text and a re-parsable Plain
// `expr` (a matrix as rows of entries, a column as a list), then B, C, g, Q, Ekin, Epot
// again at the top level, the actuated coordinates and the warnings. Written in the
// layout of nlohmann's dump(2) (json_writer.hpp). No GiNaC: any thread.
#include <string>
#include <vector>

#include "core/present/display_document.hpp"

namespace ll::present {

// What JSON gives at its top level beside the steps, whatever steps are shown.
struct ModelSummary {
    std::string mode;  // "parameters", "numeric" or "symbolic"
    DisplayPtr B, C, g, Q, Ekin, Epot;
    std::vector<std::string> actuated;  // coordinate names
    bool underactuated = false;
    std::vector<std::string> warnings;
};

std::string jsonDocument(const DisplayDocument& document, const ModelSummary& model);

}  // namespace ll::present
