// A volumetric heat source as a plugin: the fluid inside a box receives the power density q:
//     dT_i/dt += q V_i / (m_i c_i)   for fluid particles i with x_i in the box,
// c_i the heat capacity of the particle's material and V_i = 1 / sum_j W_ij its volume from the
// kernel sum (the particle number density of Hu & Adams 2006, J. Comput. Phys. 213, 844): a
// pairwise sum, written on DerivativeTemplate. The heat put in per unit time is
// sum_i q V_i ~ q * (volume of the box), the energy balance its tests check. The power of each
// particle, q V_i [W], is the field "heat_source_power" a scene may write out.
#include <tuple>

#include "app/plugin.hpp"
#include "numerics.hpp"

namespace {

using namespace num::sph;

/// Quantities of this plugin (negative ids are free for users).
constexpr auto KERNEL_SUM = QuantityId(-30);
constexpr auto HEAT_SOURCE_POWER = QuantityId(-31);

/// sum_{j != i} W_ij, each pair written once for both particles in symmetric mode.
template <int Dim>
class KernelSum : public DerivativeTemplate<KernelSum<Dim>, Dim> {
  public:
    bool needsKernelValues() const override { return true; }
    void create(Accumulated<Dim>& results) override {
        results.template insert<Float>(KERNEL_SUM, OrderEnum::ZERO);
    }
    void initialize(const Storage<Dim>&, Accumulated<Dim>& results) override {
        sum_ = results.template getValue<Float>(KERNEL_SUM);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector<Dim>&, const PairGeometry<Dim>& pair) {
        sum_[i] += pair.w;
        if constexpr (Symmetric) sum_[j] += pair.w;
    }

  private:
    ArrayView<Float> sum_;
};

template <int Dim>
class HeatSource : public IEquationTerm<Dim> {
  public:
    /// q [W/m^3] in the box [lo, hi].
    HeatSource(Float q, Vector<Dim> lo, Vector<Dim> hi) : q_(q), lo_(lo), hi_(hi) {}

    void setDerivatives(DerivativeHolder<Dim>& derivatives, const RunSettings& settings) override {
        derivatives.template require<KernelSum<Dim>>();
        w0_ = RunKernel<Dim>(settings).W(0);  // the particle's own term of its kernel sum
    }
    void initialize(IScheduler&, Storage<Dim>&, Float) override {}
    void finalize(IScheduler& scheduler, Storage<Dim>& s, Float) override {
        const auto x = s.template getValue<Vector<Dim>>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        const auto material = s.template getValue<int>(QuantityId::MATERIAL);
        const auto [m, sum, power] =
            s.template getValues<Float>(QuantityId::MASS, KERNEL_SUM, HEAT_SOURCE_POWER);
        const auto dT = s.template getDt<Float>(QuantityId::TEMPERATURE);
        std::vector<Float> c;
        for (const auto& mat : s.materials())
            c.push_back(mat->params().template get<double>("heat_capacity"));
        scheduler.parallelFor(s.size(), 4096, [&](Size begin, Size end) {
            for (Size i = begin; i < end; ++i) {
                power[i] =
                    kind[i] == int(ParticleKind::FLUID) && inside(x[i]) ? q_ / (w0_ + sum[i]) : 0.0;
                dT[i] += power[i] / (m[i] * c[material[i]]);  // add: other terms write dT too
            }
        });
    }
    void create(Storage<Dim>& s, IMaterial&) const override {
        s.template insert<Float>(QuantityId::TEMPERATURE, OrderEnum::FIRST, 0.0);  // evolves
        s.template insert<Float>(KERNEL_SUM, OrderEnum::ZERO, 0.0);
        s.template insert<Float>(HEAT_SOURCE_POWER, OrderEnum::ZERO, 0.0);
    }

  private:
    bool inside(const Vector<Dim>& x) const {
        for (int k = 0; k < Dim; ++k)
            if (x[k] < lo_[k] || x[k] > hi_[k]) return false;
        return true;
    }
    Float q_, w0_ = 0;
    Vector<Dim> lo_, hi_;
};

/// Reads {"power_density": q, "min": [...], "max": [...]} for Dim.
template <int Dim>
auto readHeatSource(const num::app::plugin::Parameters& p) {
    p.allow({"power_density", "min", "max"});
    const auto lo = p.vector<Dim>("min", "m"), hi = p.vector<Dim>("max", "m");
    for (int k = 0; k < Dim; ++k)
        if (!(hi[k] > lo[k])) p.fail("max", "max > min on every axis");
    return std::tuple{p.number("power_density", -1e12, 1e12, "W/m^3"), lo, hi};
}

}  // namespace

NUMERICS_PLUGIN(registry) {
    registry.addOne<HeatSource<2>>("heat_source", readHeatSource<2>);
    registry.addOne<HeatSource<3>>("heat_source", readHeatSource<3>);
    registry.addField("heat_source_power", HEAT_SOURCE_POWER);
}
