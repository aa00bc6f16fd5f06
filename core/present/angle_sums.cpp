#include "core/present/angle_sums.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <unordered_map>

#include "core/present/expression_printer.hpp"

namespace ll::present {
namespace {

using symbolic::parseTrigName;
using symbolic::trigSymbolName;

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;
using Mask = std::uint64_t;  // bit i-1 for q_i: robots have far fewer than 64 joints

std::vector<int> indicesOf(Mask m) {
    std::vector<int> out;
    for (int i = 0; m; ++i, m >>= 1)
        if (m & 1) out.push_back(i + 1);
    return out;
}

// One c_A or s_A factor of a term, with its power.
struct Trig {
    char kind;
    Mask mask;
    int exp;
};

// coef · rest · Π trig: rest holds everything that is not a c/s power.
struct Term {
    numeric coef;
    ex rest;
    std::string restKey;     // rest printed: a key independent of GiNaC's hash order
    std::vector<Trig> trig;  // sorted by (mask, kind)
    bool alive = true;
};

std::string trigKey(const std::vector<Trig>& trig) {
    std::string k;
    for (const Trig& t : trig) k += t.kind + std::to_string(t.mask) + "^" + std::to_string(t.exp) + ";";
    return k;
}

// trig with one power of each of `remove` taken out and one of each of `add` put in.
std::vector<Trig> changed(std::vector<Trig> trig, std::initializer_list<std::pair<char, Mask>> remove,
                          std::initializer_list<std::pair<char, Mask>> add) {
    // Plain copies, not structured bindings: clang 14 (the fuzz build) cannot capture those.
    for (const std::pair<char, Mask>& r : remove) {
        const char kind = r.first;
        const Mask mask = r.second;
        auto it = std::find_if(trig.begin(), trig.end(), [&](const Trig& t) { return t.kind == kind && t.mask == mask; });
        if (--it->exp == 0) trig.erase(it);
    }
    for (const std::pair<char, Mask>& a : add) {
        const char kind = a.first;
        const Mask mask = a.second;
        auto it = std::find_if(trig.begin(), trig.end(), [&](const Trig& t) { return t.kind == kind && t.mask == mask; });
        if (it != trig.end()) ++it->exp;
        else trig.push_back({kind, mask, 1});
    }
    std::sort(trig.begin(), trig.end(), [](const Trig& a, const Trig& b) { return std::pair(a.mask, a.kind) < std::pair(b.mask, b.kind); });
    return trig;
}

bool contiguous(Mask m) {
    m >>= std::countr_zero(m);
    return (m & (m + 1)) == 0;
}

// The terms of one expression, findable by their monomial.
class TermTable {
public:
    void add(Term t) {
        const std::string key = t.restKey + "|" + trigKey(t.trig);
        const auto it = index_.find(key);
        if (it != index_.end()) {
            Term& old = terms_[it->second];
            old.coef += t.coef;
            if (old.coef.is_zero()) kill(it->second);
            return;
        }
        if (t.coef.is_zero()) return;
        index_.emplace(key, terms_.size());
        terms_.push_back(std::move(t));
    }

    // A live term with this monomial, or -1.
    long find(const std::string& restKey, const std::vector<Trig>& trig) const {
        const auto it = index_.find(restKey + "|" + trigKey(trig));
        return it == index_.end() ? -1 : static_cast<long>(it->second);
    }

    void kill(std::size_t i) {
        terms_[i].alive = false;
        index_.erase(terms_[i].restKey + "|" + trigKey(terms_[i].trig));
    }

    // Live terms in a fixed order (by their keys), so that which of two competing
    // rewrites wins never depends on GiNaC's hash order.
    std::vector<std::size_t> order() const {
        std::vector<std::pair<std::string, std::size_t>> keyed;
        for (const auto& [key, i] : index_) keyed.emplace_back(key, i);
        std::sort(keyed.begin(), keyed.end());
        std::vector<std::size_t> out;
        for (const auto& k : keyed) out.push_back(k.second);
        return out;
    }

