// The domain decomposition against a brute-force oracle, on as many processes as mpiexec starts
// (one without it): every particle is owned by exactly one process, and each owned particle's
// neighbours found in its process's storage (owned particles and halo copies) are exactly those
// of a search over all particles, in the single-process order. Checked after distribution,
// after small moves (halo copies refreshed in place) and after a move that redistributes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "mpi_test_main.hpp"
#include "parallel/domain_decomposition.hpp"
#include "spatial/neighbour_list.hpp"

namespace {

using num::parallel::Communicator;
using num::sph::QuantityId;
using num::sph::Size;

using num::parallel::testing::world;

template <int Dim>
struct Cloud {
    using Vec = num::sph::Vector<Dim>;
    num::Domain<Dim> domain;
    double radius = 0.1;
    num::sph::Storage<Dim> all;

    /// Particles on a jittered lattice, denser in one corner (an uneven load), periodic along x.
    Cloud() {
        domain.min = Vec::filled(0), domain.max = Vec::filled(1);
        domain.max[Dim - 1] = 0.6;
        domain.periodic[0] = true;
        std::mt19937 random(7);
        std::uniform_real_distribution<double> unit(0, 1);
        std::vector<Vec> x;
        const int n = Dim == 2 ? 1500 : 2500;
        for (int k = 0; k < n; ++k) {
            Vec p;
            for (int d = 0; d < Dim; ++d) {
                const double u = unit(random);
                p[d] = domain.min[d] + (k % 3 == 0 ? u * u : u) * domain.length(d);
            }
            x.push_back(p);
        }
        all.template insert<Vec>(QuantityId::POSITION, num::sph::OrderEnum::SECOND, x);
        all.template insert<double>(QuantityId::DENSITY, num::sph::OrderEnum::ZERO, 1000.0);
        num::sph::ensureParticleIds(all);
        num::sph::reorderByKey(all, domain, radius);
    }

    /// Moves every particle by a displacement that is a function of its id (as an integrator
    /// moves owners and their copies alike), at most `step`.
    static void move(num::sph::Storage<Dim>& s, double step, const num::Domain<Dim>& domain) {
        auto x = s.template getValue<Vec>(QuantityId::POSITION);
        const auto id = s.template getValue<int>(QuantityId::PARTICLE_ID);
        for (Size i = 0; i < s.size(); ++i) {
            Vec dx;
            for (int d = 0; d < Dim; ++d) dx[d] = std::sin(1.7 * id[i] + d) * step / std::sqrt(Dim);
            x[i] = domain.wrap(x[i] + dx);
        }
    }

    /// id -> the ids of its neighbours within the radius, in storage order, over all particles.
    std::map<int, std::vector<int>> oracle() const {
        const auto x = all.template getValue<Vec>(QuantityId::POSITION);
        const auto id = all.template getValue<int>(QuantityId::PARTICLE_ID);
        std::map<int, std::vector<int>> out;
        for (Size i = 0; i < all.size(); ++i)
            for (Size j = 0; j < all.size(); ++j)
                if (j != i && normSqr(domain.minimumImage(x[i] - x[j])) < radius * radius)
                    out[id[i]].push_back(id[j]);
        return out;
    }

    /// Checks the owned particles of `local` against the oracle; returns how many it owns.
    int check(const num::parallel::DomainDecomposition<Dim>& dd,
              const num::sph::Storage<Dim>& local) const {
        const std::map<int, std::vector<int>> expected = oracle();
        const auto x = local.template getValue<Vec>(QuantityId::POSITION);
        const auto id = local.template getValue<int>(QuantityId::PARTICLE_ID);
        num::VerletList<Dim> list;
        list.configure(radius, 0.1, domain);
        list.update(x);
        typename num::VerletList<Dim>::Neighbours found;
        int owned = 0, wrong = 0;
        for (Size i = 0; i < local.size(); ++i) {
            if (!dd.owned()[i]) continue;
            ++owned;
            const Size m = list.collect(i, found);
            std::vector<int> ids;
            for (Size k = 0; k < m; ++k) ids.push_back(id[found.j[k]]);
            const auto it = expected.find(id[i]);
            const std::vector<int> want = it == expected.end() ? std::vector<int>{} : it->second;
            wrong += ids != want;
        }
        EXPECT_EQ(wrong, 0) << "owned particles whose neighbours differ from the oracle";
        return owned;
    }
};

template <int Dim>
void checkDecomposition() {
    const Communicator& comm = *world;
    Cloud<Dim> cloud;
    num::parallel::DomainDecomposition<Dim> dd(comm, cloud.domain, cloud.radius);
    num::sph::Storage<Dim> local = cloud.all;
    dd.distribute(local);
    EXPECT_EQ(comm.sum(cloud.check(dd, local)), std::int64_t(cloud.all.size()));
    if (comm.size() > 1) {
        EXPECT_GT(comm.sum(dd.haloParticles()), 0);
        EXPECT_LE(dd.imbalance(), 0.05);  // bisection by count: a few particles off the mean
    }

    // Small moves (a tenth of the halo skin): the copies are refreshed, the halo kept.
    const double skin = cloud.radius * num::parallel::DomainDecomposition<Dim>::kHaloSkin;
    for (int step = 0; step < 2; ++step) {
        Cloud<Dim>::move(cloud.all, 0.05 * skin, cloud.domain);
        Cloud<Dim>::move(local, 0.05 * skin, cloud.domain);
        dd.exchangeHalo(local);
        EXPECT_FALSE(dd.beforeStep(local, false, false));
        EXPECT_EQ(comm.sum(cloud.check(dd, local)), std::int64_t(cloud.all.size()));
    }
    // A move of a third of the skin: the particles migrate and the halo is rebuilt.
    Cloud<Dim>::move(cloud.all, 0.33 * skin, cloud.domain);
    Cloud<Dim>::move(local, 0.33 * skin, cloud.domain);
    EXPECT_EQ(dd.beforeStep(local, false, false), comm.size() > 1);
    EXPECT_EQ(comm.sum(cloud.check(dd, local)), std::int64_t(cloud.all.size()));

    // Everything gathered on the root is the whole storage, in its order.
    const num::sph::Storage<Dim> gathered = dd.gatherToRoot(local);
    if (comm.isRoot() && comm.size() > 1) {
        const auto a = gathered.template getValue<int>(QuantityId::PARTICLE_ID);
        const auto b = cloud.all.template getValue<int>(QuantityId::PARTICLE_ID);
        EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end()));
    }
}

TEST(HaloOracle, NeighboursOfEveryOwnedParticle2D) { checkDecomposition<2>(); }
TEST(HaloOracle, NeighboursOfEveryOwnedParticle3D) { checkDecomposition<3>(); }

}  // namespace

int main(int argc, char** argv) { return num::parallel::testing::runTests(argc, argv); }
