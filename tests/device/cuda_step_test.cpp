// The device step on the GPU (the CUDA execution of src/cuda/) against the same step on the host
// execution (label gpu). Exits 77 (ctest: skipped) with the reason where the build has no CUDA
// back end or there is no GPU. Checks, on a 2D and a 3D dam break: one evaluation's every array
// agrees to round-off (the GPU's pow, sqrt and division are the host's to the last bit or two);
// a run of 40 steps stays close to the host's; two GPU runs are bitwise identical.
#include <cstdio>
#include <memory>

#include "device/backend.hpp"
#include "device/fluid_run.hpp"
#include "device_test_case.hpp"

#ifdef NUMERICS_HAVE_CUDA
namespace {

using namespace num;
using namespace num::sph;
using device::ParticleArrays;

int failures = 0;

template <int Dim>
struct Case {
    FluidModel<Dim> model;
    FluidGeometry<Dim> geometry;
    RunSettings settings;
};

template <int Dim>
Case<Dim> damBreak() {
    Case<Dim> c;
    const double dx = Dim == 2 ? 0.01 : 0.04;
    c.geometry.spacing = dx;
    for (int k = 0; k < Dim; ++k) c.geometry.domain.min[k] = 0, c.geometry.domain.max[k] = 0.8;
    c.geometry.domain.max[Dim - 1] = 0.6;
    Vector<Dim> hi = c.geometry.domain.max;
    hi[0] = 0.32, hi[Dim - 1] = 0.32;
    c.geometry.fluid.push_back(
        FluidRegion<Dim>::filling(BoxOrBall<Dim>::box(c.geometry.domain.min, hi)));
    device_tests::setDamBreakNumerics(c.model, c.settings, dx);
    return c;
}

template <class V>
double size(const V& v) {
    if constexpr (std::is_arithmetic_v<V>)
        return std::abs(double(v));
    else
        return norm(v);
}

template <class V>
void expectClose(const char* what, const std::vector<V>& a, const std::vector<V>& b,
                 double relative) {
    double largest = 0, difference = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        largest = std::max(largest, size(b[i]));
        difference = std::max(difference, size(a[i] - b[i]));
    }
    const bool ok = a.size() == b.size() && difference <= relative * largest;
    std::printf("  %s %s: largest difference %.3g of %.3g (tolerance %.1g)\n", ok ? "ok  " : "FAIL",
                what, difference, largest, relative);
    failures += !ok;
}

template <class V>
void expectSame(const char* what, const std::vector<V>& a, const std::vector<V>& b) {
    std::size_t differ = a.size() == b.size() ? 0 : 1;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) differ += !(a[i] == b[i]);
    std::printf("  %s %s: %zu particles differ\n", differ ? "FAIL" : "ok  ", what, differ);
    failures += differ != 0;
}

template <int Dim>
void check() {
    std::printf("%dD dam break:\n", Dim);
    const Case<Dim> c = damBreak<Dim>();
    const auto config = device::makeFluidStepConfig(c.model, c.geometry, c.settings);
    const Storage<Dim> storage = makeFluidStorage(c.model, c.geometry, c.settings);
    const ParticleArrays<Dim> start = device::particleArrays(storage);
    {
        device::HostFluidStep<Dim> host(config);
        auto gpu = device::makeCudaFluidStep<Dim>(config);
        host.upload(start), gpu->upload(start);
        for (double t : {0.0, 0.01}) host.evaluate(t), gpu->evaluate(t);
        ParticleArrays<Dim> a, b;
        gpu->download(a), host.download(b);
        std::printf("  %zu particles, %zu bytes on the GPU\n", a.size(), gpu->bytes());
        expectSame("positions", a.x, b.x);
        expectClose("pressure", a.p, b.p, 1e-12);
        expectClose("density", a.rho, b.rho, 1e-12);
        expectClose("acceleration", a.a, b.a, 1e-10);
        expectClose("density rate", a.drho, b.drho, 1e-10);
        expectClose("kernel sum", a.kernelSum, b.kernelSum, 1e-12);
        expectClose("kernel sum gradient", a.kernelSumGradient, b.kernelSumGradient, 1e-10);
        expectClose("wall velocity", a.pairVelocity, b.pairVelocity, 1e-10);
    }
    auto runOf = [&](bool onGpu, int steps) {
        std::unique_ptr<device::IDeviceFluid<Dim>> step;
        if (onGpu)
            step = device::makeCudaFluidStep<Dim>(config);
        else
            step = std::make_unique<device::HostFluidStep<Dim>>(config);
        device::DeviceRun<Dim> run(std::move(step), config);
        run.upload(storage, false);
        for (int k = 0; k < steps; ++k) run.step();
        ParticleArrays<Dim> p;
        run.fluid().download(p);
        return p;
    };
    const int steps = 40;
    const ParticleArrays<Dim> g1 = runOf(true, steps), g2 = runOf(true, steps),
                              h = runOf(false, steps);
    expectSame("two GPU runs: positions", g1.x, g2.x);
    expectSame("two GPU runs: velocities", g1.v, g2.v);
    expectSame("two GPU runs: densities", g1.rho, g2.rho);
    expectClose("GPU run against host run: velocities", g1.v, h.v, 1e-6);
    expectClose("GPU run against host run: densities", g1.rho, h.rho, 1e-9);
}

}  // namespace
#endif

int main() {
#ifndef NUMERICS_HAVE_CUDA
    std::printf("skipped: this build has no CUDA back end\n");
    return 77;
#else
    if (const std::string why = num::device::cudaUnavailable(); !why.empty()) {
        std::printf("skipped: no GPU: %s\n", why.c_str());
        return 77;
    }
    std::printf("GPU: %s\n", num::device::cudaDeviceName().c_str());
    check<2>();
    check<3>();
    std::printf(failures ? "FAILED\n" : "PASSED\n");
    return failures ? 1 : 0;
#endif
}
