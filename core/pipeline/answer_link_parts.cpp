// The structured form's per-link quantities as answers (core/symbolic/structured_dynamics.hpp):
//
//   β_jk⁽ⁱ⁾ = m_i J_P,j⁽ⁱ⁾ᵀ J_P,k⁽ⁱ⁾ + J_O,j⁽ⁱ⁾ᵀ I_li⁰ J_O,k⁽ⁱ⁾   link i's part of b_jk
//   γ_j⁽ⁱ⁾  = g0ᵀ J_P,j⁽ⁱ⁾                                 its gravity lever: g_j = −Σ_i m_i γ_j⁽ⁱ⁾
//
// Both are scalars, the same in any frame, so the expanded derivation's own base-frame
// Jacobians (steps 3 and 4) and inertia tensors (step 5) give them exactly; the structured
// form writes them in link i's frame, which only changes how they look.
#include "core/pipeline/answer_key_data.hpp"

namespace ll {

GiNaC::ex AnswerKey::Data::linkPart(const KeyEntry& e) const {
    using symbolic::Quantity;
    const int i = e.i, j = e.j, k = e.k;
    const GiNaC::ex* Jv = itemValue(derivation, Quantity::ComJacobian, i);
    if (!Jv || static_cast<std::size_t>(i) >= masses.size()) return 0;
    const GiNaC::matrix& JP = GiNaC::ex_to<GiNaC::matrix>(*Jv);
    const auto column = [](const GiNaC::matrix& m, int c, int r) { return m(static_cast<unsigned>(r), static_cast<unsigned>(c)); };
    GiNaC::ex out = 0;
    if (k < 0) {  // γ_j⁽ⁱ⁾
        for (int r = 0; r < 3; ++r) out += gravity(static_cast<unsigned>(r), 0) * column(JP, j, r);
        return out;
    }
    for (int r = 0; r < 3; ++r) out += masses[static_cast<std::size_t>(i)] * column(JP, j, r) * column(JP, k, r);
    const GiNaC::ex* Jw = itemValue(derivation, Quantity::AngularJacobian, i);
    const GiNaC::ex* I = itemValue(derivation, Quantity::LinkInertia, i);
    if (Jw && I) {
        const GiNaC::matrix& JO = GiNaC::ex_to<GiNaC::matrix>(*Jw);
        const GiNaC::matrix& Ii = GiNaC::ex_to<GiNaC::matrix>(*I);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) out += column(JO, j, r) * Ii(static_cast<unsigned>(r), static_cast<unsigned>(c)) * column(JO, k, c);
    }
    return out;
}

}  // namespace ll
