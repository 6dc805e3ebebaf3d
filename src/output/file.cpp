#include "app/file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace num::app {

namespace {
std::string explain(int error) {
    std::string s = std::strerror(error);
    if (error == ENOSPC) s += " (the disk is full: free some space or choose another --out)";
    if (error == EACCES || error == EROFS || error == EPERM)
        s += " (choose a writable directory with --out)";
    return s;
}
}  // namespace

OutFile::OutFile(const std::string& path) : path_(path), tmp_(path + ".tmp") {
    f_ = std::fopen(tmp_.c_str(), "wb");
    if (!f_) fail("cannot create the file", errno);
}

OutFile::~OutFile() {
    if (!f_) return;
    std::fclose(f_);
    std::remove(tmp_.c_str());  // never completed: the old file (if any) stays
}

void OutFile::fail(const std::string& what, int error) {
    if (f_) std::fclose(f_), f_ = nullptr;
    std::remove(tmp_.c_str());
    throw AppError(ExitCode::OUTPUT, path_ + ": " + what + ": " + explain(error));
}

void OutFile::write(const void* data, std::size_t bytes) {
    if (bytes && std::fwrite(data, 1, bytes, f_) != bytes) fail("write failed", errno);
}

void OutFile::close(bool sync) {
    if (!f_) return;
    if (std::fflush(f_) != 0) fail("write failed", errno);
    if (sync && ::fsync(fileno(f_)) != 0 && errno != EINVAL) fail("write failed", errno);
    std::FILE* f = f_;
    f_ = nullptr;
    if (std::fclose(f) != 0) {
        const int e = errno;
        std::remove(tmp_.c_str());
        throw AppError(ExitCode::OUTPUT, path_ + ": write failed: " + explain(e));
    }
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) {
        const int e = errno;
        std::remove(tmp_.c_str());
        throw AppError(ExitCode::OUTPUT, path_ + ": cannot replace the file: " + explain(e));
    }
}

void writeFileAtomically(const std::string& path, std::string_view content, bool sync) {
    OutFile out(path);
    out.write(content);
    out.close(sync);
}

void appendToFile(const std::string& path, std::string_view text) {
    std::FILE* f = std::fopen(path.c_str(), "ab");
    if (!f) throw AppError(ExitCode::OUTPUT, path + ": cannot open the file: " + explain(errno));
    const long before = std::ftell(f);
    const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    const bool flushed = written && std::fflush(f) == 0;
    const int e = errno;
    if (!flushed && before >= 0) (void)::ftruncate(fileno(f), before);  // no half a line
    const bool closed = std::fclose(f) == 0;
    if (!flushed || !closed)
        throw AppError(ExitCode::OUTPUT, path + ": write failed: " + explain(flushed ? errno : e));
}

void makeOutputDirectory(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw AppError(ExitCode::OUTPUT,
                       dir + ": cannot create the output directory: " +
                           (ec ? ec.message() : std::string("a file of that name exists")) +
                           " (choose another with --out)");
    if (::access(dir.c_str(), W_OK) != 0)
        throw AppError(ExitCode::OUTPUT,
                       dir + ": the output directory is not writable: " + explain(errno));
}

OutputLock::OutputLock(const std::string& dir) {
    const std::string path = dir + "/" + kOutputLockName;
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
        throw AppError(
            ExitCode::OUTPUT,
            path + ": cannot create the output directory's lock file: " + explain(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int e = errno;
        if (e != EWOULDBLOCK) return;  // no locks on this file system: go on without
        std::string holder;
        std::getline(std::ifstream(path), holder);
        ::close(fd_);
        fd_ = -1;
        throw AppError(ExitCode::OUTPUT,
                       dir + ": the output directory is in use by another run" +
                           (holder.empty() ? std::string() : " (process " + holder + ")") +
                           ", which writes its files there now: give this run another --out, or "
                           "wait until that run ends");
    }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, pid.data(), pid.size(), 0);
}

OutputLock::~OutputLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
}

}  // namespace num::app