    std::vector<Term>& terms() { return terms_; }

private:
    std::vector<Term> terms_;
    std::unordered_map<std::string, std::size_t> index_;
};

// One sweep over the terms; true if anything was rewritten. With contiguousOnly, only
// unions that are runs of joints (c23, not c13): those are the textbook's, so they get
// the first chance when a term could pair two ways.
bool sweep(TermTable& table, bool contiguousOnly) {
    bool any = false;
    for (const std::size_t i : table.order()) {
        if (!table.terms()[i].alive) continue;
        const Term t = table.terms()[i];  // copy: table.add may reallocate
        bool done = false;
        for (std::size_t x = 0; x < t.trig.size() && !done; ++x)
            for (std::size_t y = x + 1; y < t.trig.size() && !done; ++y) {
                const Trig &a = t.trig[x], &b = t.trig[y];
                const Mask u = a.mask | b.mask;
                if ((a.mask & b.mask) || (contiguousOnly && !contiguous(u))) continue;
                std::vector<Trig> partner;
                numeric partnerCoef;
                char kind;
                if (a.kind == 'c' && b.kind == 'c') {  // k c_A c_B − k s_A s_B → k c_{A∪B}
                    partner = changed(t.trig, {{'c', a.mask}, {'c', b.mask}}, {{'s', a.mask}, {'s', b.mask}});
                    partnerCoef = -t.coef;
                    kind = 'c';
                } else if (a.kind != b.kind) {  // k s_A c_B + k c_A s_B → k s_{A∪B}
                    const Trig& s = a.kind == 's' ? a : b;
                    const Trig& c = a.kind == 's' ? b : a;
                    partner = changed(t.trig, {{'s', s.mask}, {'c', c.mask}}, {{'c', s.mask}, {'s', c.mask}});
                    partnerCoef = t.coef;
                    kind = 's';
                } else {
                    continue;  // s_A s_B: its c_A c_B partner leads
                }
                const long p = table.find(t.restKey, partner);
                if (p < 0 || !(table.terms()[p].coef == partnerCoef)) continue;
                table.kill(i);
                table.kill(static_cast<std::size_t>(p));
                Term merged = t;
                merged.trig = changed(t.trig, {{a.kind, a.mask}, {b.kind, b.mask}}, {{kind, u}});
                table.add(std::move(merged));
                done = any = true;
            }
    }
    return any;
}

}  // namespace

AngleSumCombiner::AngleSumCombiner(std::vector<GiNaC::symbol> q) : q_(std::move(q)) {}

const GiNaC::symbol& AngleSumCombiner::symbolFor(const TrigName& trig) {
    auto it = symbols_.find(trig);
    if (it == symbols_.end()) it = symbols_.emplace(trig, GiNaC::symbol(trigSymbolName(trig, static_cast<int>(q_.size())))).first;
    return it->second;
}

GiNaC::ex AngleSumCombiner::combine(const GiNaC::ex& e) {
    const int n = static_cast<int>(q_.size());
    const PrintOptions keyOptions{Style::Plain, {}, false};
    const ex x = e.expand();
    TermTable table;
    for (const ex& term : is_a<GiNaC::add>(x) ? x : GiNaC::lst{x}) {
        Term t{1, 1, {}, {}};
        for (const ex& f : is_a<GiNaC::mul>(term) ? term : GiNaC::lst{term}) {
            const bool power = is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint);
            const ex base = power ? f.op(0) : f;
            std::optional<TrigName> name;
            if (is_a<GiNaC::symbol>(base)) name = parseTrigName(ex_to<GiNaC::symbol>(base).get_name(), n);
            if (name && name->indices.back() <= 64) {
                symbols_.emplace(*name, ex_to<GiNaC::symbol>(base));  // reuse the caller's symbol
                Mask m = 0;
                for (int i : name->indices) m |= Mask{1} << (i - 1);
                t.trig.push_back({name->kind, m, power ? ex_to<numeric>(f.op(1)).to_int() : 1});
            } else if (is_a<numeric>(f)) {
                t.coef *= ex_to<numeric>(f);
            } else {
                t.rest *= f;
            }
        }
        t.trig = changed(t.trig, {}, {});  // sorted
        t.restKey = print(t.rest, keyOptions);
        table.add(std::move(t));
    }
    while (sweep(table, true) || sweep(table, false)) {
    }
    ex result = 0;
    for (const Term& t : table.terms()) {
        if (!t.alive) continue;
        ex product = t.coef * t.rest;
        for (const Trig& g : t.trig) product *= GiNaC::pow(symbolFor({g.kind, indicesOf(g.mask)}), g.exp);
        result += product;
    }
    return result;
}

GiNaC::matrix AngleSumCombiner::combine(const GiNaC::matrix& m) {
    GiNaC::matrix r(m.rows(), m.cols());
    for (unsigned i = 0; i < m.rows(); ++i)
        for (unsigned j = 0; j < m.cols(); ++j) r(i, j) = combine(m(i, j));
    return r;
}

GiNaC::lst AngleSumCombiner::definitions() const {
    GiNaC::lst out;
    for (const auto& [trig, symbol] : symbols_) {
        if (trig.indices.size() < 2) continue;
        ex angle = 0;
        for (int i : trig.indices) angle += q_.at(i - 1);
        out.append(symbol == (trig.kind == 'c' ? GiNaC::cos(angle) : GiNaC::sin(angle)));
    }
    return out;
}

AngleSumForm combineAngleSums(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& q) {
    AngleSumCombiner combiner(q);
    const ex value = is_a<GiNaC::matrix>(e) ? ex(combiner.combine(ex_to<GiNaC::matrix>(e))) : combiner.combine(e);
    return {value, combiner.definitions()};
}

}  // namespace ll::present
