// Checkpoints: a self-describing binary file (magic, format version, dimension, payload size,
// CRC-32 of the payload), written atomically. The payload holds the scene text, the run state
// and every quantity of the storage at every derivative level, so that a restart continues
// bitwise as the uninterrupted run would.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "app/errors.hpp"
#include "sph/storage.hpp"

namespace num::app {

/// Format version: 2 added the run's fingerprint, 3 the count of emitter points left out, 4 the
/// moving bodies' states, 5 the books of the inlets and outlets.
inline constexpr std::uint32_t kCheckpointVersion = 5;

/// Appends plain values, strings and vectors to a byte buffer.
class ByteWriter {
  public:
    template <class T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        const char* p = reinterpret_cast<const char*>(&v);
        bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
    void putString(const std::string& s) {
        put<std::uint64_t>(s.size());
        bytes_.insert(bytes_.end(), s.begin(), s.end());
    }
    template <class T>
    void putVector(const std::vector<T>& v) {
        put<std::uint64_t>(v.size());
        const char* p = reinterpret_cast<const char*>(v.data());
        bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
    }
    const std::string& bytes() const { return bytes_; }

  private:
    std::string bytes_;
};

/// Reads what ByteWriter wrote; running past the end is an AppError (CHECKPOINT).
class ByteReader {
  public:
    ByteReader(const std::string& bytes, std::string file)
        : bytes_(bytes), file_(std::move(file)) {}
    template <class T>
    T get() {
        T v;
        std::memcpy(&v, take(sizeof(T)), sizeof(T));
        return v;
    }
    std::string getString() {
        const auto n = get<std::uint64_t>();
        return std::string(take(n), n);
    }
    template <class T>
    std::vector<T> getVector() {
        const auto n = get<std::uint64_t>();
        if (n > bytes_.size()) fail();
        std::vector<T> v(n);
        if (n) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
        return v;
    }
    bool atEnd() const { return pos_ == bytes_.size(); }
    const std::string& file() const { return file_; }

  private:
    const char* take(std::size_t n) {
        if (n > bytes_.size() - pos_) fail();
        const char* p = bytes_.data() + pos_;
        pos_ += n;
        return p;
    }
    [[noreturn]] void fail() const {
        throw AppError(ExitCode::CHECKPOINT,
                       file_ +
                           ": the checkpoint's content is inconsistent (written by another "
                           "version?); it cannot be used");
    }
    const std::string& bytes_;
    std::string file_;
    std::size_t pos_ = 0;
};

/// A checkpoint's bytes: header (with the payload's size and checksum) + payload.
std::string checkpointBytes(int dimension, const std::string& payload);
/// Writes header + payload to `path` atomically.
void writeCheckpointFile(const std::string& path, int dimension, const std::string& payload);
/// Reads and checks a checkpoint (exists, magic, version, dimension, size, CRC) and returns its
/// payload; every failure is an AppError (CHECKPOINT) saying what is wrong.
std::string readCheckpointFile(const std::string& path, int dimension);
/// The same checks on a checkpoint's bytes (header + payload) already in memory; `path` names it.
std::string checkpointPayload(const std::string& bytes, const std::string& path, int dimension);

/// Every quantity with its order, type and all levels.
template <int Dim>
void writeStorage(ByteWriter& w, const sph::Storage<Dim>& s);
/// The storage written by writeStorage; the material table comes from `materials`.
template <int Dim>
sph::Storage<Dim> readStorage(ByteReader& r, const sph::Storage<Dim>& materials);

}  // namespace num::app
