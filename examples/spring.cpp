// Spring example: particles on harmonic springs, x(t) = A cos(sqrt(k/m) t), integrated with
// the kick-drift-kick leapfrog through the solver in 2D and 3D. Exits with 1 if the error after
// ten periods exceeds 1% of the amplitude (the leapfrog phase error is about
// omega^3 dt^2 t / 24 = 0.7% of A here, with omega dt = 0.05).
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "numerics.hpp"
#include "spring_force.hpp"

template <int Dim>
double runSprings() {
    using namespace num::sph;
    using Vec = Vector<Dim>;
    const Float k = 4.0, m = 1.0, omega = std::sqrt(k / m);
    // Ten and a quarter periods: the particles pass the origin, where the phase error shows.
    const Float periods = 10.25, tEnd = periods * 2 * std::numbers::pi / omega;

    // One particle per axis, displaced by A = 1 + axis along that axis, at rest.
    std::vector<Vec> x(Dim);
    for (int d = 0; d < Dim; ++d) x[d][d] = 1.0 + d;
    Storage<Dim> storage;
    storage.template insert<Vec>(QuantityId::POSITION, OrderEnum::SECOND, x);
    storage.template insert<Float>(QuantityId::MASS, OrderEnum::ZERO, m);

    RunSettings settings;
    settings.set("smoothing_length", 1.0);  // only the neighbour search uses it here
    SequentialScheduler scheduler;
    Solver<Dim> solver(scheduler, settings, makeTerm<examples::SpringForce<Dim>>(k),
                       num::Domain<Dim>{});
    Material material;
    solver.create(storage, material);
    LeapfrogKDK<Dim> leapfrog;
    Run<Dim> run(storage, solver, leapfrog);
    std::string criterion;
    while (run.time() < tEnd * (1 - 1e-14)) {
        run.step(tEnd);
        if (run.limitingCriterion() != "end time") criterion = run.limitingCriterion();
    }

    double maxError = 0;
    const auto xs = storage.template getValue<Vec>(QuantityId::POSITION);
    const auto vs = storage.template getDt<Vec>(QuantityId::POSITION);
    for (int d = 0; d < Dim; ++d) {
        // Particles may have been reordered by cell: each moves along its own axis only.
        for (Size i = 0; i < storage.size(); ++i) {
            int axis = 0;
            for (int c = 1; c < Dim; ++c)
                if (std::abs(xs[i][c]) + std::abs(vs[i][c]) >
                    std::abs(xs[i][axis]) + std::abs(vs[i][axis]))
                    axis = c;
            if (axis != d) continue;
            const double amplitude = 1.0 + d;
            const double exact = amplitude * std::cos(omega * run.time());
            maxError = std::max(maxError, std::abs(xs[i][d] - exact) / amplitude);
        }
    }
    std::printf("%dD: %u leapfrog steps (limited by %s), max error %.3e of the amplitude\n", Dim,
                run.steps(), criterion.c_str(), maxError);
    return maxError;
}

int main() {
    const double e2 = runSprings<2>();
    const double e3 = runSprings<3>();
    return e2 < 0.01 && e3 < 0.01 ? 0 : 1;
}
