// A gather pass over neighbours that runs before the main pair loop, for quantities the pair
// loop needs already finished: density by summation, and the pressure and velocity of wall
// particles extrapolated from the fluid. It reads the solver's neighbour lists of the
// evaluation, the ones the pair loop uses (same positions, radius and domain), so every pass
// shares one neighbour structure: NeighbourRefresh (a term) binds the shared gather to them at
// the start of each evaluation (IEquationTerm::beginEvaluation); later terms' initialize() use
// them.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>

#include "spatial/neighbour_list.hpp"
#include "sph/equation_term.hpp"
#include "sph/kernel_choice.hpp"

namespace num::sph {

template <int Dim>
class NeighbourGather {
  public:
    using Vec = Vector<Dim>;

    void setKernel(const RunSettings& settings) { kernel_.emplace(settings); }
    const RunKernel<Dim>& kernel() const { return *kernel_; }

    /// The neighbour lists of the current evaluation (of the storage's positions, with the
    /// kernel's support radius); valid until the evaluation ends.
    void use(const VerletList<Dim>& neighbours) { neighbours_ = &neighbours; }

    /// The lists of the current evaluation.
    const VerletList<Dim>& lists() const {
        if (!neighbours_)
            throw std::logic_error(
                "NeighbourGather: no neighbour lists (NeighbourRefresh binds the solver's lists "
                "at the start of each evaluation)");
        return *neighbours_;
    }

    /// For every i in `targets`, in parallel: f(i, visit), where visit(g) calls
    /// g(j, dx = x_i - x_j, r, W(r)) for every neighbour j, i itself included, in increasing j.
    template <class F>
    void forEach(IScheduler& scheduler, std::span<const Size> targets, F&& f) const {
        forEachWhere(
            scheduler, targets, [](Size) { return true; }, std::forward<F>(f));
    }

    /// forEach over the neighbours j for which keep(j) holds only: the others' distance and
    /// kernel value are never computed.
    template <class Keep, class F>
    void forEachWhere(IScheduler& scheduler, std::span<const Size> targets, Keep&& keep,
                      F&& f) const {
        const VerletList<Dim>& neighbours = lists();
        withKernel<Dim>(kernel_->type, [&](auto k) {
            using Kernel = decltype(k);
            const Float h = kernel_->h;
            scheduler.parallelFor(Size(targets.size()), 256, [&](Size b, Size e) {
                for (Size t = b; t < e; ++t) {
                    const Size i = targets[t];
                    auto visit = [&](auto&& g) {
                        neighbours.forEachNeighbourOf(i, keep,
                                                      [&](Size j, const Vec& dx, Float r2) {
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
    std::optional<RunKernel<Dim>> kernel_;
    const VerletList<Dim>* neighbours_ = nullptr;
};

/// Binds the shared gather to the solver's neighbour lists at the start of each evaluation.
template <int Dim>
class NeighbourRefresh : public IEquationTerm<Dim> {
  public:
    explicit NeighbourRefresh(std::shared_ptr<NeighbourGather<Dim>> gather)
        : gather_(std::move(gather)) {}

    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings& settings) override {
        gather_->setKernel(settings);
    }
    void beginEvaluation(const EvaluationContext<Dim>& context) override {
        gather_->use(context.neighbours);
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
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
