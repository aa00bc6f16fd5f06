#pragma once
// The displayed form of an expression, decided once (term order, grouping, factors,
// c12/s12 shorthand, q̇/q̈, Greek letters, subscripts) and rendered by every front end:
// Plain (re-parsable by GiNaC), Text (a terminal), LaTeX, and the QPainter typesetter of
// ui/math_typesetter. Because all of them walk the same tree they cannot disagree on
// which symbols stand where. Plain data: no GiNaC, safe to hand to any thread.
//
// Built from GiNaC by core/present/display_builder; rendered to strings here.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ll::present {

enum class DisplayKind {
    Symbol,    // a letter or name with subscript, superscript and dots (q̇1, ℓc2, T_2^0)
    Number,    // digits, a decimal, or mantissa·10^exponent
    Sum,       // terms with a sign each: a + b − c
    Product,   // factors side by side: 2 m2 a1 ℓc2 c2
    Fraction,  // children[0] over children[1]
    Power,     // children[0] to the children[1] (an exponent, usually a Number)
    Root,      // √children[0]
    Fence,     // (children[0]), |children[0]| or {children[0]}
    Function,  // upright name applied to children (cos(q1)); a Power of it prints sin²(q1)
    Matrix,    // rows of cells
    Equation,  // children[0] op children[1] (=, ≠, ≤ ...)
    List,      // {a, b}
    Raw,       // text as given in each style (GiNaC's own output for odd classes)
};

struct DisplayNode;
using DisplayPtr = std::shared_ptr<const DisplayNode>;

struct DisplayNode {
    DisplayKind kind = DisplayKind::Raw;
    // Raw made by displayMoreTerms: the N of "⋯ (N more terms)"; 0 for any other node.
    // (Beside kind, in what would be padding.)
    std::uint32_t moreTerms = 0;
    // Symbol: the link (0-based) whose inertial parameter it is (m2, ℓc2, I2: what the
    // window draws in that link's colour); −1: none. (Beside kind too.)
    std::int16_t link = -1;
    // Symbol: the base as Text prints it (θ, ℓ, q, mass), as LaTeX (\theta, \ell,
    // \mathrm{mass}), and the Plain name (GiNaC's, or cos(q1+q2) for the c/s shorthand;
    // `name` is always GiNaC's name, the sort key's spelling).
    // Number: the digits or mantissa in text/latex/plain; `exponent` the power of ten.
    // Function: the name (sin; \sin; sin). Fence: text holds the opening character.
    // Equation: the relation in each style (=; =; ==). Raw: the text in each style.
    std::string text, latex, plain, name;
    // Symbol scripts: subscript as Text prints it (c2, xx1), as LaTeX (c2, xx,1,
    // \mathrm{cart}) and as the typesetter draws it (c2, xx,1, cart).
    std::string subText, subLatex, subShown, supText, supLatex;
    std::string exponent;                       // Number: mantissa·10^exponent when not empty
    bool upright = false;                       // Symbol: a multi-letter word (\mathrm); Function: always
    bool subUpright = false;                    // Symbol: the subscript is a word (m_cart)
    int dots = 0;                               // Symbol: 1 velocity, 2 acceleration
    bool hat = false;                           // Symbol: an estimate (the controller's ĝ, b̂12)
    std::vector<bool> negative;                 // Sum: the sign of each term
    std::vector<DisplayPtr> children;           // see the kinds
    std::vector<std::vector<DisplayPtr>> rows;  // Matrix
};

enum class DisplayStyle { Plain, Text, Latex };

// Text and Plain precedence, for parentheses: Sum 0, Product 1, Power 2, Atom 3.
int displayPrecedence(const DisplayNode& node);

// One line (a Text matrix takes several, its columns aligned; Plain [[a,b],[c,d]];
// LaTeX \begin{bmatrix}). Plain with `keyNames` writes the c/s shorthand by name: the
// spelling the term order compares.
std::string renderDisplay(const DisplayNode& node, DisplayStyle style, bool keyNames = false);

// A Text matrix with columns padded to their widest entry costs as much space as the
// widest entry times the rows; beyond this many characters per row a Text matrix is
// listed entry by entry instead (b11 = …), which is what a reader can follow anyway.
inline constexpr std::size_t maxTextMatrixRow = 160;

// Typeset pages (ui/math_typesetter's layoutItem) show a sum of more than this many terms,
// at any depth, as its first two thirds of that and "⋯ (N more terms)": nobody reads an
// entry of thousands of terms on a page. The text and JSON formats keep every term.
inline constexpr std::size_t maxTypesetTerms = 90;
// How many terms such a cut sum keeps, and the node that stands for the rest.
inline constexpr std::size_t keptTypesetTerms = maxTypesetTerms * 2 / 3;
DisplayPtr displayMoreTerms(std::size_t count);
// The N of such a node; 0 for any other node.
std::size_t moreTermsCount(const DisplayNode& node);

// Whether the node is the number 0 (a matrix listed entry by entry leaves those out).
bool isZeroNumber(const DisplayNode& node);
// Whether a Matrix node has a zero entry.
bool hasZeroEntry(const DisplayNode& matrix);

// Constructors.
DisplayPtr displayNumber(std::string text, std::string latex, std::string plain, std::string exponent = {});
DisplayPtr displayNode(DisplayKind kind, std::vector<DisplayPtr> children);
DisplayPtr displayRaw(std::string text, std::string latex, std::string plain);
// lhs = rhs as one node.
DisplayPtr displayEquation(DisplayPtr lhs, DisplayPtr rhs);
// −magnitude: a Sum of one negative term.
DisplayPtr displayNegated(DisplayPtr magnitude);
// Terms a + b − c joined in the given order; each part a Sum (its signs kept) or a term.
// Parts cut for pages ("⋯ (N more terms)" last) are joined and cut again as one sum.
DisplayPtr displaySumOf(const std::vector<DisplayPtr>& parts);

// The symbols and numbers of a tree in reading order, as Text spells them: what the
// Text and LaTeX renderings of the same tree both show (tests compare it).
void displayLeaves(const DisplayNode& node, std::vector<std::string>& out);

}  // namespace ll::present
