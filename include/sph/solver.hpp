// The solver: one evaluation of all derivatives (neighbour search, terms' initialize, the pair
// loop over blocks, the sum of the blocks' buffers, terms' finalize), and the time-step limits.
//
// Reproducibility: particles are split into blocks, each evaluated by one thread in particle
// order with its own derivative objects. Symmetric mode: a fixed number of blocks (setting
// "blocks"), each with its own buffers, summed in block order. Asymmetric mode: each particle
// gathers its own sum into its own entry, whatever the split. Either way the result is bitwise
// the same for any number of threads.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "spatial/cell_grid.hpp"
#include "sph/equation_term.hpp"
#include "sph/kernel_choice.hpp"

namespace num::sph {

template <int Dim>
class Solver {
  public:
    using Vec = Vector<Dim>;

    Solver(IScheduler& scheduler, const RunSettings& settings, EquationHolder<Dim> equations,
           Domain<Dim> domain)
        : scheduler_(scheduler),
          settings_(settings),
          equations_(std::move(equations)),
          domain_(domain),
          kernel_(settings),
          symmetric_(settings.get<std::string>("evaluation") == "symmetric"),
          holders_(blockCount(settings, symmetric_, scheduler.threadCount())),
          scratch_(holders_.size()),
          accumulated_(symmetric_ ? holders_.size() : 1) {
        for (std::size_t b = 0; b < holders_.size(); ++b) {
            equations_.setDerivatives(holders_[b], settings_);
            holders_[b].create(accumulated_[symmetric_ ? b : 0]);
        }
        needsW_ = holders_[0].needsKernelValues();
    }

    /// Creates the quantities every term needs (once, before the first evaluation).
    void create(Storage<Dim>& storage, IMaterial& material) {
        storage.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND, Vec{});
        equations_.create(storage, material);
    }

    /// Evaluates every derivative at time t.
    void evaluate(Storage<Dim>& storage, Float t) {
        ArrayView<Vec> x = storage.template getValue<Vec>(QuantityId::POSITION);
        if (domain_.anyPeriodic())
            for (Vec& p : x) p = domain_.wrap(p);
        zeroHighestDerivatives(storage);
        equations_.initialize(scheduler_, storage, t);

        grid_.build(x, kernel_.supportRadius(), domain_);
        for (auto& a : accumulated_) a.reset(storage.size());
        for (std::size_t b = 0; b < holders_.size(); ++b)
            holders_[b].initialize(storage, accumulated_[symmetric_ ? b : 0]);
        withKernel<Dim>(kernel_.type, [&](auto k) { pairLoop(storage, k); });
        Accumulated<Dim>::addInto(storage, std::span<const Accumulated<Dim>>(accumulated_));

        equations_.finalize(scheduler_, storage, t);
    }

    /// The time-step limits at the current state (after an evaluation).
    TimeStepLimits timeStepLimits(const Storage<Dim>& storage) const {
        TimeStepLimits limits;
        if (const double fixed = settings_.get<double>("dt_fixed"); fixed > 0) {
            limits.offer("fixed", fixed);
            return limits;
        }
        limits.offer("dt_max", settings_.get<double>("dt_max"));
        Float a2max = 0;
        for (const Vec& a : storage.template getD2t<Vec>(QuantityId::POSITION))
            a2max = std::max(a2max, normSqr(a));
        if (a2max > 0)
            limits.offer("acceleration", settings_.get<double>("acceleration_factor") *
                                             std::sqrt(kernel_.h / std::sqrt(a2max)));
        equations_.limitTimeStep(storage, settings_, limits);
        return limits;
    }

    /// Mean number of neighbours per particle in the last evaluation (each pair counted twice).
    double meanNeighbours() const { return meanNeighbours_; }
    const CellGrid<Dim>& grid() const { return grid_; }
    const EquationHolder<Dim>& equations() const { return equations_; }
    const Domain<Dim>& domain() const { return domain_; }
    const RunSettings& settings() const { return settings_; }
    const RunKernel<Dim>& kernel() const { return kernel_; }
    IScheduler& scheduler() { return scheduler_; }

