// Mistakes a user extending the engine can make, and the messages they get: a second derivative
// of one type with other arguments (DerivativeHolder::require), and a term added after the
// storage was made (its quantities missing).
#include <gtest/gtest.h>

#include <string>

#include "heat_diffusion.hpp"
#include "numerics.hpp"
#include "sph/fluid_model.hpp"
#include "test_physics.hpp"

namespace {

using namespace num::sph;

RunSettings withH(double h) {
    RunSettings s;
    s.set("smoothing_length", h);
    return s;
}

/// The message of the std::logic_error `f` throws ("" if none).
template <class F>
std::string logicError(F&& f) {
    try {
        f();
    } catch (const std::logic_error& e) {
        return e.what();
    }
    return "";
}

TEST(DerivativeRequire, EqualArgumentsShareOtherArgumentsAreAnError) {
    DerivativeHolder<2> holder;
    holder.require<examples::EnergyLaplacian<2>>(withH(0.02));
    holder.require<examples::EnergyLaplacian<2>>(withH(0.02));
    EXPECT_EQ(holder.size(), 1u);
    const std::string message =
        logicError([&] { holder.require<examples::EnergyLaplacian<2>>(withH(0.03)); });
    EXPECT_NE(message.find("examples::EnergyLaplacian<2> with constructor arguments other"),
              std::string::npos)
        << message;
    EXPECT_EQ(holder.size(), 1u);
}

TEST(DerivativeRequire, TermsWithOtherArgumentsAreNamed) {
    // Two heat terms whose Laplacians would be made with different smoothing lengths cannot
    // share one: the error names the terms.
    struct OtherH : examples::HeatDiffusion<2> {
        using examples::HeatDiffusion<2>::HeatDiffusion;
        void setDerivatives(DerivativeHolder<2>& d, const RunSettings&) override {
            d.require<examples::EnergyLaplacian<2>>(withH(0.05));
        }
    };
    const auto equations = makeTerm<examples::HeatDiffusion<2>>(1.0) + makeTerm<OtherH>(2.0);
    DerivativeHolder<2> holder;
    const std::string message = logicError([&] { equations.setDerivatives(holder, withH(0.02)); });
    EXPECT_NE(message.find("OtherH asks for a examples::EnergyLaplacian<2>"), std::string::npos)
        << message;
    EXPECT_NE(message.find("those of the term examples::HeatDiffusion<2>"), std::string::npos)
        << message;
}

TEST(DerivativeRequire, ASecondObjectOfOneTypeIsAnError) {
    DerivativeHolder<2> holder;
    const RunSettings s = withH(0.02);
    holder.require(std::make_unique<enginetest::PairForce<2>>(s));
    const std::string message =
        logicError([&] { holder.require(std::make_unique<enginetest::PairForce<2>>(s)); });
    EXPECT_NE(message.find("a second enginetest::PairForce<2> as an object"), std::string::npos)
        << message;
    EXPECT_EQ(holder.size(), 1u);
}

/// A term with a quantity of its own (id -10), created by create().
template <int Dim>
class NeedsOwnQuantity : public IEquationTerm<Dim> {
  public:
    static constexpr auto OWN = QuantityId(-10);
    void setDerivatives(DerivativeHolder<Dim>&, const RunSettings&) override {}
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>& s, Float) override {
        for (Float& x : s.template getValue<Float>(OWN)) x += 1;
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(OWN, OrderEnum::ZERO, 0.0);
    }
};

/// A small periodic box of fluid.
FluidGeometry<2> periodicBox() {
    FluidGeometry<2> g;
    g.spacing = 0.1;
    g.domain.max = {{1.0, 1.0}};
    g.domain.periodic = {true, true};
    g.fluid.push_back(FluidRegion<2>::filling(BoxOrBall<2>::box(g.domain.min, g.domain.max)));
    return g;
}

TEST(MissingQuantity, ATermAddedAfterTheStorageSaysWhatToCall) {
    SequentialScheduler scheduler;
    FluidModel<2> model;
    const FluidGeometry<2> geometry = periodicBox();
    const RunSettings settings = withH(0.13);
    Storage<2> storage = makeFluidStorage(model, geometry, settings);
    model.extraTerms += makeTerm<NeedsOwnQuantity<2>>();  // too late: the storage is made
    Solver<2> solver(scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
    try {
        solver.evaluate(storage, 0.0);
        FAIL() << "expected a MissingQuantity";
    } catch (const MissingQuantity& e) {
        const std::string message = e.what();
        EXPECT_EQ(int(e.id), -10);
        for (const char* part :
             {"the term (anonymous namespace)::NeedsOwnQuantity<2> needs quantity -10",
              "FluidModel::extraTerms before makeFluidStorage",
              "call solver.create(storage, material)"})
            EXPECT_NE(message.find(part), std::string::npos) << part << "\n" << message;
    }
    // What the message says works.
    solver.create(storage, *storage.materials().front());
    solver.evaluate(storage, 0.0);
    EXPECT_EQ(storage.getValue<Float>(NeedsOwnQuantity<2>::OWN)[0], 1.0);
}

TEST(MissingQuantity, ADerivativeNamesTheTermThatRequiredIt) {
    SequentialScheduler scheduler;
    FluidModel<2> model;
    const FluidGeometry<2> geometry = periodicBox();
    RunSettings settings = withH(0.13);
    Storage<2> storage = makeFluidStorage(model, geometry, settings);
    model.extraTerms += makeTerm<examples::HeatDiffusion<2>>(1e-3);
    Solver<2> solver(scheduler, settings, makeFluidEquations(model, geometry), geometry.domain);
    try {
        solver.evaluate(storage, 0.0);
        FAIL() << "expected a MissingQuantity";
    } catch (const MissingQuantity& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("the derivative examples::EnergyLaplacian<2> (required by the "
                               "term examples::HeatDiffusion<2>) needs quantity"),
                  std::string::npos)
            << message;
    }
}

}  // namespace
