#pragma once
// The one sentence that says which coordinates have an input, used by the derivation
// (step 8), `derive` and `simulate`:
//   "inputs on q1, q2 (fully actuated)"
//   "inputs on theta2 (underactuated: m = 1 < n = 2)"
//   "no inputs (underactuated: m = 0 < n = 2)"
#include <string>
#include <vector>

#include "core/model/message.hpp"

namespace ll {

// The sentence's words: the English of their message ids (core/model/messages/document.def)
// unless a reader's language gives others (core/present/localized_document.cpp).
struct ActuationWords {
    std::string noInputs = englishWords(MessageId::ActuationNoInputs), inputsOn = englishWords(MessageId::ActuationInputsOn),
                underactuated = englishWords(MessageId::ActuationUnderactuated),
                fullyActuated = englishWords(MessageId::ActuationFullyActuated);
};

// actuated: 0-based coordinates with an input; coordinateNames: all n coordinates.
std::string actuationText(const std::vector<int>& actuated, const std::vector<std::string>& coordinateNames,
                          const ActuationWords& words = {});

}  // namespace ll