  private:
    /// Symmetric mode: the "blocks" setting (each block has buffers of every particle, and the
    /// results depend on the split). Asymmetric mode: every particle gathers its own sum, so
    /// the split never changes a result; at least 8 blocks per thread balance the load.
    static std::size_t blockCount(const RunSettings& s, bool symmetric, Size threads) {
        const auto blocks = std::size_t(s.get<std::int64_t>("blocks"));
        return symmetric ? blocks : std::max<std::size_t>(blocks, 8 * std::size_t(threads));
    }

    struct Scratch {
        std::vector<Size> neighs;
        std::vector<Vec> grads, dx;
        std::vector<Float> r, w;
        std::size_t pairs = 0;
    };

    static void zeroHighestDerivatives(Storage<Dim>& storage) {
        storage.forEach([](QuantityId, Quantity<Dim>& q) {
            if (q.order() == OrderEnum::ZERO) return;
            q.visit([&](auto& b) {
                auto& top = b.level(int(q.order()));
                std::fill(top.begin(), top.end(),
                          typename std::decay_t<decltype(top)>::value_type{});
            });
        });
    }

    template <class Kernel>
    void pairLoop(Storage<Dim>& storage, Kernel) {
        const ArrayView<const Vec> x = storage.template getValue<Vec>(QuantityId::POSITION);
        const std::uint64_t n = storage.size();
        const std::uint64_t blocks = holders_.size();
        const Float h = kernel_.h;
        scheduler_.parallelFor(Size(blocks), 1, [&](Size b0, Size b1) {
            for (Size b = b0; b < b1; ++b) {
                Scratch& sc = scratch_[b];
                sc.pairs = 0;
                const Size begin = Size(n * b / blocks), end = Size(n * (b + 1) / blocks);
                for (Size i = begin; i < end; ++i) {
                    sc.neighs.clear();
                    sc.dx.clear();
                    sc.r.clear();
                    grid_.forEachNeighbourOf(i, [&](Size j, const Vec& dx, Float r2) {
                        if (symmetric_ ? j > i : j != i) {
                            sc.neighs.push_back(j);
                            sc.dx.push_back(dx);
                            sc.r.push_back(std::sqrt(r2));
                        }
                    });
                    const std::size_t m = sc.neighs.size();
                    sc.pairs += m;
                    sc.grads.resize(m);
                    for (std::size_t k = 0; k < m; ++k)
                        sc.grads[k] = sc.dx[k] * Kernel::gradFactor(sc.r[k], h);
                    sc.w.resize(needsW_ ? m : 0);
                    for (std::size_t k = 0; k < sc.w.size(); ++k) sc.w[k] = Kernel::W(sc.r[k], h);
                    const NeighbourGeometry<Dim> geo{sc.dx, sc.r, sc.w};
                    if (symmetric_)
                        holders_[b].evalSymmetric(i, sc.neighs, sc.grads, geo);
                    else
                        holders_[b].evalAsymmetric(i, sc.neighs, sc.grads, geo);
                }
            }
        });
        std::size_t pairs = 0;
        for (const Scratch& sc : scratch_) pairs += sc.pairs;
        meanNeighbours_ = n ? double(pairs) * (symmetric_ ? 2.0 : 1.0) / double(n) : 0.0;
    }

    IScheduler& scheduler_;
    RunSettings settings_;
    EquationHolder<Dim> equations_;
    Domain<Dim> domain_;
    RunKernel<Dim> kernel_;
    bool symmetric_;
    std::vector<DerivativeHolder<Dim>> holders_;
    std::vector<Scratch> scratch_;
    std::vector<Accumulated<Dim>> accumulated_;
    CellGrid<Dim> grid_;
    bool needsW_ = false;
    double meanNeighbours_ = 0;
};

}  // namespace num::sph
