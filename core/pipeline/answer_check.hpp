#pragma once
// A student's own answer for one entry of a derivation (b11, c121, g2, T_2^0(1,4), p_c2(1),
// E_kin, a typed Lagrangian's dL/dtheta1_dot, equation 1), checked exactly against the
// derivation and, when wrong, explained from the robot's structure: which link's part is
// wrong, which kind of term, a sign or a factor, a swapped Christoffel index, the other DH
// convention, a length where a centre-of-mass distance belongs, the units, the coordinates.
//
//   auto key = AnswerKey::build(scene);                 // derives once (GiNaC, locked)
//   AnswerCheck c = key->check({"b11", "I1 + m1 lc1^2 + …"});
//
// Equal means equal as functions (core/symbolic/function_identity.hpp), never "a
// simplification found zero". The key is immutable after build; check() takes the GiNaC
// lock, so keys may be used from any thread. What comes back is plain data: the verdict,
// what was read, and the hints as messages (core/model/messages/answer.def) for the
// reader's language.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/model/message.hpp"
#include "core/model/scene.hpp"
#include "core/present/hidden_answers.hpp"
#include "core/symbolic/symbolic_robot.hpp"

namespace ll {

enum class AnswerVerdict { Right, Wrong, Unreadable };

// The kinds of slip the feedback names (their JSON names: answerErrorKindName).
enum class AnswerErrorKind {
    Factor,            // a constant factor (½, 2)
    Sign,              // only the sign
    Link,              // a link's part (its mass and inertia terms) is wrong
    Steiner,           // a parallel-axis term missing or counted twice
    Rotation,          // an inertia tensor not rotated into the base frame
    Length,            // a link length where a centre-of-mass distance belongs, or the reverse
    ChristoffelIndex,  // Christoffel indices or signs mixed up
    Dimension,         // a term whose units differ from the entry's
    Coordinates,       // depends on other coordinates (or velocities) than the right one
    Convention,        // right for the other DH convention
    UnknownSymbol,     // a name the scene does not know
    HomePose,          // right at q = 0 only
    Translational,     // in a link's part, the m v_cᵀv_c term is wrong
    RotationalTerm,    // in a link's part, the ωᵀIω term is wrong
};
const char* answerErrorKindName(AnswerErrorKind kind);
const char* answerVerdictName(AnswerVerdict verdict);

struct AnswerRequest {
    std::string entry;    // as typed: b11, B12, c_121, g2, T2(1,4), p_c2(1), E_kin, dL/dx_dot, equation1
    std::string answer;   // as the student writes it (core/symbolic/answer_reader.hpp)
    bool reveal = false;  // also give the right answer
};

struct AnswerCheck {
    std::string entry;  // the entry's id as the key lists it ("b11"); the request's when unknown
    AnswerVerdict verdict = AnswerVerdict::Unreadable;
    std::string readAs;               // the answer as read, printed as the derivation prints (text); empty when unreadable
    std::string readAsLatex;          // the same in LaTeX
    bool writtenDifferently = false;  // right, but not the derivation's form term by term
    bool withValues = false;          // right with numbers where the derivation has parameters
    bool sixtyDigits = false;         // compared to 60 digits, not exactly (√ of a symbol, …)
    int points = 0;                   // the points compared
    Message problem;                  // unreadable or unknown entry: what and where
    std::size_t position = 0;         // unreadable: the character (1-based); 0: not a reading error
    std::vector<Message> hints;       // one to three sentences for a wrong answer
    std::vector<AnswerErrorKind> kinds;
    std::vector<int> links;   // 1-based: the links whose part is wrong
    std::string rightAnswer;  // with reveal: the right answer (text)
};

class AnswerKey {
public:
    // Derives the scene (robot or typed Lagrangian) in `mode`. Throws InputError as
    // deriving does.
    static std::shared_ptr<const AnswerKey> build(const Scene& scene, symbolic::ParameterMode mode = symbolic::ParameterMode::Parametric);
    ~AnswerKey();

    AnswerCheck check(const AnswerRequest& request) const;

    // Every entry's id, in the derivation's order.
    const std::vector<std::string>& entries() const;
    // The id an entry name typed by a student means, "" when none.
    std::string entryId(const std::string& typed) const;
    // The right answer of an entry in text (empty for an unknown id).
    std::string rightAnswer(const std::string& id) const;
    // Where an entry stands in the derivation (core/present/hidden_answers.hpp); step −1
    // for an unknown id and for what the derivation does not show (Christoffel symbols).
    present::EntryPlace place(const std::string& id) const;
    // The entries of step `step` worth asking a student for, in the derivation's order: not
    // zero, not a constant of a step's matrix (the 1 of a transform's last row), b_ij only
    // for i ≤ j (B is symmetric), no Christoffel symbols (C asks for them).
    std::vector<std::string> practiceEntries(int step) const;
    // The entries a name typed or picked stands for: one entry (b11), or every entry of a
    // matrix or vector (B, p_c2, T_2^0); empty when it names none.
    std::vector<std::string> entriesOf(const std::string& typed) const;

    struct Data;  // core/pipeline/answer_key_data.hpp
    // The key's GiNaC side, for what builds on it (exercise generators, the tests' wrong
    // answers); use it with the GiNaC lock held.
    const Data& data() const { return *data_; }

private:
    AnswerKey();
    std::unique_ptr<Data> data_;
};

}  // namespace ll
