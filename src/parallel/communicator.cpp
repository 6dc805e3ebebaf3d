// The processes of one run: the only file of numerics that names MPI. Built with MPI when the
// compile definition NUMERICS_HAVE_MPI is set (CMake: NUMERICS_WITH_MPI and MPI found); without
// it every call is the one-process copy.
#include "parallel/communicator.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#ifdef NUMERICS_HAVE_MPI
#include <mpi.h>
#endif

namespace num::parallel {

namespace {

/// An integer environment variable, or -1 when it is absent or not a number.
long envInteger(const char* name) {
    const char* text = std::getenv(name);
    if (text == nullptr || *text == '\0') return -1;
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    return (end != nullptr && *end == '\0' && value >= 0) ? value : -1;
}

/// What the environment says about an MPI launcher: whether one started this program, and how
/// many processes it started (-1 when it does not say; more than one when a rank above 0 shows).
struct Launch {
    bool launched = false;
    long processes = -1;
};

Launch launchFromEnvironment() {
    Launch launch;
    // Open MPI (mpirun, mpiexec), MPICH and Intel MPI (hydra), PMIx launchers (srun, prterun).
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        const long n = envInteger(name);
        if (n >= 0) launch.launched = true;
        if (n > launch.processes) launch.processes = n;
    }
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}) {
        const long r = envInteger(name);
        if (r >= 0) launch.launched = true;
        if (r >= 1 && launch.processes < r + 1) launch.processes = r + 1;
    }
    return launch;
}

#ifdef NUMERICS_HAVE_MPI

[[noreturn]] void tooLarge(const char* call) {
    throw std::runtime_error(std::string("Communicator::") + call +
                             ": more than 2 GiB (INT_MAX bytes) in one message or in all of "
                             "one process's messages of a call, which MPI counts cannot hold");
}

/// Displacements (in bytes) of blocks of these sizes laid end to end; false when the total does
/// not fit an MPI count (int).
bool displacements(const std::vector<std::int64_t>& counts, std::vector<int>& intCounts,
                   std::vector<int>& displs) {
    intCounts.assign(counts.size(), 0);
    displs.assign(counts.size(), 0);
    std::int64_t total = 0;
    for (std::size_t i = 0; i < counts.size(); ++i) {
        if (counts[i] < 0 || counts[i] > INT_MAX || total > INT_MAX) return false;
        intCounts[i] = int(counts[i]);
        displs[i] = int(total);
        total += counts[i];
    }
    return total <= INT_MAX;
}

std::vector<Bytes> split(const Bytes& all, const std::vector<int>& counts,
                         const std::vector<int>& displs) {
    std::vector<Bytes> parts(counts.size());
    for (std::size_t i = 0; i < counts.size(); ++i)
        parts[i].assign(all.begin() + displs[i], all.begin() + displs[i] + counts[i]);
    return parts;
}

/// Every process's count of bytes as MPI counts and displacements; throws on every process alike
/// when the whole does not fit an MPI count (each has every count).
void countsOfAll(std::int64_t count, int processes, std::vector<int>& counts,
                 std::vector<int>& displs, const char* call) {
    std::vector<std::int64_t> all(static_cast<std::size_t>(processes));
    MPI_Allgather(&count, 1, MPI_INT64_T, all.data(), 1, MPI_INT64_T, MPI_COMM_WORLD);
    if (!displacements(all, counts, displs)) tooLarge(call);
}

bool mpiRunning() {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    return initialised && !finalised;
}

#endif

}  // namespace

Communicator::Communicator() = default;

Communicator::Communicator([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
    const Launch launch = launchFromEnvironment();
#ifdef NUMERICS_HAVE_MPI
    // MPI only when a launcher started the program (or someone initialised it already): a
    // program started without mpirun never touches MPI (no singleton initialisation).
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!launch.launched && !initialised) return;
    if (!initialised) {
        int provided = MPI_THREAD_SINGLE;
        MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
        initialisedMpi_ = true;
        if (provided < MPI_THREAD_FUNNELED)
            std::fprintf(stderr,
                         "warning: the MPI library gives no MPI_THREAD_FUNNELED support; numerics "
                         "calls MPI from the main thread only, with worker threads running\n");
    }
    usesMpi_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
    if (launch.processes > 1)
        throw std::runtime_error(
            "an MPI launcher (mpirun) started " + std::to_string(launch.processes) +
            " processes, but this build of numerics has no MPI: install libopenmpi-dev and "
            "rebuild, or run without mpirun");
#endif
}

Communicator::~Communicator() {
#ifdef NUMERICS_HAVE_MPI
    if (initialisedMpi_ && mpiRunning()) MPI_Finalize();
#endif
}

bool Communicator::mpiAvailable() {
#ifdef NUMERICS_HAVE_MPI
    return true;
#else
    return false;
#endif
}

