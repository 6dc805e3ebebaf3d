// The gather (asymmetric) pair loop skips a wall or body particle unless a derivative of the
// pass adds anything for it (IDerivative::gathersAtBoundary): a user derivative is gathered for
// every particle unless it says otherwise, the fluid terms only for fluid particles, heat
// conduction also for boundary particles that are not adiabatic. Skipping changes no result.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <string>

#include "numerics.hpp"
#include "sph/fluid_model.hpp"

namespace {

using namespace num::sph;

/// Counts the particles the pair loop gathers for, by kind.
struct GatherCounts {
    std::atomic<int> fluid{0}, boundary{0};
};

/// A user derivative that leaves gathersAtBoundary as it is (true).
class CountingDerivative : public DerivativeTemplate<CountingDerivative, 2> {
  public:
    explicit CountingDerivative(std::shared_ptr<GatherCounts> counts)
        : counts_(std::move(counts)) {}
    void create(Accumulated<2>&) override {}
    void initialize(const Storage<2>& s, Accumulated<2>&) override {
        kind_ = s.getValue<int>(QuantityId::KIND);
    }
    void gatherNeighbours(Size i, ArrayView<const Size>, ArrayView<const Vector<2>>,
                          const NeighbourGeometry<2>&) {
        ++(isFluid(kind_[i]) ? counts_->fluid : counts_->boundary);
    }
    template <bool Symmetric>
    void eval(Size, Size, const Vector<2>&) {}

  private:
    std::shared_ptr<GatherCounts> counts_;
    ArrayView<const int> kind_;
};

/// The same, declaring that it adds nothing for boundary particles.
class FluidOnlyCountingDerivative : public CountingDerivative {
  public:
    using CountingDerivative::CountingDerivative;
    bool gathersAtBoundary(Size) const override { return false; }
};

template <class Derivative>
class CountingTerm : public IEquationTerm<2> {
  public:
    explicit CountingTerm(std::shared_ptr<GatherCounts> counts) : counts_(std::move(counts)) {}
    void setDerivatives(DerivativeHolder<2>& d, const RunSettings&) override {
        d.require(std::make_unique<Derivative>(counts_));
    }
    void initialize(IScheduler&, Storage<2>&, Float) override {}
    void finalize(IScheduler&, Storage<2>&, Float) override {}
    void create(Storage<2>&, IMaterial&) const override {}

  private:
    std::shared_ptr<GatherCounts> counts_;
};

/// Warm water in a walled box with a hot body (fixed temperature) and a wall moving along the
/// top: every kind of particle and thermal condition the skip decides on.
struct HeatedTank {
    static constexpr double dx = 0.05;
    FluidModel<2> model;
    FluidGeometry<2> geometry;
    RunSettings settings;

