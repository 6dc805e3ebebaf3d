// DerivativeHolder, Accumulated, DerivativeTemplate and FusedDerivative.
#include <gtest/gtest.h>

#include <vector>

#include "heat_diffusion.hpp"
#include "numerics.hpp"
#include "test_physics.hpp"

namespace {

using namespace num::sph;
using V2 = Vector<2>;

TEST(DerivativeHolder, RequireKeepsOneDerivativePerType) {
    RunSettings settings;
    DerivativeHolder<2> holder;
    holder.require<examples::EnergyLaplacian<2>>(settings);
    holder.require<examples::EnergyLaplacian<2>>(settings);
    EXPECT_EQ(holder.size(), 1u);
    holder.require<enginetest::PairForce<2>>(settings);
    EXPECT_EQ(holder.size(), 2u);
    // Two terms that require the same derivative share it.
    const auto equations = makeTerm<examples::HeatDiffusion<2>>(1.0) +
                           makeTerm<examples::HeatDiffusion<2>>(2.0) +
                           makeTerm<enginetest::PairForceTerm<2>>();
    DerivativeHolder<2> shared;
    equations.setDerivatives(shared, settings);
    EXPECT_EQ(shared.size(), 2u);
    EXPECT_EQ(equations.size(), 3u);
}

TEST(Accumulated, BlocksAreSummedInBlockOrderIntoTheirTargets) {
    Storage<2> s;
    s.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND, std::vector<V2>(2));
    s.insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, 5.0);
    s.getD2t<V2>(QuantityId::POSITION)[1] = V2{{1.0, 2.0}};
    std::vector<Accumulated<2>> blocks(3);
    for (auto& b : blocks) {
        b.insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO);
        b.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND);
        b.insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO);  // again: ignored
        b.reset(2);
    }
    EXPECT_EQ(blocks[0].bufferCount(), 2u);
    EXPECT_THROW(blocks[0].insert<V2>(QuantityId::DENSITY, OrderEnum::ZERO), std::logic_error);
    // Values whose sum depends on the order: (1e16 + 1) - 1e16 is 0 in double, not 1.
    const double parts[3] = {1e16, 1.0, -1e16};
    for (int b = 0; b < 3; ++b) {
        blocks[b].getValue<Float>(QuantityId::DENSITY)[0] = parts[b];
        blocks[b].getValue<Float>(QuantityId::DENSITY)[1] = b + 1.0;
        blocks[b].getValue<V2>(QuantityId::POSITION)[1] = V2{{0.5, 0.25}};
    }
    Accumulated<2>::addInto(s, blocks);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    EXPECT_EQ(rho[0], (parts[0] + parts[1]) + parts[2]);  // block order, the value replaced
    EXPECT_EQ(rho[1], 6.0);
    // A d2t target is added to (other terms' contributions stay).
    EXPECT_EQ(s.getD2t<V2>(QuantityId::POSITION)[1], (V2{{2.5, 2.75}}));
}

