#pragma once
// GiNaC → display tree (core/present/display_tree.hpp): walks an expression once and
// builds the tree every front end renders. How names read is symbol_names.hpp's, how
// numbers read number_spelling.hpp's, the order of terms and factors term_order.hpp's;
// this file only puts them together. It never expands and never regroups: how an item is
// shaped for a reader comes before (textbook_form.hpp).
// Must be called with the GiNaC lock held (core/symbolic/ginac_lock.hpp); the tree it
// returns is plain data.
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <ginac/ginac.h>

#include "core/present/display_tree.hpp"
#include "core/present/number_spelling.hpp"
#include "core/present/symbol_names.hpp"
#include "core/present/term_order.hpp"

namespace ll::present {

struct DisplayOptions {
    // The coordinates by index and whether c<i>, s<i> are the trig shorthand (symbol_names.hpp).
    NameRules names;
    // Symbols drawn as given (the structured form's named quantities: Jx2_4 as
    // J_{P2,x}^{(4)}), by GiNaC name; any other symbol by the naming rules.
    std::shared_ptr<const std::map<std::string, DisplayPtr>> givenSymbols;
    // Numbers spelled as number_spelling.hpp's NumberSpelling reads them (a scene's
    // decimals as decimals, `typedDecimals` the values the scene typed as decimals); else
    // as GiNaC holds them (fractions stay fractions).
    bool readableNumbers = false;
    std::vector<GiNaC::numeric> typedDecimals;
    bool allDigits = false;  // readable numbers with every digit (NumberSpelling's allDigits)
    // Only for pages: a sum of more than maxTypesetTerms terms is built already cut as the
    // typesetter cuts it (its first keptTypesetTerms terms in display order and "⋯ (N more
    // terms)"). Every term is still ordered; the others are never built, which for the
    // expanded Panda's C and equations is most of them.
    bool cutLongSums = false;
};

// Builds expressions with one set of options: a scalar, a GiNaC::matrix (Matrix node) or
// a relational (Equation node).
class DisplayBuilder {
public:
    explicit DisplayBuilder(DisplayOptions options);
    ~DisplayBuilder();
    DisplayBuilder(const DisplayBuilder&) = delete;
    DisplayBuilder& operator=(const DisplayBuilder&) = delete;
    DisplayPtr operator()(const GiNaC::ex& e);

private:
    struct Term;
    struct Product;
    struct Symbol;
    struct Factor;
    DisplayPtr node(const GiNaC::ex& e);
    DisplayPtr number(const GiNaC::numeric& n, bool standalone = false) const;
    bool decimal(const GiNaC::numeric& n) const;
    DisplayPtr atom(const GiNaC::ex& e);
    DisplayPtr sum(const GiNaC::ex& e, bool negate);
    const std::vector<Term>& orderedTerms(const GiNaC::ex& e);
    Product product(const GiNaC::ex& e);
    DisplayPtr productNode(const GiNaC::numeric& coefficient, const Product& p);
    DisplayPtr factorNode(const Factor& f);
    FactorKey factorKey(const Factor& f);
    Symbol& symbol(const GiNaC::symbol& s);
    void addToKey(const GiNaC::ex& e, TermKey& key);

    DisplayOptions options_;
    NumberSpelling numbers_;
    // Each symbol's meaning and node, made once per builder: names repeat in every term.
    std::unordered_map<std::string, std::unique_ptr<Symbol>> symbols_;
    // The one memo of ordered sums, by GiNaC object (held, so its address stays its own):
    // a sum factor is ordered to know its sign, for its sort key and again when shown, and
    // a document shows the same shaped sums again (the expanded C in the equations of
    // motion and in JSON's results), whose trees are then shared. By object, not by
    // value: GiNaC's equality has 9/16 == 0.5625, and the two read differently.
    std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, std::vector<Term>>> sums_;
};

// One expression, its own builder.
DisplayPtr buildDisplay(const GiNaC::ex& e, const DisplayOptions& options);

}  // namespace ll::present
