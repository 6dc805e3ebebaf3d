// The processes of one run and the messages between them: MPI (MPI_COMM_WORLD) when the program
// was built with MPI and started by an MPI launcher (mpirun), one process otherwise. The rest of
// numerics sees this class only, never MPI itself; with one process every call is a copy.
//
// Every call is collective: all processes make the same calls in the same order. Reductions are
// exact (minimum, maximum, integer sums, logical or), so their results never depend on the
// number of processes.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace num::parallel {

using Bytes = std::vector<char>;

class Communicator {
  public:
    /// Joins the run's processes: MPI_Init_thread (threads funnelled through the main one) when
    /// built with MPI and an MPI launcher started the program (its environment says so), else
    /// one process. Throws std::runtime_error when a launcher started several processes of a
    /// build without MPI. Create one, in main, before any thread starts.
    Communicator(int& argc, char**& argv);
    /// One process, whatever the environment (tests, library users).
    Communicator();
    ~Communicator();  // MPI_Finalize when this object initialised MPI
    Communicator(const Communicator&) = delete;
    Communicator& operator=(const Communicator&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool isRoot() const { return rank_ == 0; }
    /// Whether this build can run on several processes (built with MPI).
    static bool mpiAvailable();

    double minimum(double v) const;
    double maximum(double v) const;
    std::int64_t sum(std::int64_t v) const;
    bool any(bool v) const;

    /// Sends toEach[r] to process r (toEach has size() entries) and returns what each process
    /// sent to this one, by rank.
    std::vector<Bytes> exchange(const std::vector<Bytes>& toEach) const;
    /// Every process's bytes, by rank, on every process.
    std::vector<Bytes> allGather(const Bytes& mine) const;
    /// Every process's bytes, by rank, on the root (process 0); empty elsewhere.
    std::vector<Bytes> gatherToRoot(const Bytes& mine) const;
    /// The root's bytes on every process.
    Bytes broadcast(const Bytes& fromRoot) const;
    void barrier() const;

    /// Ends every process at once with this exit code (an error one process cannot share).
    [[noreturn]] void abort(int code) const;

  private:
    int rank_ = 0, size_ = 1;
    bool usesMpi_ = false;         // the calls go through MPI (MPI_COMM_WORLD)
    bool initialisedMpi_ = false;  // this object called MPI_Init_thread
};

}  // namespace num::parallel