// The gather loop's sums: every target is the stored array itself; a value keeps its previous
// value until startSums zeroes it, a d2t keeps what terms added and the sums add on to it.
TEST(Accumulated, SumsInStorageAreTheStoredArrays) {
    Storage<2> s;
    s.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND, std::vector<V2>(2));
    s.insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, 5.0);
    s.getD2t<V2>(QuantityId::POSITION)[1] = V2{{1.0, 2.0}};  // a term's, before the loop
    Accumulated<2> sums;
    sums.sumInStorage();
    sums.insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO);
    sums.insert<V2>(QuantityId::POSITION, OrderEnum::SECOND);
    sums.reset(s);
    const auto rho = s.getValue<Float>(QuantityId::DENSITY);
    const auto acceleration = s.getD2t<V2>(QuantityId::POSITION);
    auto rhoSum = sums.getValue<Float>(QuantityId::DENSITY);
    auto accelerationSum = sums.getValue<V2>(QuantityId::POSITION);
    EXPECT_EQ(rhoSum.data(), rho.data());
    EXPECT_EQ(accelerationSum.data(), acceleration.data());
    EXPECT_EQ(rhoSum[1], 5.0);  // the previous value, for a derivative's initialize
    const auto sequential = [](Size n, const auto& range) { range(Size(0), n); };
    sums.startSums(sequential);
    EXPECT_EQ(rho[0], 0.0);
    EXPECT_EQ(rho[1], 0.0);
    EXPECT_EQ(acceleration[1], (V2{{1.0, 2.0}}));
    rhoSum[1] += 3.0;
    accelerationSum[1] += V2{{0.5, 0.25}};
    Accumulated<2>::addInto(s, std::span<const Accumulated<2>>(&sums, 1), sequential);
    EXPECT_EQ(rho[1], 3.0);  // not added again
    EXPECT_EQ(acceleration[1], (V2{{1.5, 2.25}}));

    // A value target the storage lacks: the derivative's initialize meets it (and the
    // DerivativeHolder names the derivative and its term), else the sums name the derivative.
    Accumulated<2> missing;
    missing.sumInStorage();
    missing.setOwner("MyDerivative");
    missing.insert<Float>(QuantityId::TEMPERATURE, OrderEnum::ZERO);
    missing.reset(s);
    EXPECT_THROW(missing.getValue<Float>(QuantityId::TEMPERATURE), MissingQuantity);
    try {
        missing.startSums(sequential);
        ADD_FAILURE() << "no error for a missing quantity";
    } catch (const MissingQuantity& e) {
        EXPECT_NE(std::string(e.what()).find("MyDerivative"), std::string::npos) << e.what();
    }
}

/// The pair force and the Laplacian, fused into one pass.
template <int Dim>
class FusedTerm : public IEquationTerm<Dim> {
  public:
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& s) override {
        using Fused =
            FusedDerivative<Dim, enginetest::PairForce<Dim>, examples::EnergyLaplacian<Dim>>;
        d.require(std::make_unique<Fused>(enginetest::PairForce<Dim>(s),
                                          examples::EnergyLaplacian<Dim>(s)));
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(examples::EnergyLaplacian<Dim>::LAPLACIAN, OrderEnum::ZERO, 0.0);
    }
};

template <int Dim>
Storage<Dim> evaluateOnce(EquationHolder<Dim> eq, const std::string& mode) {
    RunSettings settings;
    settings.set("smoothing_length", 0.06).set("evaluation", mode);
    Storage<Dim> s = enginetest::randomParticles<Dim>(400, 4);
    SequentialScheduler scheduler;
    Solver<Dim> solver(scheduler, settings, eq, num::Domain<Dim>{});
    Material material;
    solver.create(s, material);
    solver.evaluate(s, 0);
    return s;
}

TEST(FusedDerivative, EqualsTheSeparateDerivativesBitwise) {
    for (const std::string mode : {"symmetric", "asymmetric"}) {
        const auto fused = evaluateOnce<2>(makeTerm<FusedTerm<2>>(), mode);
        // HeatDiffusion with alpha = 0 requires the same Laplacian and adds nothing to du.
        const auto separate = evaluateOnce<2>(
            makeTerm<enginetest::PairForceTerm<2>>() + makeTerm<examples::HeatDiffusion<2>>(0.0),
            mode);
        const auto lapF = fused.getValue<Float>(examples::EnergyLaplacian<2>::LAPLACIAN);
        const auto lapS = separate.getValue<Float>(examples::EnergyLaplacian<2>::LAPLACIAN);
        const auto aF = fused.getD2t<V2>(QuantityId::POSITION);
        const auto aS = separate.getD2t<V2>(QuantityId::POSITION);
        double largest = 0;
        for (Size i = 0; i < fused.size(); ++i) {
            EXPECT_EQ(lapF[i], lapS[i]);
            EXPECT_EQ(aF[i], aS[i]);
            largest = std::max(largest, std::abs(lapF[i]));
        }
        EXPECT_GT(largest, 0.0);  // the particles do interact
    }
}

}  // namespace
