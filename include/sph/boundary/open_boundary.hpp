// An open side: no particles; fluid that crosses it leaves the run, removed after the step
// (the post-step sink) and counted (removed_particles in summary.json). A tank's top, usually.
#pragma once

#include "sph/boundary/side_boundary.hpp"

namespace num::sph {

template <int Dim>
class OpenBoundary : public ISideBoundary<Dim> {
  public:
    const char* type() const override { return "open"; }
    void build(FluidGeometry<Dim>&, int, int) const override {}
    /// Fluid beyond the side's plane.
    void markLeaving(const Storage<Dim>& s, int axis, int high, Float bound,
                     std::vector<char>& leaving) const override {
        const auto x = s.template getValue<Vector<Dim>>(QuantityId::POSITION);
        const auto kind = s.template getValue<int>(QuantityId::KIND);
        for (Size i = 0; i < s.size(); ++i)
            if (isFluid(kind[i]) && (high ? x[i][axis] > bound : x[i][axis] < bound))
                leaving[i] = 1;
    }
    bool letsFluidOut() const override { return true; }
};

}  // namespace num::sph
