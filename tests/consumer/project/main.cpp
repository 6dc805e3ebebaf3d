// A user program of numerics: evaluates the seed kernel and computes a density by summation
// over particles held in num::sph::Storage. Exits non-zero if a value is wrong.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "numerics.hpp"

int main() {
    using num::sph::OrderEnum;
    using num::sph::QuantityId;
    using Vector = num::sph::Vector<2>;

    // Three particles on a line, spacing dx, equal masses.
    const double dx = 0.01, h = 1.3 * dx, mass = 1000.0 * dx * dx;
    std::vector<Vector> positions(3);
    for (int k = 0; k < 3; ++k) positions[k][0] = k * dx;

    num::sph::Storage<2> storage;
    storage.insert<Vector>(QuantityId::POSITION, OrderEnum::SECOND, positions);
    storage.insert<double>(QuantityId::MASS, OrderEnum::ZERO, mass);
    storage.insert<double>(QuantityId::DENSITY, OrderEnum::ZERO, 0.0);

    // Density summation rho_i = sum_j m_j W(|x_i - x_j|, h) with the seed kernel (float).
    auto x = storage.getValue<Vector>(QuantityId::POSITION);
    auto m = storage.getValue<double>(QuantityId::MASS);
    auto rho = storage.getValue<double>(QuantityId::DENSITY);
    for (std::size_t i = 0; i < storage.size(); ++i) {
        for (std::size_t j = 0; j < storage.size(); ++j) {
            const float r = float(num::norm(x[i] - x[j]));
            rho[i] += m[j] * num::SPHKernel<2>::W(r, float(h));
        }
    }

    const double w0 = num::SPHKernel<2>::W(0.0f, float(h));
    const double expectedW0 = 10.0 / (7.0 * std::numbers::pi * h * h);
    const bool ok = storage.size() == 3 && std::abs(w0 - expectedW0) < 1e-6 * expectedW0 &&
                    rho[1] > rho[0] && std::abs(rho[0] - rho[2]) < 1e-9 * rho[0];
    std::printf(
        "numerics consumer: %u particles, W(0, h) = %.6g (expected %.6g), rho = %.6g %.6g "
        "%.6g: %s\n",
        unsigned(storage.size()), w0, expectedW0, rho[0], rho[1], rho[2], ok ? "ok" : "WRONG");
    return ok ? 0 : 1;
}
