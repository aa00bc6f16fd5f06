#include "core/symbolic/named_definitions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/model/cancellation.hpp"
#include "core/symbolic/ginac_kind.hpp"
#include "core/symbolic/ginac_pairs.hpp"

namespace ll::symbolic {
namespace {

// Never named (SYMORO's rule): numbers, symbols and number·symbol.
bool isAtomic(const GiNaC::ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::constant>(e)) return true;
    return GiNaC::is_a<GiNaC::mul>(e) && e.nops() == 2 && GiNaC::is_a<GiNaC::numeric>(e.op(1)) && GiNaC::is_a<GiNaC::symbol>(e.op(0));
}

// Every symbol occurrence in e (through its pairs: ginac_pairs.hpp).
template <class Visit>
void forEachSymbol(const GiNaC::ex& e, Visit& visit) {
    auto symbols = [&visit](const GiNaC::ex& node, GinacKind kind) {
        if (kind == GinacKind::Symbol) visit(node);
        return false;
    };
    anyNode(e, symbols);
}

}  // namespace

NamedDefinitions::NamedDefinitions(const TrigContext& tc) : tc_(tc) {
    for (int k = 0; k < tc.size(); ++k) {
        coordinateOf_[tc.q(k)] = k;
        coordinateOf_[tc.c(k)] = k;
        coordinateOf_[tc.s(k)] = k;
    }
}

GiNaC::ex NamedDefinitions::name(const GiNaC::ex& e, const std::string& plain, const std::string& latex, const Message& meaning, int step,
                                 int link, const std::string& unit) {
    throwIfCancelled(cancel_);
    const GiNaC::ex value = tc_.reduce(e);
    if (value.is_zero() || isAtomic(value)) return value;
    if (const auto it = byValue_.find(value); it != byValue_.end()) return entries_[it->second].symbol;
    if (const auto it = byValue_.find((-value).expand()); it != byValue_.end()) return -entries_[it->second].symbol;
    NamedDefinition d{sharedSymbol(plain), plain, value, latex, meaning, step, link, unit, dependenciesOf(value), coordinatesOf(value)};
    const int index = size();
    byValue_.emplace(value, index);
    bySymbol_.emplace(d.symbol, index);
    entries_.push_back(std::move(d));
    unfolded_.emplace_back();
    isUnfolded_.push_back(false);
    return entries_.back().symbol;
}

int NamedDefinitions::indexOf(const GiNaC::ex& symbol) const {
    const auto it = bySymbol_.find(symbol);
    return it == bySymbol_.end() ? -1 : it->second;
}

std::uint64_t NamedDefinitions::coordinatesOf(const GiNaC::ex& e) const {
    std::uint64_t bits = 0;
    auto visit = [&](const GiNaC::ex& s) {
        if (const auto it = coordinateOf_.find(s); it != coordinateOf_.end()) bits |= std::uint64_t(1) << it->second;
        if (const int k = indexOf(s); k >= 0) bits |= entries_[k].coordinates;
    };
    forEachSymbol(e, visit);
    return bits;
}

std::vector<int> NamedDefinitions::dependenciesOf(const GiNaC::ex& e) const {
    std::vector<int> deps;
    auto visit = [&](const GiNaC::ex& s) {
        if (const int k = indexOf(s); k >= 0) deps.push_back(k);
    };
    forEachSymbol(e, visit);
    std::sort(deps.begin(), deps.end());
    deps.erase(std::unique(deps.begin(), deps.end()), deps.end());
    return deps;
}

std::vector<int> NamedDefinitions::coneOf(const GiNaC::ex& e) const {
    std::vector<bool> in(entries_.size(), false);
    std::vector<int> stack = dependenciesOf(e);
    while (!stack.empty()) {
        const int k = stack.back();
        stack.pop_back();
        if (in[k]) continue;
        in[k] = true;
        for (int d : entries_[k].dependencies) stack.push_back(d);
    }
    std::vector<int> cone;
    for (int k = 0; k < size(); ++k)
        if (in[k]) cone.push_back(k);
    return cone;
}

GiNaC::ex NamedDefinitions::unfold(const GiNaC::ex& e, const std::atomic<bool>* cancel) {
    GiNaC::exmap substitution;
    for (int k : coneOf(e)) {  // ascending: dependencies first
        if (!isUnfolded_[k]) {
            throwIfCancelled(cancel);
            throwIfCancelled(cancel_);
            GiNaC::exmap direct;
            for (int d : entries_[k].dependencies) direct[entries_[d].symbol] = unfolded_[d];
            unfolded_[k] = tc_.reduce(entries_[k].value.subs(direct, GiNaC::subs_options::no_pattern));
            isUnfolded_[k] = true;
        }
    }
    for (int k : dependenciesOf(e)) substitution[entries_[k].symbol] = unfolded_[k];
    return tc_.reduce(e.subs(substitution, GiNaC::subs_options::no_pattern));
}

