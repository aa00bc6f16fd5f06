#include "core/symbolic/structured_entries.hpp"

#include "core/model/one_based.hpp"
#include <algorithm>
#include <cctype>
#include <chrono>
#include <map>
#include <stdexcept>

#include "core/model/cancellation.hpp"
#include "core/model/message_error.hpp"
#include "core/symbolic/ginac_lock.hpp"

namespace ll::symbolic {
namespace {

std::size_t termCount(const GiNaC::ex& e) { return e.is_zero() ? 0 : GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; }

}  // namespace

std::string entryLabel(char m, int r, int c, int n) {
    std::string label(1, m);  // appended, for the -Wrestrict false positive (coordinateName)
    label += idx(r);
    if (m == 'g') return label;
    if (n >= 10) label += '_';
    label += idx(c);
    return label;
}

EntryRef parseEntry(const std::string& text, int n) {
    const auto fail = [&](Message why) { throw MessageError(message(MessageId::EntryRefused, text, std::move(why))); };
    if (text.size() < 2 || (text[0] != 'B' && text[0] != 'C' && text[0] != 'g' && text[0] != 'b' && text[0] != 'c'))
        fail(MessageId::EntryExpected);
    EntryRef e;
    e.matrix = static_cast<char>(text[0] == 'b' ? 'B' : text[0] == 'c' ? 'C' : text[0]);
    std::string rest = text.substr(1);
    std::vector<int> indices;
    try {
        if (rest.find('_') != std::string::npos || rest.find(',') != std::string::npos) {
            for (std::size_t start = 0; start <= rest.size();) {
                const std::size_t end = std::min(rest.find_first_of("_,", start), rest.size());
                indices.push_back(std::stoi(rest.substr(start, end - start)));
                start = end + 1;
            }
        } else if (e.matrix == 'g') {
            indices.push_back(std::stoi(rest));
        } else if (rest.size() == 2) {
            indices = {rest[0] - '0', rest[1] - '0'};
        } else {  // B123: which digits go together is not said
            fail(MessageId::EntryIndicesNotNumbers);
        }
    } catch (const std::logic_error&) {
        fail(MessageId::EntryIndicesNotNumbers);
    }
    for (char ch : rest)
        if (!std::isdigit(static_cast<unsigned char>(ch)) && ch != '_' && ch != ',') fail(MessageId::EntryIndicesNotNumbers);
    if (indices.size() != (e.matrix == 'g' ? 1u : 2u))
        fail(e.matrix == 'g' ? MessageId::EntryGHasOneIndex : MessageId::EntryBAndCHaveTwoIndices);
    for (int i : indices)
        if (i < 1 || i > n) fail(message(MessageId::EntryIndicesRange, n));
    e.row = indices[0] - 1;
    e.col = indices.size() > 1 ? indices[1] - 1 : 0;
    e.label = entryLabel(e.matrix, e.row, e.col, n);
    return e;
}

ExpandedEntry expandEntry(StructuredDynamics& s, const EntryRef& ref, const std::atomic<bool>* cancel) {
    const auto lock = lockGinac();
    const auto start = std::chrono::steady_clock::now();
    NamedDefinitions& table = *s.table;
    const TrigContext& tc = *s.trig;
    ExpandedEntry out{ref, 0, 0, 0};
    if (ref.matrix == 'B') {
        out.value = table.unfold(s.B(ref.row, ref.col), cancel);
    } else if (ref.matrix == 'g') {
        out.value = table.unfold(s.g(ref.row, 0), cancel);
    } else {
        // c_ij = Σ_k ½(∂b_ij/∂q_k + ∂b_ik/∂q_j − ∂b_jk/∂q_i) q̇_k from entries of rows i and j
        // of B expanded, each only when it depends on the coordinate it is differentiated
        // by (the names say which: b_jk never depends on q_1..q_min(j,k)); for i = j the
        // last two terms cancel and are not formed.
        const int i = ref.row, j = ref.col;
        std::map<std::pair<int, int>, GiNaC::ex> expandedB;
        const auto derivative = [&](int r, int c, int l) -> GiNaC::ex {
            if (!(table.coordinatesOf(s.B(r, c)) & (std::uint64_t(1) << l))) return 0;
            const auto key = std::minmax(r, c);
            auto it = expandedB.find(key);
            if (it == expandedB.end()) it = expandedB.emplace(key, table.unfold(s.B(r, c), cancel)).first;
            throwIfCancelled(cancel);
            return tc.diffq(it->second, l);
        };
        // Each Christoffel symbol is reduced alone: multiplied by its own q̇_k, the reduced
        // symbols only need expanding into one sum (a 27,000-term c₁₁ is never reduced whole).
        GiNaC::ex c = 0;
        for (int k = 0; k < s.n; ++k) {
            GiNaC::ex christoffel = derivative(i, j, k);
            if (i != j) christoffel += derivative(i, k, j) - derivative(j, k, i);
            if (!christoffel.is_zero()) c += GiNaC::numeric(1, 2) * tc.reduce(christoffel) * tc.qd(k);
            throwIfCancelled(cancel);
        }
        out.value = c.expand();
    }
    out.terms = termCount(out.value);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

bool skewSymmetric(const StructuredDynamics& s) {
    const auto lock = lockGinac();
    for (int j = 0; j < s.n; ++j)
        for (int k = j; k < s.n; ++k) {
            GiNaC::ex sum = -2 * (s.C(j, k) + s.C(k, j));
            for (int l = 0; l < s.n; ++l) sum += 2 * s.dB[l](j, k) * s.trig->qd(l);
            if (!sum.expand().is_zero()) return false;
        }
    return true;
}

}  // namespace ll::symbolic
