// The kernel of a run, chosen by name at run time and dispatched once into templated loops.
#pragma once

#include <string>

#include "spatial/kernels.hpp"
#include "sph/settings.hpp"
#include "sph/types.hpp"

namespace num::sph {

enum class KernelType { CUBIC_SPLINE, WENDLAND_C2, WENDLAND_C4, QUINTIC_SPLINE };

inline KernelType kernelFromName(const std::string& name) {
    if (name == "cubic_spline") return KernelType::CUBIC_SPLINE;
    if (name == "wendland_c2") return KernelType::WENDLAND_C2;
    if (name == "wendland_c4") return KernelType::WENDLAND_C4;
    if (name == "quintic_spline") return KernelType::QUINTIC_SPLINE;
    throw SettingsError("unknown kernel '" + name +
                        "' (expected cubic_spline, wendland_c2, wendland_c4 or quintic_spline)");
}

/// Calls f(Kernel{}) with the kernel type for `type`; f is instantiated for every kernel.
template <int Dim, class F>
decltype(auto) withKernel(KernelType type, F&& f) {
    switch (type) {
        case KernelType::CUBIC_SPLINE:
            return f(kernels::CubicSpline<Dim, Float>{});
        case KernelType::WENDLAND_C4:
            return f(kernels::WendlandC4<Dim, Float>{});
        case KernelType::QUINTIC_SPLINE:
            return f(kernels::QuinticSpline<Dim, Float>{});
        default:
            return f(kernels::WendlandC2<Dim, Float>{});
    }
}

/// The run's kernel with its smoothing length, for per-particle (not per-pair) use.
template <int Dim>
struct RunKernel {
    KernelType type;
    Float h;

    explicit RunKernel(const RunSettings& s)
        : type(kernelFromName(s.get<std::string>("kernel"))),
          h(s.get<double>("smoothing_length")) {}

    Float W(Float r) const {
        return withKernel<Dim>(type, [&](auto k) { return k.W(r, h); });
    }
    Float dW_dr(Float r) const {
        return withKernel<Dim>(type, [&](auto k) { return k.dW_dr(r, h); });
    }
    Float supportRadius() const {
        return withKernel<Dim>(type, [&](auto k) { return k.supportRadius(h); });
    }
};

}  // namespace num::sph
