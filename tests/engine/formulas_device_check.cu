// Compile check: every formula header compiles for a CUDA device and each of its functions is
// callable from a kernel (the test formulas_nvcc compiles this file with nvcc; it is not run).
#include "spatial/kernels.hpp"
#include "sph/formulas/equation_of_state.hpp"
#include "sph/formulas/fluid_pairs.hpp"
#include "sph/formulas/fluid_particles.hpp"
#include "sph/formulas/heat_pairs.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/formulas/post_step.hpp"
#include "sph/formulas/wall_condition.hpp"

namespace {

using namespace num::sph;
using namespace num::sph::formulas;

template <int Dim>
__global__ void everyFormula(const double* in, double* out,
                             GradientFactor<num::kernels::CubicSpline<Dim>> gradient,
                             KernelValue<num::kernels::WendlandC2<Dim>> kernelValue,
                             EquationOfState eos, ViscosityOfTemperature viscosity) {
    using Vec = Vector<Dim>;
    const Vec dx = Vec::filled(in[0]), vi = Vec::filled(in[1]), vj = Vec::filled(in[2]);
    const double r = norm(dx), h = in[3];
    const Vec grad = dx * gradient.factor(r);
    const PairGeometry<Dim> pair{dx, r, kernelValue.value(r),
                                 pairLaplacian(dx, grad, r, 1e-3 * h * h),
                                 pairInverseR2(r, 1e-2 * h * h)};
    double s =
        num::kernels::CubicSpline<Dim>::W(r, h) + num::kernels::QuinticSpline<Dim>::dW_dr(r, h) +
        num::kernels::WendlandC4<Dim>::dW_dh(r, h) + num::kernels::Spiky<Dim>::gradFactor(r, h) +
        num::kernels::WendlandC2<Dim>::gradW(dx, h)[0];
    s += continuityRate(in[4], in[5], continuityDivergence(vi, vj, grad));
    s +=
        deltaSphFlux(deltaSphCoefficient(0.1, 10.0, h), in[4], in[6], vi, dx, grad, pair.inverseR2);
    s += pressureGradientForce(grad, pressureOverDensity2(in[7], in[4]), in[8])[0];
    s += artificialViscosityPi(0.1, num::hd::min(approachRate(vi, vj, dx), 0.0), pair.inverseR2,
                               in[4], in[6]);
    s += laminarViscosityAcceleration(
        vi - vj, laminarViscosityFactor(dynamicViscosity(in[4], 1e-6), in[9], pair.laplacian),
        in[5], 1.0 / in[4])[0];
    s += kernelSumWeight(in[5], pair.w) + summationDensityTerm(in[12], pair.w);
    s += (grad * shiftingTensileFactor(pair.w, in[10], in[11]))[0] +
         densityGradientTerm(grad, in[5], in[6])[0] +
         velocityGradientTerm(vj - vi, in[5], grad[0])[0];
    s += heatRate(in[12],
                  heatExchange(0.6, 0.5, in[4], in[6], conductionTemperature(1, in[1], in[2]),
                               in[2], pair.laplacian),
                  in[13]);
    s += conductsHeat(0, 2) ? 1.0 : 0.0;
    const double rho = surfaceDensityFloor(in[4], 990.0);
    const double p = surfacePressureFloor(fluidPressure(eos, rho, -1e5), 0.0);
    s += p + rho + eos.density(p) + power(in[4], 7.0) + particleVolume(in[12], in[4]);
    s += atFreeSurface(in[5], in[5], in[6]) ? 1.0 : 0.0;
    s += viscosity(in[1], 1e-6, 20.0, 1000.0);
    s += shiftingDisplacement(grad, vi, 1e-3, 0.1 * h, false)[0] + particleSpacing<Dim>(in[5]);
    s += deltaSphGravityTerm(vj, 1000.0, 10.0)[0];
    Vec a = boussinesqAcceleration(vi, 2e-4, in[1], 20.0);
    addBodyForce(a, vj);
    WallSums<Dim> sums;
    sums.add(in[7], in[4], vi, in[1], true, dx, pair.w);
    if (sums.any())
        s += wallPressure(sums, vj) + wallVelocity(sums, vi, true)[0] +
             wallTemperature(sums, in[1], true);
    Vec x = vi, v = vj;  // containment: the box's walls and a body (a ball)
    containInWalls(x[0], v[0], 0.0, 1.0, true, true);
    BoxOrBall<Dim> ball;
    ball.type = BoxOrBall<Dim>::Type::BALL, ball.center = dx, ball.radius = 0.1;
    containOutsideBody<Dim>(x, v, ball);
    s += x[0] + v[0];
    out[0] = s + a[0];
}

template __global__ void everyFormula<2>(const double*, double*,
                                         GradientFactor<num::kernels::CubicSpline<2>>,
                                         KernelValue<num::kernels::WendlandC2<2>>, EquationOfState,
                                         ViscosityOfTemperature);
template __global__ void everyFormula<3>(const double*, double*,
                                         GradientFactor<num::kernels::CubicSpline<3>>,
                                         KernelValue<num::kernels::WendlandC2<3>>, EquationOfState,
                                         ViscosityOfTemperature);

}  // namespace