namespace {

bool isOne(const GiNaC::numeric& x) {
    static const GiNaC::numeric one(1);  // made on first use: GiNaC is initialised by then
    return x.is_equal(one);
}

template <class Values>
double evaluate(const GiNaC::ex& e, const Values& values, bool absolute = false);

template <class Values>
double powerValue(const GiNaC::ex& base, const GiNaC::ex& exponent, const Values& values, bool absolute) {
    using namespace GiNaC;
    const double b = evaluate(base, values, absolute);
    if (ginacKind(exponent) == GinacKind::Numeric && ex_to<numeric>(exponent).is_integer())
        return std::pow(b, ex_to<numeric>(exponent).to_int());
    return std::pow(b, evaluate(exponent, values));
}

template <class Values>
double evaluate(const GiNaC::ex& e, const Values& values, bool absolute) {
    using namespace GiNaC;
    const auto sized = [absolute](double v) { return absolute ? std::abs(v) : v; };
    switch (ginacKind(e)) {
        case GinacKind::Numeric: return sized(ex_to<numeric>(e).to_double());
        case GinacKind::Symbol: {
            const auto it = values.find(e);
            if (it == values.end()) throw std::invalid_argument("no value for " + ex_to<symbol>(e).get_name());
            return sized(it->second);
        }
        case GinacKind::Constant: return sized(ex_to<numeric>(e.evalf()).to_double());
        // Sums and products read in place (ginac_pairs.hpp): op(k) would make each term
        // (rest·coefficient) and each power anew. The same operations in op()'s order.
        case GinacKind::Add: {
            const add& sum = ex_to<add>(e);
            double s = 0;
            for (const expair& term : GinacPairs::of(sum)) {
                const numeric& c = ex_to<numeric>(term.coeff);
                const double rest = evaluate(term.rest, values, absolute);
                s += isOne(c) ? rest : rest * sized(c.to_double());
            }
            const numeric& number = ex_to<numeric>(GinacPairs::number(sum));
            if (!number.is_zero()) s += sized(number.to_double());
            return s;
        }
        case GinacKind::Mul: {
            const mul& product = ex_to<mul>(e);
            double p = 1;
            for (const expair& factor : GinacPairs::of(product))
                p *= isOne(ex_to<numeric>(factor.coeff)) ? evaluate(factor.rest, values, absolute)
                                                         : powerValue(factor.rest, factor.coeff, values, absolute);
            const numeric& number = ex_to<numeric>(GinacPairs::number(product));
            if (!isOne(number)) p *= sized(number.to_double());
            return p;
        }
        case GinacKind::Power: return powerValue(e.op(0), e.op(1), values, absolute);
        case GinacKind::Function: {
            const std::string f = ex_to<function>(e).get_name();
            const double x = evaluate(e.op(0), values);
            if (absolute) return std::abs(evaluate(e, values));
            if (f == "cos") return std::cos(x);
            if (f == "sin") return std::sin(x);
            if (f == "tan") return std::tan(x);
            if (f == "exp") return std::exp(x);
            if (f == "log") return std::log(x);
            if (f == "tanh") return std::tanh(x);
            if (f == "abs") return std::abs(x);
            throw std::invalid_argument("cannot evaluate " + f);
        }
        case GinacKind::Other: break;
    }
    throw std::invalid_argument("cannot evaluate an expression of this kind");
}

}  // namespace

DefinitionValues::DefinitionValues(const NamedDefinitions& table, const GiNaC::lst& inputs, const std::atomic<bool>* cancel) {
    values_.reserve(inputs.nops() + table.entries().size());
    for (const GiNaC::ex& rel : inputs) values_[rel.lhs()] = evaluate(rel.rhs(), values_);
    magnitudes_ = values_;
    int count = 0;
    for (const NamedDefinition& d : table.entries()) {
        if (++count % 64 == 0) throwIfCancelled(cancel);
        values_[d.symbol] = evaluate(d.value, values_);
        magnitudes_[d.symbol] = evaluate(d.value, magnitudes_, true);
    }
}

double DefinitionValues::operator()(const GiNaC::ex& e) const { return evaluate(e, values_); }

double DefinitionValues::magnitude(const GiNaC::ex& e) const { return evaluate(e, magnitudes_, true); }

}  // namespace ll::symbolic
