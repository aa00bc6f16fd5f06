#pragma once
// A student's answer read as the student wrote it: "2 a1 lc2 cos(q2)", "m2*a1*ℓc2*c2",
// "½ I₁ θ̇₁²", "s12", "sin^2 q2", "pi/2". What a hand derivation uses is understood: the
// scene's parameter names, q1 or θ1 or theta1, qd1 or q̇1 or dq1 or qdot1, the shorthands
// c2, s12, c23 (cos q2, sin(q1 + q2), …), π or pi, ^ or **, superscripts (², ³),
// subscripts (₁), ½, a product written without '*' where that is unambiguous (a run of
// names written together, "a1lc2", is split when only one split gives known names), a
// function without parentheses (cos q2), and one '=' (an equation, read as left − right).
// Numbers are exact: 9.81 is 981/100. Anything else stops the reading with the character
// where it went wrong and what was expected there (AnswerUnreadable). A whole matrix or
// vector is typed in brackets, rows split by ';' (or as a list of bracketed rows).
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/model/message.hpp"

namespace ll::symbolic {

// Everything an answer may name. Built from a derivation (core/pipeline/answer_key.cpp).
struct AnswerVocabulary {
    std::map<std::string, GiNaC::ex> names;    // parameters and every other name as the scene spells it
    std::vector<GiNaC::symbol> q, qd, qdd;     // the coordinates, 1-based in what a student types
    std::vector<std::string> coordinateNames;  // a typed Lagrangian's names (x, theta1); empty for a robot
    bool robot = true;                         // q1, θ1, c12 shorthands apply
};

class AnswerUnreadable : public std::runtime_error {
public:
    AnswerUnreadable(Message message, std::size_t position, std::vector<std::string> closest = {}, bool unknownName = false);
    const Message& message() const { return message_; }
    std::size_t position() const { return position_; }                    // 1-based, in characters of what was typed
    const std::vector<std::string>& closest() const { return closest_; }  // for an unknown name: the nearest known
    bool unknownName() const { return unknownName_; }

private:
    Message message_;
    std::size_t position_;
    std::vector<std::string> closest_;
    bool unknownName_;
};

struct ReadAnswer {
    GiNaC::ex value;  // cos and sin as functions (c12 → cos(q1 + q2)); an equation as left − right
    bool equation = false;
    // A matrix or vector typed whole, "[a, b; c, d]" or "[[a, b], [c, d]]" (a column:
    // "[a; b; c]"): its rows. Empty for one expression.
    std::vector<std::vector<GiNaC::ex>> rows;
};

// Throws AnswerUnreadable. Takes no lock: the caller holds the GiNaC lock.
ReadAnswer readAnswer(const std::string& text, const AnswerVocabulary& vocabulary);

// What the reader reads: the answer spelled in ASCII (θ₁ → theta1, q̇1 → q_dot1, ½ → (1/2),
// ² → ^2, − → -). Throws AnswerUnreadable for a character no formula has.
std::string plainSpelling(const std::string& text);

// The names closest to `name` (edit distance at most 2, nearest first, at most 3).
std::vector<std::string> closestNames(const std::string& name, const std::vector<std::string>& known);

}  // namespace ll::symbolic
