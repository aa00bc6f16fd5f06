#pragma once
// The exact GiNaC class of an expression in one virtual call and a few pointer
// comparisons. GiNaC's is_a<T> is a dynamic_cast, and a failed cast across libginac's
// boundary compares type names with strcmp: in the numeric walks over thousands of
// named quantities that was an eighth of the Panda's structured derivation.
// Call with the GiNaC lock held.
#include <ginac/ginac.h>

namespace ll::symbolic {

enum class GinacKind { Numeric, Symbol, Constant, Add, Mul, Power, Function, Other };

inline GinacKind ginacKind(const GiNaC::ex& e) {
    const GiNaC::basic& b = GiNaC::ex_to<GiNaC::basic>(e);
    const GiNaC::registered_class_info* c = &b.get_class_info();
    if (c == &GiNaC::mul::get_class_info_static()) return GinacKind::Mul;
    if (c == &GiNaC::symbol::get_class_info_static()) return GinacKind::Symbol;
    if (c == &GiNaC::add::get_class_info_static()) return GinacKind::Add;
    if (c == &GiNaC::numeric::get_class_info_static()) return GinacKind::Numeric;
    if (c == &GiNaC::power::get_class_info_static()) return GinacKind::Power;
    if (c == &GiNaC::function::get_class_info_static()) return GinacKind::Function;
    if (c == &GiNaC::constant::get_class_info_static()) return GinacKind::Constant;
    // Subclasses, as is_a sees them: realsymbol, possymbol; fderivative.
    if (GiNaC::is_a<GiNaC::symbol>(b)) return GinacKind::Symbol;
    return GiNaC::is_a<GiNaC::function>(b) ? GinacKind::Function : GinacKind::Other;
}

// Whether b is GiNaC's one shared 1 (ex(1) is it): products and sums hold it as the
// exponent or coefficient of most factors and terms, so a pointer compared answers
// "is it 1?" without cln for most numbers.
inline bool isSharedOne(const GiNaC::basic& b) {
    static const GiNaC::basic* const one = &GiNaC::ex_to<GiNaC::basic>(GiNaC::ex(1));
    return &b == one;
}

// is_a<T>(e) for the classes above (T's subclasses included), without a dynamic_cast.
inline bool isKind(const GiNaC::ex& e, GinacKind kind) { return ginacKind(e) == kind; }

}  // namespace ll::symbolic
