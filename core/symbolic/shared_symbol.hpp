#pragma once
// A GiNaC symbol made once on the heap, held as an expression. GiNaC copies a symbol
// *value* (GiNaC::symbol x("x")) onto the heap every time it becomes part of an
// expression: an allocation per use, and as many objects as uses. A shared symbol is one
// object that every expression using it points to, so it costs nothing to use.
// Call with the GiNaC lock held.
#include <string>

#include <ginac/ginac.h>

namespace ll::symbolic {

inline GiNaC::ex sharedSymbol(const std::string& name) { return GiNaC::dynallocate<GiNaC::symbol>(name); }

// The symbol a sharedSymbol holds: converting it back to an expression shares the
// object (it is on the heap), where a copy of the value would be duplicated again.
inline const GiNaC::symbol& symbolOf(const GiNaC::ex& shared) { return GiNaC::ex_to<GiNaC::symbol>(shared); }

}  // namespace ll::symbolic
