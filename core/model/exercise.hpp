#pragma once
// A student's work on a scene's derivation: the scene file's "exercise" section. The
// entries to answer, named as the answer key names them (b11, g2, T_2^0(1,4), E_kin), and
// the answers typed so far, as typed (core/symbolic/answer_reader.hpp reads them). Saved
// with the scene, so the window's exercise mode and its recovery copy keep an evening's
// work, and `lagrangelab check-answer SCENE` checks the answers a scene holds.
#include <string>
#include <utility>
#include <vector>

namespace ll {

struct Exercise {
    std::vector<std::string> entries;                          // in the order they are asked
    std::vector<std::pair<std::string, std::string>> answers;  // entry → answer, in file order

    bool empty() const { return entries.empty() && answers.empty(); }
    // The answer typed for `entry` ("" when none).
    const std::string& answer(const std::string& entry) const {
        static const std::string none;
        for (const auto& [e, a] : answers)
            if (e == entry) return a;
        return none;
    }
};

}  // namespace ll
