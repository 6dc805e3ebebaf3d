// Every call of the process communicator on the processes the test was started on: one without a
// launcher, several under mpiexec (ctest: parallel.communicator.np3). Results are exact, so the
// expectations hold for any number of processes.
//
// Every process runs the same tests in the same order. No assertion returns from a test before
// its last collective call (EXPECT, not ASSERT), so a failure on one process never leaves the
// others waiting; ctest's TIMEOUT guards against hangs all the same.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"

using num::parallel::Bytes;
using num::parallel::Communicator;

namespace {

using num::parallel::testing::world;

/// The message from process `from` to process `to`: its size depends on both (empty for some
/// pairs, among them every process to itself when its rank is even; 1 MiB from 1 to 0), its
/// bytes encode both.
Bytes message(int from, int to) {
    std::size_t size = std::size_t(3 * from + 7 * to) % 11 * 97;
    if (from % 2 == 0 && from == to) size = 0;
    if (from == 1 && to == 0) size = std::size_t(1) << 20;
    Bytes m(size);
    for (std::size_t i = 0; i < size; ++i) m[i] = char((from * 31 + to * 17 + int(i)) % 251);
    return m;
}

TEST(Communicator, RankAndSize) {
    const Communicator& c = *world;
    EXPECT_GE(c.size(), 1);
    EXPECT_GE(c.rank(), 0);
    EXPECT_LT(c.rank(), c.size());
    EXPECT_EQ(c.isRoot(), c.rank() == 0);
    EXPECT_EQ(Communicator::mpiAvailable(), bool(NUMERICS_TEST_EXPECT_MPI));
    // Under a launcher, a build with MPI has as many processes as the launcher started.
    if (const char* n = std::getenv("OMPI_COMM_WORLD_SIZE"); n && Communicator::mpiAvailable()) {
        EXPECT_EQ(c.size(), std::atoi(n));
    }
    // Ranks are distinct and cover 0 .. size-1.
    EXPECT_EQ(c.sum(1), c.size());
    const std::int64_t n = c.size();
    EXPECT_EQ(c.sum(c.rank()), n * (n - 1) / 2);
    EXPECT_EQ(c.sum(std::int64_t(c.rank()) * c.rank()), (n - 1) * n * (2 * n - 1) / 6);
}

TEST(Communicator, Reductions) {
    const Communicator& c = *world;
    const int n = c.size(), r = c.rank();
    EXPECT_EQ(c.minimum(r), 0.0);
    EXPECT_EQ(c.maximum(r), double(n - 1));
    EXPECT_EQ(c.minimum(-0.25 * r), -0.25 * (n - 1));
    EXPECT_EQ(c.maximum(-0.25 * r - 1.0), -1.0);
    EXPECT_EQ(c.minimum(1e300), 1e300);
    // Sums of 64-bit integers beyond 32 bits, exact.
    const std::int64_t big = std::int64_t(1) << 40;
    EXPECT_EQ(c.sum(big * (r + 1) + 1), big * std::int64_t(n) * (n + 1) / 2 + n);
    EXPECT_EQ(c.sum(-big), -big * n);
    EXPECT_TRUE(c.any(r == n - 1));
    EXPECT_TRUE(c.any(r == 0));
    EXPECT_TRUE(c.any(true));
    EXPECT_FALSE(c.any(false));
    EXPECT_FALSE(c.any(r == n));
}

TEST(Communicator, Exchange) {
    const Communicator& c = *world;
    const int n = c.size();
    std::vector<Bytes> toEach(n);
    for (int to = 0; to < n; ++to) toEach[to] = message(c.rank(), to);
    const std::vector<Bytes> got = c.exchange(toEach);
    EXPECT_EQ(got.size(), std::size_t(n));
    for (int from = 0; from < n && from < int(got.size()); ++from)
        EXPECT_EQ(got[from], message(from, c.rank())) << "from " << from << " to " << c.rank();

    // Nothing at all to send.
    const std::vector<Bytes> none = c.exchange(std::vector<Bytes>(n));
    EXPECT_EQ(none, std::vector<Bytes>(n));

    // A wrong number of messages is refused on every process, before any message moves.
    EXPECT_THROW(c.exchange(std::vector<Bytes>(n + 1)), std::invalid_argument);
}

TEST(Communicator, AllGather) {
    const Communicator& c = *world;
    const int n = c.size();
    const std::vector<Bytes> got = c.allGather(message(c.rank(), 1));
    EXPECT_EQ(got.size(), std::size_t(n));
    for (int from = 0; from < n && from < int(got.size()); ++from)
        EXPECT_EQ(got[from], message(from, 1)) << "from " << from;

    const std::vector<Bytes> empty = c.allGather({});
    EXPECT_EQ(empty, std::vector<Bytes>(n));
}

TEST(Communicator, GatherToRoot) {
    const Communicator& c = *world;
    const int n = c.size();
    const std::vector<Bytes> got = c.gatherToRoot(message(c.rank(), 2));
    if (c.isRoot()) {
        EXPECT_EQ(got.size(), std::size_t(n));
        for (int from = 0; from < n && from < int(got.size()); ++from)
            EXPECT_EQ(got[from], message(from, 2)) << "from " << from;
    } else {
        EXPECT_TRUE(got.empty());
    }
}

TEST(Communicator, Broadcast) {
    const Communicator& c = *world;
    // Other processes pass bytes of their own, of another size: only the root's count.
    const Bytes mine = c.isRoot() ? message(5, 6) : message(c.rank(), 3);
    EXPECT_EQ(c.broadcast(mine), message(5, 6));
    EXPECT_EQ(c.broadcast(c.isRoot() ? Bytes{} : Bytes{'x'}), Bytes{});
    c.barrier();
}

TEST(Communicator, DefaultIsOneProcess) {
    // Whatever the environment and however many processes run: one process, every call a copy.
    const Communicator one;
    EXPECT_EQ(one.rank(), 0);
    EXPECT_EQ(one.size(), 1);
    EXPECT_TRUE(one.isRoot());
    EXPECT_EQ(one.minimum(2.5), 2.5);
    EXPECT_EQ(one.maximum(-2.5), -2.5);
    EXPECT_EQ(one.sum(-7), -7);
    EXPECT_TRUE(one.any(true));
    EXPECT_FALSE(one.any(false));
    const Bytes m = message(1, 0);
    EXPECT_EQ(one.exchange({m}), std::vector<Bytes>{m});
    EXPECT_EQ(one.allGather(m), std::vector<Bytes>{m});
    EXPECT_EQ(one.gatherToRoot(m), std::vector<Bytes>{m});
    EXPECT_EQ(one.broadcast(m), m);
    EXPECT_THROW(one.exchange({m, m}), std::invalid_argument);
    one.barrier();
}

}  // namespace

int main(int argc, char** argv) { return num::parallel::testing::runTests(argc, argv); }
