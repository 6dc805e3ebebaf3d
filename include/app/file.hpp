// Output files that report every failure (permissions, a full disk) as an AppError with exit
// code OUTPUT, each written whole or not at all (a temporary file, renamed when complete).
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "app/errors.hpp"

namespace num::app {

/// An output file written to `<path>.tmp` and renamed to `path` by close(), so that a reader
/// (and a full disk, a crash or a second Ctrl-C) never leaves a partial file under `path`.
class OutFile {
  public:
    explicit OutFile(const std::string& path);
    /// Without close(): the temporary file is removed and `path` is left as it was.
    ~OutFile();
    OutFile(const OutFile&) = delete;
    OutFile& operator=(const OutFile&) = delete;

    void write(const void* data, std::size_t bytes);
    void write(std::string_view text) { write(text.data(), text.size()); }
    /// Flushes (to the disk with `sync`), closes and renames; throws on any failure.
    void close(bool sync = false);
    const std::string& path() const { return path_; }

  private:
    [[noreturn]] void fail(const std::string& what, int error);
    std::string path_, tmp_;
    std::FILE* f_ = nullptr;
};

/// Writes `content` to `path` atomically: a reader sees the old file or the new one, never a
/// partial one.
void writeFileAtomically(const std::string& path, std::string_view content, bool sync = true);

/// Appends `text` (whole lines) to `path`; on a failure the file is cut back to its old length,
/// so it never ends in part of a line.
void appendToFile(const std::string& path, std::string_view text);

/// Creates a directory and its parents; an AppError (OUTPUT) when it cannot, or when it is not
/// writable.
void makeOutputDirectory(const std::string& dir);

/// The name of the lock file in an output directory.
inline constexpr const char* kOutputLockName = ".numerics.lock";

/// The lock of an output directory, held while a run writes there: an exclusive flock on
/// `<dir>/.numerics.lock` (which holds the process id and stays when the run ends), so that
/// a second run writing the directory at the same time, in this process or another, is
/// refused (AppError OUTPUT) naming the process that holds it. The lock goes with the process
/// however it ends. On a file system without locks (some network file systems) the run goes
/// on without one.
class OutputLock {
  public:
    explicit OutputLock(const std::string& dir);
    ~OutputLock();
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;

  private:
    int fd_ = -1;
};

}  // namespace num::app
