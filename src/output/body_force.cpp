#include "output/body_force.hpp"

#include "sph/defaults.hpp"
#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/terms/fluid_quantities.hpp"

namespace num::io {

namespace {

/// The storage's values one pair reads (fluid i, body particle j).
template <int Dim>
struct PairFields {
    using Vec = sph::Vector<Dim>;
    sph::ArrayView<const double> m, rho, p, nu;
    sph::ArrayView<const Vec> v;
    sph::ArrayView<const int> slip;

    explicit PairFields(const sph::Storage<Dim>& s) {
        using sph::QuantityId;
        m = s.template getValue<double>(QuantityId::MASS);
        rho = s.template getValue<double>(QuantityId::DENSITY);
        p = s.template getValue<double>(QuantityId::PRESSURE);
        v = s.template getValue<Vec>(sph::FluidId::PAIR_VELOCITY);
        if (s.has(sph::FluidId::KINEMATIC_VISCOSITY))
            nu = s.template getValue<double>(sph::FluidId::KINEMATIC_VISCOSITY);
        if (s.has(sph::FluidId::WALL_SLIP))
            slip = s.template getValue<int>(sph::FluidId::WALL_SLIP);
    }
};

}  // namespace

template <int Dim>
std::vector<typename BodyForces<Dim>::Vec> BodyForces<Dim>::operator()(
    const sph::Storage<Dim>& s) const {
    namespace f = sph::formulas;
    using sph::QuantityId;
    std::vector<Vec> force(targets_, Vec{});
    const auto x = s.template getValue<Vec>(QuantityId::POSITION);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const PairFields<Dim> q(s);
    const double h = kernel_.h, support = kernel_.supportRadius();
    const double laplacianEta2 = sph::defaults::laplacianEta2 * h * h;
    const double inverseR2Eta2 = sph::defaults::inverseR2Eta2 * h * h;
    CellGrid<Dim> grid;
    grid.build(x, support, domain_);
    for (sph::Size j = 0; j < s.size(); ++j) {
        if (sph::isFluid(kind[j])) continue;
        const int b = targetOf_(kind[j], x[j]);
        if (b < 0 || b >= targets_) continue;
        const bool noSlip = q.slip.empty() || q.slip[j] == int(sph::WallSlip::NO_SLIP);
        const double pr2j = f::pressureOverDensity2(q.p[j], q.rho[j]);
        grid.forEachNeighbour(x[j], [&](sph::Size i, const Vec& dxji, double r2) {
            if (!sph::isFluid(kind[i]) || r2 <= 0) return;
            const Vec dx = -dxji;  // x_i - x_j
            const double r = std::sqrt(r2);
            const Vec grad = dx * (kernel_.dW_dr(r) / r);
            Vec a =
                -f::pressureGradientForce(grad, f::pressureOverDensity2(q.p[i], q.rho[i]), pr2j) *
                q.m[j];
            if (!q.nu.empty() && noSlip) {
                const double factor = f::laminarViscosityFactor(
                    f::dynamicViscosity(q.rho[i], q.nu[i]), f::dynamicViscosity(q.rho[j], q.nu[j]),
                    f::pairLaplacian(dx, grad, r, laplacianEta2));
                a += f::laminarViscosityAcceleration(q.v[i] - q.v[j], factor, q.m[j] / q.rho[j],
                                                     1.0 / q.rho[i]);
            }
            const double vr = f::approachRate(q.v[i], q.v[j], dx);
            if (alphaC0h_ > 0 && vr < 0)
                a -= grad *
                     f::artificialViscosityPi(alphaC0h_, vr, f::pairInverseR2(r, inverseR2Eta2),
                                              q.rho[i], q.rho[j]) *
                     q.m[j];
            force[b] -= a * q.m[i];
        });
    }
    return force;
}

template class BodyForces<2>;
template class BodyForces<3>;

}  // namespace num::io
