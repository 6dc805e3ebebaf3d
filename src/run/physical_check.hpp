// Unphysical states that stay finite: a weakly-compressible run can throw spray far faster
// than its flow or squeeze particles far from the rest density without any value becoming
// NaN. The check compares every fluid particle with the scales the scene set:
//   speed:   |v| > 3 U warns (U the velocity scale of the sound speed, c0 = 10 U: the Mach
//            number passes 0.3 and density errors pass about 5 %, Monaghan 1994, sec. 3);
//            |v| >= c0 stops the run: supersonic flow is outside the weakly-compressible model;
//   density: |rho / rho0 - 1| > 0.2 warns (the model is built for about 1 %);
//            rho < rho0 / 2 or rho > 2 rho0 stops the run;
//   temperature: any particle (fluid, wall or body) below absolute zero stops the run: a
//            wall's heat flux or a plugin's heat sink drew more heat than the water holds;
//   a plugin's quantity outside the range its plugin declared (Registry::addField) stops it.
// Each kind of warning is reported once, with its time and figures, on the terminal and in
// summary.json; a stop is the app's UNSTABLE error (exit 9), the last good output kept.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "app/errors.hpp"
#include "app/formatted.hpp"
#include "parallel/communicator.hpp"
#include "sph/scheduler.hpp"
#include "sph/storage.hpp"
#include "sph/types.hpp"

namespace num::app {

class PhysicalCheck {
  public:
    /// U: the velocity scale [m/s]; c0: the sound speed [m/s]; rho0: the rest density.
    PhysicalCheck(double U, double c0, double rho0) : U_(U), c0_(c0), rho0_(rho0) {}

    /// Checks the fluid particles at time t; returns a new warning (empty if none) and throws
    /// AppError(UNSTABLE) where the run is lost. With several processes, the extremes are those
    /// of every process (each checks its particles; halo copies equal their owners). The
    /// particles are scanned in chunks on the scheduler's threads; each extreme names the
    /// first particle in storage order that reaches it, as a serial scan would.
    template <int Dim>
    std::string check(const sph::Storage<Dim>& s, double t, const parallel::Communicator& comm,
                      sph::IScheduler& scheduler) {
        checkRanges(s, t, comm);
        const Extremes local = findExtremes(s, scheduler);
        Extremes all = local;
        all.vmax = comm.maximum(local.vmax), all.rhoMin = comm.minimum(local.rhoMin);
        all.rhoMax = comm.maximum(local.rhoMax);
        // Where each extreme particle is: the processes agree on whether to ask, so all take part.
        const auto positions = s.template getValue<sph::Vector<Dim>>(sph::QuantityId::POSITION);
        const Where where{[&, positions](Extreme which) {
            switch (which) {
                case Extreme::FASTEST:
                    return position<Dim>(positions, local.fastest, local.vmax == all.vmax, comm);
                case Extreme::THINNEST:
                    return position<Dim>(positions, local.thinnest, local.rhoMin == all.rhoMin,
                                         comm);
                default:
                    return position<Dim>(positions, local.densest, local.rhoMax == all.rhoMax,
                                         comm);
            }
        }};
        const std::string at = "at t = " + formatted("%.3g", t) + " s ";
        stopIfLost(all, at, where);
        const std::string warning = warnOnce(all, at, where);
        if (!warning.empty()) warnings_.push_back(warning);
        return warning;
    }

    /// The same for a run of one process, on one thread.
    template <int Dim>
    std::string check(const sph::Storage<Dim>& s, double t) {
        const parallel::Communicator one;
        sph::SequentialScheduler serial;
        return check(s, t, one, serial);
    }

    const std::vector<std::string>& warnings() const { return warnings_; }

    /// A quantity with a physical range [lo, hi] (in its unit, named in messages): a value
    /// outside it, on any particle, stops the run.
    struct Range {
        sph::QuantityId id;
        std::string name, unit;
        double lo, hi;
        std::string hint;
    };
    /// Adds a range to those checked; temperature's (above absolute zero) is there from the start.
    void addRange(Range r) { ranges_.push_back(std::move(r)); }

  private:
    /// Stops (UNSTABLE) at the first quantity with a value outside its range, naming the lowest
    /// or highest value over every process.
    template <int Dim>
    void checkRanges(const sph::Storage<Dim>& s, double t, const parallel::Communicator& comm) {
        for (const Range& range : ranges_) {
            double lo = range.lo, hi = range.hi;
            if (s.has(range.id)) {
                const auto q = s.template getValue<double>(range.id);
                for (double x : q) lo = std::min(lo, x), hi = std::max(hi, x);
            }
            lo = comm.minimum(lo), hi = comm.maximum(hi);
            if (lo >= range.lo && hi <= range.hi) continue;
            const bool below = lo < range.lo;
            const std::string unit = range.unit.empty() ? "" : " " + range.unit;
            throw AppError(ExitCode::UNSTABLE,
                           "at t = " + formatted("%.3g", t) + " s a particle's " + range.name +
                               " reached " + formatted("%.6g", below ? lo : hi) + unit + ", " +
                               (below ? "below " : "above ") +
                               formatted("%.6g", below ? range.lo : range.hi) + unit +
                               (range.hint.empty() ? "" : ": " + range.hint));
        }
    }

    /// The fastest, thinnest and densest fluid particles.
    struct Extremes {
        double vmax, rhoMin, rhoMax;
        sph::Size fastest, thinnest, densest;
    };
    enum class Extreme { FASTEST, THINNEST, DENSEST };
    /// " at (x, y) m": where an extreme particle is, on whichever process holds it.
    using Where = std::function<std::string(Extreme)>;

