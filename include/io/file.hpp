// Output files that report every failure (permissions, a full disk) as an AppError with exit
// code OUTPUT, and atomic replacement (write a temporary file, flush to disk, rename).
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "io/errors.hpp"

namespace num::io {

class OutFile {
  public:
    /// Opens `path` for writing (truncating it).
    explicit OutFile(const std::string& path);
    ~OutFile();
    OutFile(const OutFile&) = delete;
    OutFile& operator=(const OutFile&) = delete;

    void write(const void* data, std::size_t bytes);
    void write(std::string_view text) { write(text.data(), text.size()); }
    /// Flushes to the disk (fsync) and closes; throws on any failure.
    void close(bool sync = false);
    const std::string& path() const { return path_; }

  private:
    [[noreturn]] void fail(const std::string& what, int error);
    std::string path_;
    std::FILE* f_ = nullptr;
};

/// Writes `content` to `path` atomically: a reader sees the old file or the new one, never a
/// partial one.
void writeFileAtomically(const std::string& path, std::string_view content);

/// Creates a directory and its parents; an AppError (OUTPUT) when it cannot, or when it is not
/// writable.
void makeOutputDirectory(const std::string& dir);

}  // namespace num::io
