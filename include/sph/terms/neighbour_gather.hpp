// A gather pass over neighbours that runs before the main pair loop, for quantities the pair
// loop needs already finished: density by summation, and the pressure and velocity of wall
// particles extrapolated from the fluid. NeighbourRefresh (a term placed first) rebuilds the
// cell grid once per evaluation; later terms' initialize() use it.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <span>

#include "spatial/cell_grid.hpp"
#include "sph/equation_term.hpp"
#include "sph/kernel_choice.hpp"

namespace num::sph {

template <int Dim>
class NeighbourGather {
  public:
    using Vec = Vector<Dim>;

    explicit NeighbourGather(const Domain<Dim>& domain) : domain_(domain) {}

    void setKernel(const RunSettings& settings) { kernel_.emplace(settings); }
    const RunKernel<Dim>& kernel() const { return *kernel_; }

    void build(ArrayView<const Vec> x) {
        x_ = x;
        grid_.build(x, kernel_->supportRadius(), domain_);
    }

    /// For every i in `targets`, in parallel: f(i, visit), where visit(g) calls
    /// g(j, dx = x_i - x_j, r, W(r)) for every neighbour j, i itself included.
    template <class F>
    void forEach(IScheduler& scheduler, std::span<const Size> targets, F&& f) const {
        withKernel<Dim>(kernel_->type, [&](auto k) {
            using Kernel = decltype(k);
            const Float h = kernel_->h;
            scheduler.parallelFor(Size(targets.size()), 256, [&](Size b, Size e) {
                for (Size t = b; t < e; ++t) {
                    const Size i = targets[t];
                    auto visit = [&](auto&& g) {
                        grid_.forEachNeighbour(x_[i], [&](Size j, const Vec& dx, Float r2) {
                            const Float r = std::sqrt(r2);
                            g(j, dx, r, Kernel::W(r, h));
                        });
                    };
                    f(i, visit);
                }
            });
        });
    }

  private:
    Domain<Dim> domain_;
    std::optional<RunKernel<Dim>> kernel_;
    CellGrid<Dim> grid_;
    ArrayView<const Vec> x_;
};

/// Rebuilds the shared gather grid at the start of each evaluation.
template <int Dim>
class NeighbourRefresh : public IEquationTerm<Dim> {
  public:
    explicit NeighbourRefresh(std::shared_ptr<NeighbourGather<Dim>> gather)
        : gather_(std::move(gather)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings& settings) override {
        gather_->setKernel(settings);
    }
    void initialize(IScheduler&, Storage<Dim>& s, Float) override {
        gather_->build(s.template getValue<Vector<Dim>>(QuantityId::POSITION));
    }
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>&, IMaterial&) const override {}

  private:
    std::shared_ptr<NeighbourGather<Dim>> gather_;
};

/// Indices of the particles whose KIND satisfies pred.
template <int Dim, class Pred>
std::vector<Size> particlesWhere(const Storage<Dim>& s, Pred&& pred) {
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    std::vector<Size> out;
    for (Size i = 0; i < s.size(); ++i)
        if (pred(kind[i])) out.push_back(i);
    return out;
}

}  // namespace num::sph
