// The kernels a run may choose (RunSettings "kernel", a scene's particles.kernel): one line each.
// A new kernel is its class (spatial/kernels.hpp, or a header of its own included here) and its
// line in kernelTable; the settings, the scene reader, their error texts and the dispatch
// (sph/kernel_choice.hpp) take it from there.
#pragma once

#include <tuple>

#include "spatial/kernels.hpp"
#include "sph/choice_table.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// A kernel of the table: its name, a line of help and the kernel template (Dim, scalar).
template <template <int, class> class Kernel>
struct KernelChoice {
    std::string_view name, help;
    template <int Dim>
    using type = Kernel<Dim, Float>;
};

inline constexpr std::tuple kernelTable{
    KernelChoice<kernels::CubicSpline>{"cubic_spline", "cubic B-spline M4, support 2h"},
    KernelChoice<kernels::WendlandC2>{"wendland_c2", "Wendland C2, support 2h"},
    KernelChoice<kernels::WendlandC4>{"wendland_c4", "Wendland C4, support 2h"},
    KernelChoice<kernels::QuinticSpline>{"quintic_spline", "quintic B-spline M6, support 3h"},
};

}  // namespace num::sph
