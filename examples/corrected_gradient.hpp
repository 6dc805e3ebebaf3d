// A two-pass example: the kernel gradient correction of Bonet & Lok (1999, Comput. Methods Appl.
// Mech. Engrg. 180, 97, sec. 3.2; Randles & Libersky 1996), written as user code.
//     B_i = sum_j V_j grad_i W_ij (x_j - x_i)^T,          V_j = m_j / rho_j
//     (grad f)_i = B_i^-1 sum_j V_j (f_j - f_i) grad_i W_ij
// For a linear field f = a . x + c the sum is B_i a, so the corrected gradient is a exactly, on
// any particle arrangement where B_i is invertible (at free surfaces and in disorder too), while
// the plain sum is off wherever the neighbourhood is not symmetric.
// B_i is a pair sum, and the gradient needs B_i of the same positions before its own sum is
// finished: two passes. GradientCorrection declares that it produces B^-1; CorrectedGradient
// declares that it reads it, so the solver runs it one pass later, in whatever order the two
// terms were added.
#pragma once

#include <array>
#include <cmath>
#include <tuple>

#include "numerics.hpp"

namespace examples {

using num::sph::Float;
using num::sph::Size;

/// The quantities of this example (negative ids are free for users): the field f, the rows of
/// B and of B^-1, the uncorrected and the corrected gradient.
enum class CorrectionId : int {
    FIELD = -20,
    MOMENT_ROW = -21,      // -21, -22, -23: the rows of B
    CORRECTION_ROW = -24,  // -24, -25, -26: the rows of B^-1
    RAW_GRADIENT = -27,
    GRADIENT = -28,
};

inline num::sph::QuantityId correctionId(CorrectionId id, int row = 0) {
    return num::sph::QuantityId(int(id) - row);
}

/// The pair sums B_i, row by row (pass 1).
template <int Dim>
class MomentMatrix : public num::sph::DerivativeTemplate<MomentMatrix<Dim>, Dim> {
  public:
    using Vector = num::sph::Vector<Dim>;
    void create(num::sph::Accumulated<Dim>& results) override {
        for (int k = 0; k < Dim; ++k)
            results.template insert<Vector>(correctionId(CorrectionId::MOMENT_ROW, k));
    }
    void initialize(const num::sph::Storage<Dim>& s, num::sph::Accumulated<Dim>& r) override {
        using num::sph::QuantityId;
        std::tie(m_, rho_) = s.template getValues<Float>(QuantityId::MASS, QuantityId::DENSITY);
        for (int k = 0; k < Dim; ++k)
            rows_[k] = r.template getValue<Vector>(correctionId(CorrectionId::MOMENT_ROW, k));
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector& grad, const num::sph::PairGeometry<Dim>& pair) {
        // Row k of grad (x_j - x_i)^T is grad[k] (-dx); from j's side both signs flip.
        for (int k = 0; k < Dim; ++k) {
            rows_[k][i] -= pair.dx * (m_[j] / rho_[j] * grad[k]);
            if constexpr (Symmetric) rows_[k][j] -= pair.dx * (m_[i] / rho_[i] * grad[k]);
        }
    }

  private:
    num::sph::ArrayView<const Float> m_, rho_;
    std::array<num::sph::ArrayView<Vector>, Dim> rows_;
};

/// The plain gradient sum_j V_j (f_j - f_i) grad_i W_ij (pass 2).
template <int Dim>
class RawGradient : public num::sph::DerivativeTemplate<RawGradient<Dim>, Dim> {
  public:
    using Vector = num::sph::Vector<Dim>;
    void create(num::sph::Accumulated<Dim>& results) override {
        results.template insert<Vector>(correctionId(CorrectionId::RAW_GRADIENT));
    }
    void initialize(const num::sph::Storage<Dim>& s, num::sph::Accumulated<Dim>& r) override {
        using num::sph::QuantityId;
        std::tie(m_, rho_) = s.template getValues<Float>(QuantityId::MASS, QuantityId::DENSITY);
        f_ = s.template getValue<Float>(correctionId(CorrectionId::FIELD));
        gradient_ = r.template getValue<Vector>(correctionId(CorrectionId::RAW_GRADIENT));
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector& grad) {
        const Float df = f_[j] - f_[i];
        gradient_[i] += grad * (m_[j] / rho_[j] * df);
        if constexpr (Symmetric) gradient_[j] += grad * (m_[i] / rho_[i] * df);
    }