    /// This process's extremes, each at the first particle in storage order that reaches it.
    template <int Dim>
    Extremes findExtremes(const sph::Storage<Dim>& s, sph::IScheduler& scheduler) const {
        const auto v = s.template getDt<sph::Vector<Dim>>(sph::QuantityId::POSITION);
        const auto rho = s.template getValue<double>(sph::QuantityId::DENSITY);
        const auto kind = s.template getValue<int>(sph::QuantityId::KIND);
        const Extremes none{0, rho0_, rho0_, s.size(), s.size(), s.size()};
        return sph::reduceChunks(
            scheduler, s.size(), 8192, none,
            [&](sph::Size b, sph::Size end, Extremes& x) {
                for (sph::Size i = b; i < end; ++i) {
                    if (kind[i] != int(sph::ParticleKind::FLUID)) continue;
                    if (const double speed = norm(v[i]); speed > x.vmax)
                        x.vmax = speed, x.fastest = i;
                    if (rho[i] < x.rhoMin) x.rhoMin = rho[i], x.thinnest = i;
                    if (rho[i] > x.rhoMax) x.rhoMax = rho[i], x.densest = i;
                }
            },
            [](Extremes& x, const Extremes& p) {
                if (p.vmax > x.vmax) x.vmax = p.vmax, x.fastest = p.fastest;
                if (p.rhoMin < x.rhoMin) x.rhoMin = p.rhoMin, x.thinnest = p.thinnest;
                if (p.rhoMax > x.rhoMax) x.rhoMax = p.rhoMax, x.densest = p.densest;
            });
    }

    /// The position held by the lowest rank whose own extreme is the global one (`holds`).
    template <int Dim>
    static std::string position(sph::ArrayView<const sph::Vector<Dim>> r, sph::Size i, bool holds,
                                const parallel::Communicator& comm) {
        parallel::Bytes mine;
        if (holds) {
            const auto* bytes = reinterpret_cast<const char*>(&r[i]);
            mine.assign(bytes, bytes + sizeof(sph::Vector<Dim>));
        }
        for (const parallel::Bytes& b : comm.allGather(mine)) {
            if (b.size() != sizeof(sph::Vector<Dim>)) continue;
            sph::Vector<Dim> x;
            std::memcpy(&x, b.data(), sizeof x);
            std::string text = " at (";
            for (int d = 0; d < Dim; ++d) text += (d ? ", " : "") + formatted("%.3g", x[d]);
            return text + ") m";
        }
        return std::string();
    }

    /// Throws UNSTABLE where the run left the model: supersonic flow or a density off by 2x.
    void stopIfLost(const Extremes& e, const std::string& at, const Where& where) const {
        if (e.vmax >= c0_)
            throw AppError(ExitCode::UNSTABLE,
                           at + "a fluid particle" + where(Extreme::FASTEST) + " moves at " +
                               formatted("%.3g", e.vmax) + " m/s, at or above the sound speed " +
                               formatted("%.3g", c0_) +
                               " m/s: the run left the weakly-compressible model; raise the "
                               "material's sound_speed or physics.max_speed, or lower time.cfl");
        if (e.rhoMin < 0.5 * rho0_ || e.rhoMax > 2 * rho0_) {
            const bool low = e.rhoMin < 0.5 * rho0_;
            throw AppError(ExitCode::UNSTABLE,
                           at + "the fluid density reached " +
                               formatted("%.3g", low ? e.rhoMin : e.rhoMax) + " kg/m^3" +
                               where(low ? Extreme::THINNEST : Extreme::DENSEST) +
                               " against the rest density " + formatted("%.3g", rho0_) +
                               ": the run is lost; raise the sound speed or refine the spacing");
        }
    }

    /// The first warning of each kind (spray too fast, density far from rest), else "".
    std::string warnOnce(const Extremes& e, const std::string& at, const Where& where) {
        if (!speedWarned_ && e.vmax > WARN_SPEED * U_) {
            speedWarned_ = true;
            return at + "a fluid particle" + where(Extreme::FASTEST) + " moves at " +
                   formatted("%.3g", e.vmax) + " m/s, " + formatted("%.3g", e.vmax / U_) +
                   " times the velocity scale U = " + formatted("%.3g", U_) +
                   " m/s the sound speed was set for: spray this fast is not physical; set "
                   "physics.max_speed to the speed you expect";
        }
        if (!densityWarned_ &&
            (e.rhoMax > rho0_ * (1 + WARN_DENSITY) || e.rhoMin < rho0_ * (1 - WARN_DENSITY))) {
            densityWarned_ = true;
            // Named: the particle furthest from rest, below or above.
            const bool thin = rho0_ - e.rhoMin >= e.rhoMax - rho0_;
            return at + "the fluid density ranges over " + formatted("%.3g", e.rhoMin) + " to " +
                   formatted("%.3g", e.rhoMax) + " kg/m^3 (" +
                   (thin ? "the lowest" : "the highest") +
                   where(thin ? Extreme::THINNEST : Extreme::DENSEST) +
                   "), more than 20 % from the rest density " + formatted("%.3g", rho0_) +
                   ": the fluid is far from incompressible; raise the sound speed";
        }
        return "";
    }
    static constexpr double WARN_SPEED = 3, WARN_DENSITY = 0.2;

    double U_, c0_, rho0_;
    std::vector<Range> ranges_{
        {sph::QuantityId::TEMPERATURE, "temperature", "degC", -273.15, HUGE_VAL,
         "nothing is colder than absolute zero (-273.15 degC): the scene draws more heat than the "
         "water holds; lower a wall's heat_flux, a plugin's heat sink or the conductivity, or "
         "lower time.cfl"}};
    bool speedWarned_ = false, densityWarned_ = false;
    std::vector<std::string> warnings_;
};

}  // namespace num::app