    HeatedTank() {
        model.maxVelocity = 1;
        model.viscosity = 1e-2;
        model.artificialViscosity = 0.02;
        model.bodyForce = [](Float) { return Vector<2>{{0, -9.81}}; };
        model.heat.conduction = true;
        geometry.spacing = dx;
        geometry.domain.max = {{1.0, 1.0}};
        for (int k = 0; k < 2; ++k) geometry.walls[k][0] = geometry.walls[k][1] = WallSide<2>{};
        geometry.walls[1][1].velocity = Vector<2>{{1.0, 0.0}};
        geometry.fluid.push_back(
            FluidRegion<2>::filling(BoxOrBall<2>::box({{0.0, 0.0}}, {{1.0, 0.8}})));
        geometry.bodies.push_back(SolidBody<2>{BoxOrBall<2>::ball({{0.5, 0.4}}, 0.15)});
        geometry.bodies.back().temperature = 60;
        settings.set("smoothing_length", 1.5 * dx);
    }
    Storage<2> storage() const {
        Storage<2> s = makeFluidStorage(model, geometry, settings);
        auto v = s.getDt<Vector<2>>(QuantityId::POSITION);
        const auto x = s.getValue<Vector<2>>(QuantityId::POSITION);
        const auto kind = s.getValue<int>(QuantityId::KIND);
        for (Size i = 0; i < s.size(); ++i)
            if (isFluid(kind[i])) v[i] = Vector<2>{{0.1 * x[i][1], -0.05 * x[i][0]}};
        return s;
    }
    EquationHolder<2> equations(EquationHolder<2> extra = {}) const {
        FluidModel<2> m = model;
        m.extraTerms += extra;
        return makeFluidEquations(m, geometry);
    }
};

Size countKind(const Storage<2>& s, bool fluid) {
    const auto kind = s.getValue<int>(QuantityId::KIND);
    Size n = 0;
    for (Size i = 0; i < s.size(); ++i) n += isFluid(kind[i]) == fluid;
    return n;
}

/// Boundary particles that are not adiabatic.
Size conducting(const Storage<2>& s) {
    const auto kind = s.getValue<int>(QuantityId::KIND);
    const auto cond = s.getValue<int>(heat_ids::THERMAL_CONDITION);
    Size n = 0;
    for (Size i = 0; i < s.size(); ++i)
        n += !isFluid(kind[i]) && cond[i] != int(ThermalCondition::ADIABATIC);
    return n;
}

TEST(BoundaryGather, AUserDerivativeIsGatheredEverywhereUnlessItSaysOtherwise) {
    const HeatedTank tank;
    SequentialScheduler scheduler;
    for (const bool atBoundary : {true, false}) {
        auto counts = std::make_shared<GatherCounts>();
        EquationHolder<2> extra;
        if (atBoundary)
            extra += makeTerm<CountingTerm<CountingDerivative>>(counts);
        else
            extra += makeTerm<CountingTerm<FluidOnlyCountingDerivative>>(counts);
        Storage<2> s = tank.storage();
        Solver<2> solver(scheduler, tank.settings, tank.equations(extra), tank.geometry.domain);
        solver.evaluate(s, 0.0);
        EXPECT_EQ(Size(counts->fluid), countKind(s, true)) << atBoundary;
        // Declining, it is still called where heat conduction needs the sums: the hot body.
        EXPECT_EQ(Size(counts->boundary), atBoundary ? countKind(s, false) : conducting(s))
            << atBoundary;
    }
}

TEST(BoundaryGather, SkippingBoundaryParticlesChangesNoResult) {
    const HeatedTank tank;
    SequentialScheduler scheduler;
    // Without a user term the pair loop skips the adiabatic walls; a counting derivative that
    // asks for every particle makes it gather for them all. Every rate must be the same.
    Storage<2> skipped = tank.storage(), all = tank.storage();
    Solver<2> skipping(scheduler, tank.settings, tank.equations(), tank.geometry.domain);
    EquationHolder<2> extra;
    extra += makeTerm<CountingTerm<CountingDerivative>>(std::make_shared<GatherCounts>());
    Solver<2> gathering(scheduler, tank.settings, tank.equations(extra), tank.geometry.domain);
    skipping.evaluate(skipped, 0.0);
    gathering.evaluate(all, 0.0);

    const auto kind = all.getValue<int>(QuantityId::KIND);
    const auto a1 = skipped.getD2t<Vector<2>>(QuantityId::POSITION);
    const auto a2 = all.getD2t<Vector<2>>(QuantityId::POSITION);
    const auto r1 = skipped.getDt<Float>(QuantityId::DENSITY);
    const auto r2 = all.getDt<Float>(QuantityId::DENSITY);
    const auto t1 = skipped.getDt<Float>(QuantityId::TEMPERATURE);
    const auto t2 = all.getDt<Float>(QuantityId::TEMPERATURE);
    Size heated = 0;
    for (Size i = 0; i < all.size(); ++i) {
        EXPECT_EQ(a1[i], a2[i]) << i;
        EXPECT_EQ(r1[i], r2[i]) << i;
        EXPECT_EQ(t1[i], t2[i]) << i;
        heated += isFluid(kind[i]) && t1[i] > 0;
    }
    EXPECT_GT(heated, 0u) << "the hot body must heat the water next to it";
    // The heat the fixed-temperature body gave, booked from its own conduction sums, which
    // the skip keeps.
    const auto* books1 = skipping.equations().find<ThermalBoundary<2>>();
    const auto* books2 = gathering.equations().find<ThermalBoundary<2>>();
    ASSERT_NE(books1, nullptr);
    ASSERT_NE(books2, nullptr);
    skipping.postStep(skipped, 0.0, 1e-4);
    gathering.postStep(all, 0.0, 1e-4);
    EXPECT_GT(books1->books().heatFromFixed(), 0.0);
    EXPECT_EQ(books1->books().heatFromFixed(), books2->books().heatFromFixed());
}

}  // namespace
