#include "core/present/structured_control_law.hpp"

#include <map>
#include <memory>
#include <string>

#include "core/model/one_based.hpp"
#include "core/present/derivation_document.hpp"
#include "core/symbolic/control_law.hpp"
#include "core/symbolic/index_list.hpp"

namespace ll::present {

DisplayStep structuredControlStep(const Scene& scene, const symbolic::StructuredDynamics& s) {
    // A derivation whose B, C, g are step 8's entries by name: b_jk (= b_kj), c_ij, g_i,
    // each a symbol read as the entry's label. Q is the structured form's own.
    symbolic::Derivation d;
    d.system = symbolic::SystemKind::Robot;
    d.systemName = s.systemName;
    d.q = s.trig->q();
    d.qd = s.trig->qd();
    d.qdd = s.qdd;
    for (int i = 0; i < s.n; ++i) d.coordinateNames.push_back("q" + idx(i));
    d.trigToFunctions = s.trigToFunctions;
    d.parameterValues = s.parameterValues;
    d.B = GiNaC::matrix(s.n, s.n), d.C = GiNaC::matrix(s.n, s.n), d.g = GiNaC::matrix(s.n, 1), d.Q = s.Q;
    auto given = std::make_shared<std::map<std::string, DisplayPtr>>();
    const auto entry = [&](const std::string& letter, std::vector<std::string> indices) {
        const std::string name = "entry_" + letter + "_" + symbolic::joined(indices);
        auto n = std::make_shared<DisplayNode>();
        n->kind = DisplayKind::Symbol;
        n->text = n->latex = letter;
        n->subText = n->subShown = n->subLatex = symbolic::joined(indices);
        n->name = n->plain = letter + n->subText;
        (*given)[name] = n;
        return GiNaC::ex(GiNaC::symbol(name));
    };
    for (int i = 0; i < s.n; ++i) {
        d.g(i, 0) = s.g(i, 0).is_zero() ? GiNaC::ex(0) : entry("g", {idx(i)});
        for (int j = 0; j < s.n; ++j) {
            d.C(i, j) = s.C(i, j).is_zero() ? GiNaC::ex(0) : entry("c", {idx(i), idx(j)});
            d.B(i, j) = j < i ? d.B(j, i) : s.B(i, j).is_zero() ? GiNaC::ex(0) : entry("b", {idx(i), idx(j)});
        }
    }
    const symbolic::DerivationStep step = symbolic::controlLawStep(scene, d, [](const GiNaC::ex& e) { return e.expand(); });
    return displayStep(d, step, given);
}

}  // namespace ll::present
