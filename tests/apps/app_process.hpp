// An app started in the background, for tests that signal it while it runs: its output goes to
// a file, and every wait is a hang guard (generous bounds that fail a hung app, never a timing
// measurement: a waiting loop returns as soon as its condition holds).
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "app_runner.hpp"

namespace apptest {

/// Polls `done` every 10 ms until it holds (true) or `guardSeconds` passed (false).
inline bool waitFor(const std::function<bool()>& done, double guardSeconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(guardSeconds);
    while (!done()) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return true;
}

class AppProcess {
  public:
    /// Starts `program args...` in `dir` with `env` ("NAME=value") added; stdout and stderr go
    /// to `dir`/output.txt.
    AppProcess(const std::string& program, const std::vector<std::string>& args,
               const std::string& dir, const std::vector<std::string>& env = {})
        : log_(dir + "/output.txt") {
        pid_ = ::fork();
        if (pid_ != 0) return;
        if (::chdir(dir.c_str()) != 0) ::_exit(126);
        const int fd = ::open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0) ::_exit(126);
        ::dup2(fd, 1), ::dup2(fd, 2);
        for (const std::string& e : env) ::putenv(const_cast<char*>(e.c_str()));
        std::vector<char*> argv{const_cast<char*>(program.c_str())};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
    AppProcess(const AppProcess&) = delete;
    AppProcess& operator=(const AppProcess&) = delete;
    /// A process still running at the end of a test (a failed one) is killed.
    ~AppProcess() {
        if (running()) ::kill(pid_, SIGKILL), ::waitpid(pid_, &status_, 0);
    }

    pid_t pid() const { return pid_; }
    std::string output() const { return readFile(log_); }
    bool running() {
        if (exited_) return false;
        exited_ = ::waitpid(pid_, &status_, WNOHANG) == pid_;
        return !exited_;
    }
    /// Waits for the exit under a hang guard; false when the process still runs after it.
    bool waitForExit(double guardSeconds) {
        return waitFor([&] { return !running(); }, guardSeconds);
    }
    /// The exit code, or -(signal) for a process ended by a signal.
    int code() const { return WIFEXITED(status_) ? WEXITSTATUS(status_) : -WTERMSIG(status_); }
    /// Whether the program has installed a handler of `sig` (from /proc/PID/status, SigCgt).
    bool catches(int sig) const {
        const std::string status = readFile("/proc/" + std::to_string(pid_) + "/status");
        const auto p = status.find("SigCgt:");
        if (p == std::string::npos) return false;
        const unsigned long long mask = std::stoull(status.substr(p + 7), nullptr, 16);
        return (mask >> (sig - 1)) & 1;
    }

  private:
    std::string log_;
    pid_t pid_ = -1;
    int status_ = 0;
    bool exited_ = false;
};

}  // namespace apptest
