// Progress of a run: one rewritten line on a terminal (simulated time, percent, dt, particles,
// ETA), plain lines every few seconds otherwise, nothing when quiet.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "app/formatted.hpp"

namespace num::app {

class Progress {
  public:
    enum class Mode { TERMINAL, PLAIN, QUIET };

    Progress(Mode mode, double startTime, double endTime)
        : mode_(mode), t0_(startTime), t1_(endTime), start_(Clock::now()), last_(start_) {}

    /// Reports the state after a step; throttled to a few updates per second (terminal) or one
    /// line every 10 s (plain).
    void update(double t, double dt, std::size_t particles, std::size_t steps) {
        if (mode_ == Mode::QUIET) return;
        const auto now = Clock::now();
        const double sinceLast = seconds(last_, now);
        if (sinceLast < (mode_ == Mode::TERMINAL ? 0.25 : 10.0)) return;
        last_ = now;
        print(t, dt, particles, steps, now);
    }
    /// Ends the progress line.
    void finish(double t, double dt, std::size_t particles, std::size_t steps) {
        if (mode_ == Mode::QUIET) return;
        print(t, dt, particles, steps, Clock::now());
        if (mode_ == Mode::TERMINAL) std::fputc('\n', stdout);
        std::fflush(stdout);
    }
    /// Clears a terminal line before other text is printed.
    void clearLine() const {
        if (mode_ == Mode::TERMINAL) std::fputs("\r\033[K", stdout);
    }

  private:
    using Clock = std::chrono::steady_clock;
    static double seconds(Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double>(b - a).count();
    }
    void print(double t, double dt, std::size_t particles, std::size_t steps,
               Clock::time_point now) {
        const double frac = t1_ > t0_ ? (t - t0_) / (t1_ - t0_) : 1.0;
        const double elapsed = seconds(start_, now);
        const double eta = frac > 1e-6 ? elapsed * (1 - frac) / frac : 0.0;
        const std::string line = formatted(
            "t = %.4f s / %.4g s  %5.1f %%  step %zu  dt = %.3g s  %zu particles  "
            "elapsed %.0f s  ETA %.0f s",
            t, t1_, 100 * frac, steps, dt, particles, elapsed, eta);
        std::printf(mode_ == Mode::TERMINAL ? "\r\033[K%s" : "%s\n", line.c_str());
        std::fflush(stdout);
    }

    Mode mode_;
    double t0_, t1_;
    Clock::time_point start_, last_;
};

}  // namespace num::app
