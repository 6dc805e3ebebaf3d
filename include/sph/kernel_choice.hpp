// The kernel of a run, chosen by name at run time (sph/kernel_table.hpp) and dispatched once into
// templated loops.
#pragma once

#include <string>

#include "sph/defaults.hpp"
#include "sph/kernel_table.hpp"
#include "sph/settings.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// A kernel of kernelTable, by its position there.
struct KernelType {
    std::size_t index;
    friend bool operator==(KernelType, KernelType) = default;
};

inline KernelType kernelFromName(const std::string& name) {
    return {chooseIndex(kernelTable, "kernel", name)};
}

/// The default kernel (defaults::kernel), checked against the table when compiled.
inline constexpr KernelType defaultKernel{*choiceIndex(kernelTable, defaults::kernel)};

/// Calls f(Kernel{}) with the kernel type for `type`; f is instantiated for every kernel.
template <int Dim, class F>
decltype(auto) withKernel(KernelType type, F&& f) {
    return withChoice(kernelTable, type.index, [&](auto entry) {
        return f(typename decltype(entry)::template type<Dim>{});
    });
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
