// The passes of an evaluation (sph/evaluation_schedule.hpp): where the solver places terms from
// what they declare, and a two-pass term (examples/corrected_gradient.hpp) run through the
// solver against the analytic result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "corrected_gradient.hpp"
#include "numerics.hpp"
#include "sph/fluid_model.hpp"

namespace {

using namespace num::sph;

const QuantityId X = QuantityId(-1), Y = QuantityId(-2), Z = QuantityId(-3);

std::vector<std::string> names(std::size_t n) {
    std::vector<std::string> out;
    for (std::size_t k = 0; k < n; ++k) out.push_back(std::string(1, char('A' + k)));
    return out;
}

/// The pass of every term, in the order added.
std::vector<std::size_t> passOf(const EvaluationSchedule& schedule, std::size_t n) {
    std::vector<std::size_t> pass(n, 99);
    for (std::size_t p = 0; p < schedule.passes.size(); ++p)
        for (std::size_t t : schedule.passes[p].terms) pass[t] = p;
    return pass;
}

TEST(EvaluationSchedule, TermsThatDeclareNothingShareOnePassInTheOrderAdded) {
    const auto s = scheduleEvaluation(std::vector<TermAccess>(3), names(3));
    ASSERT_EQ(s.passes.size(), 1u);
    EXPECT_EQ(s.passes[0].terms, (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(s.passes[0].derivatives, (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(s.describe(names(3)), "pass 1: A, B, C\n");
}

TEST(EvaluationSchedule, AReaderOfPairSumsRunsOnePassLaterWhateverTheOrderAdded) {
    // A reads X, which B produces; C declares nothing.
    const std::vector<TermAccess> access{{.reads = {X}}, {.produces = {X}}, {}};
    const auto s = scheduleEvaluation(access, names(3));
    EXPECT_EQ(passOf(s, 3), (std::vector<std::size_t>{1, 0, 0}));
    EXPECT_EQ(s.passes[0].derivatives, (std::vector<std::size_t>{1, 2}));
    EXPECT_EQ(s.passes[1].derivatives, (std::vector<std::size_t>{0}));
    EXPECT_EQ(s.describe(names(3)), "pass 1: B, C\npass 2: A\n");
}

TEST(EvaluationSchedule, APreparedQuantityIsReadAfterItsPreparerInItsPass) {
    // B reads X (produced by A) and prepares Y: pass 2. C, added after B, reads Y: pass 2 too,
    // after B. D, added before B, reads Y as it was: it stays in pass 1. E reads Z, produced
    // in pass 2 by C: pass 3.
    const std::vector<TermAccess> access{{.produces = {X}},
                                         {.reads = {Y}},
                                         {.reads = {X}, .prepares = {Y}},
                                         {.reads = {Y}, .produces = {Z}},
                                         {.reads = {Z}}};
    const auto s = scheduleEvaluation(access, names(5));
    EXPECT_EQ(passOf(s, 5), (std::vector<std::size_t>{0, 0, 1, 1, 2}));
    EXPECT_EQ(s.passes[1].terms, (std::vector<std::size_t>{2, 3}));
}

TEST(EvaluationSchedule, LastAndEveryPlacements) {
    const std::vector<TermAccess> access{{.placement = PassPlacement::LAST},
                                         {.reads = {X}},
                                         {.produces = {X}},
                                         {.placement = PassPlacement::EVERY}};
    const auto s = scheduleEvaluation(access, names(4));
    ASSERT_EQ(s.passes.size(), 2u);
    EXPECT_EQ(passOf(s, 4), (std::vector<std::size_t>{1, 1, 0, 0}));
    // EVERY: its setDerivatives runs in both passes, after the pass's own terms.
    EXPECT_EQ(s.passes[0].derivatives, (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(s.passes[1].derivatives, (std::vector<std::size_t>{0, 1, 3}));
}

std::string logicError(const std::vector<TermAccess>& access) {
    try {
        scheduleEvaluation(access, names(access.size()));
    } catch (const std::logic_error& e) {
        return e.what();
    }
    return "";
}

TEST(EvaluationSchedule, ImpossibleDeclarationsAreErrorsThatNameTheTerms) {
    // A and B each read what the other produces; C is innocent.
    const std::string cycle =
        logicError({{.reads = {Y}, .produces = {X}}, {.reads = {X}, .produces = {Y}}, {}});
    EXPECT_NE(cycle.find("the terms A, B read what each other produce"), std::string::npos)
        << cycle;
    EXPECT_EQ(cycle.find("C"), std::string::npos) << cycle;
    // Reading what a term of the last pass produces: no pass comes after it.
    const std::string last =
        logicError({{.produces = {X}, .placement = PassPlacement::LAST}, {.reads = {X}}});
    EXPECT_NE(last.find("the term B reads what A writes, which is placed in the last pass"),
              std::string::npos)
        << last;
}

/// The fluid model's terms, with walls, bodies, heat, buoyancy and temperature-dependent
/// viscosity, by summation or continuity: their declarations keep them in one pass in the
/// order the model adds them, which is the order its results were validated in.
TEST(EvaluationSchedule, TheFluidModelIsOnePassInTheOrderItAddsItsTerms) {
    for (const DensityMode density : {DensityMode::CONTINUITY, DensityMode::SUMMATION}) {
        FluidModel<2> model;
        model.density = density;
        model.viscosity = 1e-6;
        model.artificialViscosity = 0.1;
        model.bodyForce = constantForce(Vector<2>{{0, -9.81}});
        model.heat.conduction = model.heat.buoyancy = model.heat.temperatureViscosity = true;
        FluidGeometry<2> geometry;
        geometry.spacing = 0.1;
        geometry.domain.max = {{1.0, 1.0}};
        const EquationHolder<2> equations = makeFluidEquations(model, geometry);
        const EvaluationSchedule s = equations.schedule();
        ASSERT_EQ(s.passes.size(), 1u) << s.describe(equations.names());
        std::vector<std::size_t> added(equations.size());
        for (std::size_t k = 0; k < added.size(); ++k) added[k] = k;
        EXPECT_EQ(s.passes[0].terms, added);
        EXPECT_EQ(s.passes[0].derivatives, added);
    }
}

/// A disordered cloud of particles in the unit box (no periodic axis: every particle near a
/// side has a one-sided neighbourhood), with the field f = a . x + 3.
template <int Dim>
Storage<Dim> cloudWithLinearField(Float dx, const Vector<Dim>& a) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-0.3 * dx, 0.3 * dx), unit(0.8, 1.2);
    std::vector<Vector<Dim>> x;
    const int n = int(std::round(1 / dx));
    for (int c = 0; c < int(std::pow(n, Dim)); ++c) {
        Vector<Dim> p;
        for (int k = 0, rest = c; k < Dim; ++k, rest /= n)
            p[k] = (rest % n + 0.5) * dx + jitter(rng);
        x.push_back(p);
    }
    Storage<Dim> s;
    s.template insert<Vector<Dim>>(QuantityId::POSITION, OrderEnum::SECOND, x);
    std::vector<Float> m(x.size()), rho(x.size()), f(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        m[i] = std::pow(dx, Dim) * unit(rng), rho[i] = unit(rng), f[i] = dot(a, x[i]) + 3;
    }
    s.template insert<Float>(QuantityId::MASS, OrderEnum::ZERO, m);
    s.template insert<Float>(QuantityId::DENSITY, OrderEnum::ZERO, rho);
    s.template insert<Float>(examples::correctionId(examples::CorrectionId::FIELD), OrderEnum::ZERO,
                             f);
    return s;
}

template <int Dim>
RunSettings settingsFor(Float dx, const std::string& evaluation = "asymmetric") {
    RunSettings settings;
    settings.set("smoothing_length", 1.3 * dx).set("evaluation", evaluation);
    return settings;
}

/// The corrected gradient after one evaluation (and the uncorrected one).
template <int Dim>
struct Gradients {
    std::vector<Vector<Dim>> corrected, plain;
    std::size_t passes = 0;
};

template <int Dim>
Gradients<Dim> gradients(Float dx, const Vector<Dim>& a, bool correctionFirst, IScheduler& sch,
                         const std::string& evaluation = "asymmetric") {
    using namespace examples;
    Storage<Dim> s = cloudWithLinearField<Dim>(dx, a);
    auto correction = makeTerm<GradientCorrection<Dim>>();
    auto gradient = makeTerm<CorrectedGradient<Dim>>();
    num::Domain<Dim> domain;
    for (int k = 0; k < Dim; ++k) domain.min[k] = 0, domain.max[k] = 1;
    Solver<Dim> solver(sch, settingsFor<Dim>(dx, evaluation),
                       correctionFirst ? correction + gradient : gradient + correction, domain);
    Material material("cloud");
    solver.create(s, material);
    solver.evaluate(s, 0);
    const auto corrected = s.template getValue<Vector<Dim>>(correctionId(CorrectionId::GRADIENT));
    const auto plain = s.template getValue<Vector<Dim>>(correctionId(CorrectionId::RAW_GRADIENT));
    return {{corrected.begin(), corrected.end()},
            {plain.begin(), plain.end()},
            solver.schedule().passes.size()};
}

template <int Dim>
void expectExactGradientOfALinearField(Float dx) {
    Vector<Dim> a;
    for (int k = 0; k < Dim; ++k) a[k] = 1.5 - k;
    SequentialScheduler sch;
    const Gradients<Dim> g = gradients<Dim>(dx, a, false, sch);
    EXPECT_EQ(g.passes, 2u);
    Float corrected = 0, plain = 0;
    for (std::size_t i = 0; i < g.corrected.size(); ++i) {
        corrected = std::max(corrected, norm(g.corrected[i] - a) / norm(a));
        plain = std::max(plain, norm(g.plain[i] - a) / norm(a));
    }
    // Exact in exact arithmetic; round-off grows with the condition of B near the corners.
    EXPECT_LT(corrected, 1e-10) << "dimension " << Dim;
    // Without the second pass's correction the one-sided sums miss by a large fraction.
    EXPECT_GT(plain, 0.2) << "dimension " << Dim;
}

TEST(TwoPasses, TheCorrectedGradientOfALinearFieldIsExactOnADisorderedCloud) {
    expectExactGradientOfALinearField<2>(0.05);
    expectExactGradientOfALinearField<3>(0.1);
}

template <class T>
bool bitwiseEqual(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(TwoPasses, TheSameResultWhateverTheOrderAddedTheThreadsOrTheLoop) {
    const Vector<2> a{{0.7, -2.0}};
    SequentialScheduler one;
    ThreadPoolScheduler two(2);
    const auto reference = gradients<2>(0.05, a, true, one);
    const auto reversed = gradients<2>(0.05, a, false, one);
    const auto threads = gradients<2>(0.05, a, false, two);
    EXPECT_TRUE(bitwiseEqual(reference.corrected, reversed.corrected));
    EXPECT_TRUE(bitwiseEqual(reference.corrected, threads.corrected));
    // The symmetric loop sums in another order: equal to round-off.
    const auto symmetric = gradients<2>(0.05, a, false, two, "symmetric");
    for (std::size_t i = 0; i < reference.corrected.size(); ++i)
        EXPECT_LT(norm(symmetric.corrected[i] - reference.corrected[i]), 1e-11) << i;
}

/// Shepard's sum sum_j V_j W_ij, a derivative that needs kernel values, into SHEPARD.
const QuantityId SHEPARD = QuantityId(-40);
template <int Dim>
class ShepardSum : public DerivativeTemplate<ShepardSum<Dim>, Dim> {
  public:
    void create(Accumulated<Dim>& r) override { r.template insert<Float>(SHEPARD); }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        std::tie(m_, rho_) = s.template getValues<Float>(QuantityId::MASS, QuantityId::DENSITY);
        sum_ = r.template getValue<Float>(SHEPARD);
    }
    bool needsKernelValues() const override { return true; }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector<Dim>&, const PairGeometry<Dim>& pair) {
        sum_[i] += m_[j] / rho_[j] * pair.w;
        if constexpr (Symmetric) sum_[j] += m_[i] / rho_[i] * pair.w;
    }

  private:
    ArrayView<const Float> m_, rho_;
    ArrayView<Float> sum_;
};

/// Requires ShepardSum; reading `after` (if any) puts it in a later pass.
template <int Dim>
class ShepardTerm : public IEquationTerm<Dim> {
  public:
    explicit ShepardTerm(std::vector<QuantityId> after) : after_(std::move(after)) {}
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings&) override {
        d.template require<ShepardSum<Dim>>();
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(SHEPARD, OrderEnum::ZERO, 0.0);
    }
    TermAccess access() const override { return {.reads = after_}; }

  private:
    std::vector<QuantityId> after_;
};

TEST(TwoPasses, ALaterPassWithKernelValuesGivesWhatTheFirstPassGives) {
    // The first pass needs no kernel values (the gradient correction); the Shepard sum in the
    // second does: it must equal the Shepard sum of a one-pass solver bit for bit.
    using namespace examples;
    const Vector<2> a{{1.0, 0.0}};
    const Float dx = 0.05;
    num::Domain<2> domain;
    domain.max = {{1.0, 1.0}};
    SequentialScheduler sch;
    Material material("cloud");
    auto shepard = [&](EquationHolder<2> equations, std::size_t passes) {
        Storage<2> s = cloudWithLinearField<2>(dx, a);
        Solver<2> solver(sch, settingsFor<2>(dx), std::move(equations), domain);
        EXPECT_EQ(solver.schedule().passes.size(), passes);
        solver.create(s, material);
        solver.evaluate(s, 0);
        const auto sum = s.getValue<Float>(SHEPARD);
        return std::vector<Float>(sum.begin(), sum.end());
    };
    const auto one = shepard(makeTerm<ShepardTerm<2>>(std::vector<QuantityId>{}), 1);
    const auto two = shepard(
        makeTerm<GradientCorrection<2>>() + makeTerm<ShepardTerm<2>>(std::vector<QuantityId>{
                                                correctionId(CorrectionId::CORRECTION_ROW, 0)}),
        2);
    EXPECT_TRUE(bitwiseEqual(one, two));
    EXPECT_GT(*std::min_element(one.begin(), one.end()), 0.2);  // every particle has neighbours
}

/// Per particle: the largest relative deviation of PairGeometry's shared factors from their
/// definitions, dx . grad W / (r^2 + 0.001 h^2) and 1 / (r^2 + 0.01 h^2) (FACTOR_ERROR), and the
/// number of pairs seen (PAIRS_SEEN).
const QuantityId FACTOR_ERROR = QuantityId(-41), PAIRS_SEEN = QuantityId(-42);
template <int Dim>
class PairFactorCheck : public DerivativeTemplate<PairFactorCheck<Dim>, Dim> {
  public:
    explicit PairFactorCheck(Float h) : h_(h) {}
    void create(Accumulated<Dim>& r) override {
        r.template insert<Float>(FACTOR_ERROR), r.template insert<Float>(PAIRS_SEEN);
    }
    void initialize(const Storage<Dim>&, Accumulated<Dim>& r) override {
        error_ = r.template getValue<Float>(FACTOR_ERROR);
        seen_ = r.template getValue<Float>(PAIRS_SEEN);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector<Dim>& grad, const PairGeometry<Dim>& pair) {
        const Float r2 = pair.r * pair.r;
        const Float laplacian = dot(pair.dx, grad) / (r2 + defaults::laplacianEta2 * h_ * h_);
        const Float inverseR2 = 1 / (r2 + defaults::inverseR2Eta2 * h_ * h_);
        const Float e = std::max(std::abs(pair.laplacian / laplacian - 1),
                                 std::abs(pair.inverseR2 / inverseR2 - 1));
        error_[i] = std::max(error_[i], e), seen_[i] += 1;
        if constexpr (Symmetric) error_[j] = std::max(error_[j], e), seen_[j] += 1;
    }

  private:
    Float h_;
    ArrayView<Float> error_, seen_;
};

template <int Dim>
class PairFactorTerm : public IEquationTerm<Dim> {
  public:
    void setDerivatives(DerivativeHolder<Dim>& d, const RunSettings& settings) override {
        d.template require<PairFactorCheck<Dim>>(settings.get<double>("smoothing_length"));
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler&, Storage<Dim>&, Float) override {}
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(FACTOR_ERROR, OrderEnum::ZERO, 0.0);
        s.template insert<Float>(PAIRS_SEEN, OrderEnum::ZERO, 0.0);
    }
};

TEST(PairGeometry, SharedFactorsAreTheirDefinitionsInBothLoops) {
    // The factors are computed once per pair by the solver; every term reads them instead of
    // dividing. They must equal their definitions to round-off (a few units in the last place).
    const Float dx = 0.05;
    num::Domain<2> domain;
    domain.max = {{1.0, 1.0}};
    SequentialScheduler sch;
    Material material("cloud");
    for (const char* evaluation : {"asymmetric", "symmetric"}) {
        SCOPED_TRACE(evaluation);
        Storage<2> s = cloudWithLinearField<2>(dx, Vector<2>{{1.0, 0.0}});
        Solver<2> solver(sch, settingsFor<2>(dx, evaluation), makeTerm<PairFactorTerm<2>>(),
                         domain);
        solver.create(s, material);
        solver.evaluate(s, 0);
        const auto error = s.getValue<Float>(FACTOR_ERROR);
        const auto seen = s.getValue<Float>(PAIRS_SEEN);
        EXPECT_LT(*std::max_element(error.begin(), error.end()), 1e-14);
        EXPECT_GT(*std::min_element(seen.begin(), seen.end()), 2.0);  // every particle has pairs
    }
}

template <int Dim>
void expectPairLoopKernelFormsEqualTheKernels() {
    for (std::size_t index = 0; index < std::tuple_size_v<decltype(kernelTable)>; ++index)
        withKernel<Dim>(KernelType{index}, [&](auto kernel) {
            using Kernel = decltype(kernel);
            SCOPED_TRACE(typeName(kernel));
            const Float h = 0.013;
            const KernelValue<Kernel> value(h);
            const GradientFactor<Kernel> gradient(h);
            const Float support = Kernel::supportRadius(h);
            // q = r / h there, r (1 / h) here, one rounding apart. The splines' derivatives
            // cancel terms at small q and the Wendland (1 - q/2)^3 near the support radius, so
            // the round-off is judged on the factor's scale: 1e-13 of its largest value.
            Float largest = 0;
            for (int k = 0; k < 1000; ++k)
                largest = std::max(largest, std::abs(Kernel::gradFactor(support * k / 1000.0, h)));
            for (int k = 0; k < 1000; ++k) {
                const Float r = support * k / 1000.0;
                EXPECT_EQ(value.value(r), Kernel::W(r, h)) << "r = " << r;
                EXPECT_LE(std::abs(gradient.factor(r) - Kernel::gradFactor(r, h)), 1e-13 * largest)
                    << "r = " << r;
            }
            for (const Float r : {support, std::nextafter(support, 1.0), 2 * support}) {
                EXPECT_EQ(value.value(r), 0.0);
                EXPECT_LE(std::abs(gradient.factor(r)), 1e-13 * largest);
            }
        });
}

TEST(PairGeometry, ThePairLoopsBranchFreeKernelFormsAreTheKernels) {
    // The pair loop computes W and (1/r) dW/dr without branches, so that its loops vectorise:
    // W bitwise Kernel::W and 0 from the support radius on, the gradient factor within
    // round-off of Kernel::gradFactor, for every kernel.
    expectPairLoopKernelFormsEqualTheKernels<2>();
    expectPairLoopKernelFormsEqualTheKernels<3>();
}

}  // namespace