#ifdef NUMERICS_HAVE_MPI
namespace {
/// The reduction `op` of every process's v.
template <class T>
T allReduce(T v, MPI_Datatype type, MPI_Op op) {
    T r = v;
    MPI_Allreduce(&v, &r, 1, type, op, MPI_COMM_WORLD);
    return r;
}
}  // namespace
#endif

double Communicator::minimum(double v) const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) return allReduce(v, MPI_DOUBLE, MPI_MIN);
#endif
    return v;
}

double Communicator::maximum(double v) const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) return allReduce(v, MPI_DOUBLE, MPI_MAX);
#endif
    return v;
}

std::int64_t Communicator::sum(std::int64_t v) const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) return allReduce(v, MPI_INT64_T, MPI_SUM);
#endif
    return v;
}

bool Communicator::any(bool v) const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) return allReduce(int(v), MPI_INT, MPI_LOR) != 0;
#endif
    return v;
}

std::vector<Bytes> Communicator::exchange(const std::vector<Bytes>& toEach) const {
    if (toEach.size() != std::size_t(size_))
        throw std::invalid_argument("Communicator::exchange: " + std::to_string(toEach.size()) +
                                    " messages for " + std::to_string(size_) + " processes");
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) {
        std::vector<std::int64_t> sendCounts(size_), recvCounts(size_);
        for (int r = 0; r < size_; ++r) sendCounts[r] = std::int64_t(toEach[r].size());
        MPI_Alltoall(sendCounts.data(), 1, MPI_INT64_T, recvCounts.data(), 1, MPI_INT64_T,
                     MPI_COMM_WORLD);
        std::vector<int> sc, sd, rc, rd;
        const bool fits = displacements(sendCounts, sc, sd) && displacements(recvCounts, rc, rd);
        // Every process learns of a too large message before any throws, so none waits forever.
        if (any(!fits)) tooLarge("exchange");
        Bytes send(std::size_t(sd.back()) + std::size_t(sc.back()));
        for (int r = 0; r < size_; ++r)
            std::copy(toEach[r].begin(), toEach[r].end(), send.begin() + sd[r]);
        Bytes recv(std::size_t(rd.back()) + std::size_t(rc.back()));
        MPI_Alltoallv(send.data(), sc.data(), sd.data(), MPI_BYTE, recv.data(), rc.data(),
                      rd.data(), MPI_BYTE, MPI_COMM_WORLD);
        return split(recv, rc, rd);
    }
#endif
    return toEach;
}

std::vector<Bytes> Communicator::allGather(const Bytes& mine) const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) {
        const std::int64_t count = std::int64_t(mine.size());
        std::vector<int> rc, rd;
        countsOfAll(count, size_, rc, rd, "allGather");
        Bytes recv(std::size_t(rd.back()) + std::size_t(rc.back()));
        MPI_Allgatherv(mine.data(), int(count), MPI_BYTE, recv.data(), rc.data(), rd.data(),
                       MPI_BYTE, MPI_COMM_WORLD);
        return split(recv, rc, rd);
    }
#endif
    return {mine};
}

std::vector<Bytes> Communicator::gatherToRoot(const Bytes& mine) const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) {
        // The counts go to every process (not only the root), so that all of them know whether
        // the root could hold the whole and throw together when it could not.
        const std::int64_t count = std::int64_t(mine.size());
        std::vector<int> rc, rd;
        countsOfAll(count, size_, rc, rd, "gatherToRoot");
        Bytes recv(isRoot() ? std::size_t(rd.back()) + std::size_t(rc.back()) : 0);
        MPI_Gatherv(mine.data(), int(count), MPI_BYTE, recv.data(), rc.data(), rd.data(), MPI_BYTE,
                    0, MPI_COMM_WORLD);
        if (!isRoot()) return {};
        return split(recv, rc, rd);
    }
#endif
    return {mine};
}

Bytes Communicator::broadcast(const Bytes& fromRoot) const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) {
        std::int64_t count = isRoot() ? std::int64_t(fromRoot.size()) : 0;
        MPI_Bcast(&count, 1, MPI_INT64_T, 0, MPI_COMM_WORLD);
        if (count > INT_MAX) tooLarge("broadcast");
        Bytes data = isRoot() ? fromRoot : Bytes(std::size_t(count));
        MPI_Bcast(data.data(), int(count), MPI_BYTE, 0, MPI_COMM_WORLD);
        return data;
    }
#endif
    return fromRoot;
}

void Communicator::barrier() const {
#ifdef NUMERICS_HAVE_MPI
    if (usesMpi_) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

void Communicator::abort(int code) const {
#ifdef NUMERICS_HAVE_MPI
    if (mpiRunning()) {
        MPI_Abort(MPI_COMM_WORLD, code);
    }
#endif
    std::exit(code);
}

}  // namespace num::parallel