  private:
    num::sph::ArrayView<const Float> m_, rho_, f_;
    num::sph::ArrayView<Vector> gradient_;
};

/// B^-1 from the rows of B (identity where B is singular: an isolated particle keeps the plain
/// gradient). Rows in, rows out; Dim 1 to 3.
template <int Dim>
std::array<num::sph::Vector<Dim>, Dim> inverseRows(
    const std::array<num::sph::Vector<Dim>, Dim>& b) {
    std::array<num::sph::Vector<Dim>, Dim> inv{};
    if constexpr (Dim == 1) {
        inv[0][0] = b[0][0] != 0 ? 1 / b[0][0] : 1;
    } else if constexpr (Dim == 2) {
        const Float det = b[0][0] * b[1][1] - b[0][1] * b[1][0];
        if (det == 0) return inv[0][0] = inv[1][1] = 1, inv;
        inv[0] = {{b[1][1] / det, -b[0][1] / det}};
        inv[1] = {{-b[1][0] / det, b[0][0] / det}};
    } else {
        // Column l of B^-1 is the cross product of rows l+1 and l+2 of B over det B.
        for (int l = 0; l < 3; ++l) {
            const auto &p = b[(l + 1) % 3], &q = b[(l + 2) % 3];
            inv[0][l] = p[1] * q[2] - p[2] * q[1];
            inv[1][l] = p[2] * q[0] - p[0] * q[2];
            inv[2][l] = p[0] * q[1] - p[1] * q[0];
        }
        const Float det = b[0][0] * inv[0][0] + b[0][1] * inv[1][0] + b[0][2] * inv[2][0];
        if (det == 0) return inv = {}, inv[0][0] = inv[1][1] = inv[2][2] = 1, inv;
        for (auto& row : inv) row = row / det;
    }
    return inv;
}

/// Pass 1: sums B_i and stores its inverse, row by row.
template <int Dim>
class GradientCorrection : public num::sph::IEquationTerm<Dim> {
  public:
    using Vector = num::sph::Vector<Dim>;
    void setDerivatives(num::sph::DerivativeHolder<Dim>& d, const num::sph::RunSettings&) override {
        d.template require<MomentMatrix<Dim>>();
    }
    void initialize(num::sph::IScheduler&, num::sph::Storage<Dim>&, Float) override {}
    void finalize(num::sph::IScheduler& scheduler, num::sph::Storage<Dim>& s, Float) override {
        std::array<num::sph::ArrayView<Vector>, Dim> b, inv;
        for (int k = 0; k < Dim; ++k) {
            b[k] = s.template getValue<Vector>(correctionId(CorrectionId::MOMENT_ROW, k));
            inv[k] = s.template getValue<Vector>(correctionId(CorrectionId::CORRECTION_ROW, k));
        }
        scheduler.parallelFor(s.size(), 1024, [&](Size begin, Size end) {
            for (Size i = begin; i < end; ++i) {
                std::array<Vector, Dim> rows;
                for (int k = 0; k < Dim; ++k) rows[k] = b[k][i];
                const auto inverse = inverseRows<Dim>(rows);
                for (int k = 0; k < Dim; ++k) inv[k][i] = inverse[k];
            }
        });
    }
    void create(num::sph::Storage<Dim>& s, num::sph::IMaterial&) const override {
        for (int k = 0; k < Dim; ++k) {
            s.template insert<Vector>(correctionId(CorrectionId::MOMENT_ROW, k),
                                      num::sph::OrderEnum::ZERO, Vector{});
            s.template insert<Vector>(correctionId(CorrectionId::CORRECTION_ROW, k),
                                      num::sph::OrderEnum::ZERO, Vector{});
        }
    }
    /// Reads the densities other terms prepare; produces B^-1 (after its pair sums).
    num::sph::TermAccess access() const override {
        num::sph::TermAccess access{.reads = {num::sph::QuantityId::DENSITY}};
        for (int k = 0; k < Dim; ++k)
            access.produces.push_back(correctionId(CorrectionId::CORRECTION_ROW, k));
        return access;
    }
};

/// Pass 2: the corrected gradient of FIELD, B_i^-1 times the plain sum, into GRADIENT.
template <int Dim>
class CorrectedGradient : public num::sph::IEquationTerm<Dim> {
  public:
    using Vector = num::sph::Vector<Dim>;
    void setDerivatives(num::sph::DerivativeHolder<Dim>& d, const num::sph::RunSettings&) override {
        d.template require<RawGradient<Dim>>();
    }
    void initialize(num::sph::IScheduler&, num::sph::Storage<Dim>&, Float) override {}
    void finalize(num::sph::IScheduler& scheduler, num::sph::Storage<Dim>& s, Float) override {
        const auto raw = s.template getValue<Vector>(correctionId(CorrectionId::RAW_GRADIENT));
        auto gradient = s.template getValue<Vector>(correctionId(CorrectionId::GRADIENT));
        std::array<num::sph::ArrayView<const Vector>, Dim> inv;
        for (int k = 0; k < Dim; ++k)
            inv[k] = s.template getValue<Vector>(correctionId(CorrectionId::CORRECTION_ROW, k));
        scheduler.parallelFor(s.size(), 1024, [&](Size begin, Size end) {
            for (Size i = begin; i < end; ++i)
                for (int k = 0; k < Dim; ++k) gradient[i][k] = dot(inv[k][i], raw[i]);
        });
    }
    void create(num::sph::Storage<Dim>& s, num::sph::IMaterial&) const override {
        using num::sph::OrderEnum;
        s.template insert<Float>(correctionId(CorrectionId::FIELD), OrderEnum::ZERO, 0.0);
        s.template insert<Vector>(correctionId(CorrectionId::RAW_GRADIENT), OrderEnum::ZERO,
                                  Vector{});
        s.template insert<Vector>(correctionId(CorrectionId::GRADIENT), OrderEnum::ZERO, Vector{});
    }
    /// Reads B^-1, which GradientCorrection produces: the solver puts this term a pass later.
    num::sph::TermAccess access() const override {
        num::sph::TermAccess access{
            .reads = {num::sph::QuantityId::DENSITY, correctionId(CorrectionId::FIELD)},
            .produces = {correctionId(CorrectionId::GRADIENT)}};
        for (int k = 0; k < Dim; ++k)
            access.reads.push_back(correctionId(CorrectionId::CORRECTION_ROW, k));
        return access;
    }
};

}  // namespace examples
