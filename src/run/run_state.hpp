// The pieces of the time loop (internal to numerics_app): the state a checkpoint keeps besides
// the particles, health checks, open boundaries, summary.json and the final report.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/checkpoint.hpp"
#include "app/diagnostics.hpp"
#include "app/fields.hpp"
#include "app/formatted.hpp"
#include "app/outputs.hpp"
#include "run/checkpoint_state.hpp"
#include "sph/solver.hpp"

namespace num::app {

/// mass, momentum (Dim values), kinetic, potential and thermal energy of the fluid.
template <int Dim>
std::vector<double> conservationVector(const sph::Storage<Dim>& s, const sph::Vector<Dim>& g) {
    const Conservation<Dim> c = conservation(s, g);
    std::vector<double> v{c.mass};
    for (int k = 0; k < Dim; ++k) v.push_back(c.momentum[k]);
    v.push_back(c.kinetic), v.push_back(c.potential), v.push_back(c.thermal);
    return v;
}

/// Whether particle i's value of field f is finite (integer fields always are).
template <int Dim>
class FiniteCheck {
  public:
    FiniteCheck(const sph::Storage<Dim>& s, const OutputField& f) : type_(f.type) {
        if (type_ == OutputField::Type::FLOAT) scalar_ = s.template getValue<double>(f.id);
        if (type_ == OutputField::Type::VECTOR)
            vector_ = f.derivative ? s.template getDt<sph::Vector<Dim>>(f.id)
                                   : s.template getValue<sph::Vector<Dim>>(f.id);
    }
    bool operator()(sph::Size i) const {
        if (type_ == OutputField::Type::FLOAT) return std::isfinite(scalar_[i]);
        if (type_ == OutputField::Type::INT) return true;
        bool finite = true;
        for (int k = 0; k < Dim; ++k) finite &= std::isfinite(vector_[i][k]);
        return finite;
    }

  private:
    OutputField::Type type_;
    sph::ArrayView<const double> scalar_;
    sph::ArrayView<const sph::Vector<Dim>> vector_;
};

/// "fluid particle 12": particle i's kind and id, for a message.
template <int Dim>
std::string particleName(const sph::Storage<Dim>& s, sph::Size i) {
    static const char* kinds[] = {"fluid particle", "wall particle", "body particle",
                                  "inlet particle", "outlet particle"};
    const int kind = s.template getValue<int>(sph::QuantityId::KIND)[i];
    return std::string(kind >= 0 && kind < sph::kParticleKinds ? kinds[kind] : "particle") + " " +
           std::to_string(s.template getValue<int>(sph::QuantityId::PARTICLE_ID)[i]);
}

/// The wall a fluid particle at x left the domain through (more than a spacing beyond it), as
/// (axis, side); (-1, 0) where it did not, or is not fluid.
template <int Dim>
std::pair<int, int> wallLeftThrough(const Scene<Dim>& scene, int kind, const sph::Vector<Dim>& x) {
    if (kind != int(sph::ParticleKind::FLUID)) return {-1, 0};
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) {
            if (!scene.sides[k][hi]->closes()) continue;
            const double beyond = hi ? x[k] - scene.domainMax[k] : scene.domainMin[k] - x[k];
            if (beyond > scene.spacing) return {k, hi};
        }
    return {-1, 0};
}

/// Stops the run (AppError UNSTABLE) on a non-finite value in any written field, a density that
/// is not positive, fluid beyond a wall, or a collapsed time step, naming the time, the step,
/// the field and the likely cause. The first problem is reported: the fields in the order
/// position, then the written fields, then density and walls, each at its first particle in
/// storage order. One scan over the particles, in chunks on the scheduler's threads.
template <int Dim>
void checkHealth(sph::IScheduler& scheduler, const sph::Storage<Dim>& s, const Scene<Dim>& scene,
                 double t, std::uint64_t step, double dt, const std::string& criterion,
                 const FieldNames& names = {}) {
    using sph::QuantityId;
    const std::string where =
        formatted("the run went unstable at t = %.6g s (step %llu, dt = %.3g s limited by %s): ", t,
                  (unsigned long long)step, dt, criterion.c_str());
    const std::string cause =
        ". Likely cause: the time step is too large or the sound speed too low for this flow; "
        "lower time.cfl, raise the material's sound_speed, or refine particles.spacing";
    const auto particle = [&](long i) { return particleName(s, sph::Size(i)); };
    std::vector<OutputField> fields = outputFields(s, names);
    fields.insert(fields.begin(), {"position", QuantityId::POSITION, OutputField::Type::VECTOR});
    std::vector<FiniteCheck<Dim>> finite;
    for (const OutputField& f : fields) finite.emplace_back(s, f);
    const auto kind = s.template getValue<int>(QuantityId::KIND);
    const auto x = s.template getValue<sph::Vector<Dim>>(QuantityId::POSITION);
    const auto rho = s.template getValue<double>(QuantityId::DENSITY);
    const auto leftThrough = [&](sph::Size i) { return wallLeftThrough(scene, kind[i], x[i]); };
    // The first particle of each check (every field's finiteness, then density and walls), -1
    // where none fails.
    const std::size_t checks = finite.size() + 1;
    const std::vector<long> first = sph::reduceChunks(
        scheduler, s.size(), 8192, std::vector<long>(checks, -1),
        [&](sph::Size b, sph::Size e, std::vector<long>& firstOf) {
            for (sph::Size i = b; i < e; ++i) {
                for (std::size_t c = 0; c < finite.size(); ++c)
                    if (firstOf[c] < 0 && !finite[c](i)) firstOf[c] = long(i);
                if (firstOf.back() < 0 && (!(rho[i] > 0) || leftThrough(i).first >= 0))
                    firstOf.back() = long(i);
            }
        },
        [](std::vector<long>& firstOf, const std::vector<long>& partial) {
            for (std::size_t c = 0; c < firstOf.size(); ++c)
                if (firstOf[c] < 0) firstOf[c] = partial[c];
        });
    for (std::size_t c = 0; c < finite.size(); ++c)
        if (const long i = first[c]; i >= 0)
            throw AppError(ExitCode::UNSTABLE,
                           where + particle(i) + " has a non-finite " + fields[c].name + cause);
    if (const long i = first.back(); i >= 0) {
        if (!(rho[i] > 0))
            throw AppError(ExitCode::UNSTABLE, where + particle(i) + " has a density <= 0" + cause);
        const auto [k, hi] = leftThrough(sph::Size(i));
        throw AppError(ExitCode::UNSTABLE,
                       where + std::string("a fluid particle left the domain through the ") +
                           sideName(k, hi) + " wall" + cause);
    }
    if (criterion != "end time" && dt < 1e-9 * scene.endTime)
        throw AppError(ExitCode::UNSTABLE, where + std::string("the time step collapsed") + cause);
}

/// Whether any side of the box lets the fluid out (an open side).
template <int Dim>
bool anySideLetsFluidOut(const Scene<Dim>& scene) {
    bool anyOut = false;
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi) anyOut |= scene.sides[k][hi]->letsFluidOut();
    return anyOut;
}

/// Whether fluid within `extent` (the box holding every fluid particle) is beyond a side that
/// lets fluid out: what removeOutflow removes.
template <int Dim>
bool fluidLeaves(const Scene<Dim>& scene, const sph::FluidExtent<Dim>& extent) {
    for (int k = 0; k < Dim; ++k)
        if ((scene.sides[k][0]->letsFluidOut() && extent.min[k] < scene.domainMin[k]) ||
            (scene.sides[k][1]->letsFluidOut() && extent.max[k] > scene.domainMax[k]))
            return true;
    return false;
}

/// The sides' post-step sink: removes the fluid particles that left through a side that lets
/// fluid out (ISideBoundary::markLeaving); returns how many.
template <int Dim>
std::size_t removeOutflow(sph::Storage<Dim>& s, const Scene<Dim>& scene) {
    if (!anySideLetsFluidOut(scene)) return 0;
    std::vector<char> leaving(s.size(), 0);
    for (int k = 0; k < Dim; ++k)
        for (int hi = 0; hi < 2; ++hi)
            scene.sides[k][hi]->markLeaving(s, k, hi, hi ? scene.domainMax[k] : scene.domainMin[k],
                                            leaving);
    std::vector<sph::Size> out;
    for (sph::Size i = 0; i < s.size(); ++i)
        if (leaving[i]) out.push_back(i);
    if (!out.empty()) s.remove(out);
    return out.size();
}

template <int Dim>
nlohmann::json summaryJson(const Scene<Dim>& scene, const sph::Storage<Dim>& s,
                           const SceneSetup<Dim>& setup, const RunState<Dim>& state, double t,
                           std::uint64_t steps, std::uint64_t runSteps, double wall,
                           double particleSteps, int threads, const std::string& backend,
                           const std::string& status, const std::string& message,
                           double neighbours) {
    const std::vector<double> end =
        conservationVector(s, setup.gravity(1e300));  // full gravity, after any ramp
    const auto kind = s.template getValue<int>(sph::QuantityId::KIND);
    std::size_t fluid = 0;
    for (int k : kind) fluid += k == int(sph::ParticleKind::FLUID);
    nlohmann::json c;
    auto pair = [&](std::size_t i) {
        return nlohmann::json{{"start", state.start.at(i)}, {"end", end.at(i)}};
    };
    nlohmann::json mStart = nlohmann::json::array(), mEnd = nlohmann::json::array();
    for (int k = 0; k < Dim; ++k)
        mStart.push_back(state.start.at(1 + k)), mEnd.push_back(end.at(1 + k));
    c["mass"] = pair(0);
    c["momentum"] = {{"start", mStart}, {"end", mEnd}};
    c["kinetic_energy"] = pair(Dim + 1);
    c["potential_energy"] = pair(Dim + 2);
    c["thermal_energy"] = pair(Dim + 3);
    c["note"] =
        "sums over fluid particles; mass changes by inlets and outlets (in, out), emitters and "
        "open sides; thermal energy is sum m c T with T in degC, and changes by in, out, the heat "
        "walls and bodies gave (walls) and conduction into conducting bodies";
    return {{"dimension", Dim},
            {"scene", scene.file},
            {"name", scene.name},
            {"status", status},
            {"message", message},
            {"particles", s.size()},
            {"fluid_particles", fluid},
            {"steps", steps},
            {"steps_this_run", runSteps},
            {"final_time", t},
            {"end_time", scene.endTime},
            {"wall_seconds", wall},
            {"particle_steps_per_second", wall > 0 ? particleSteps / wall : 0.0},
            {"mean_neighbours", neighbours},
            {"threads", threads},
            {"backend", backend},
            {"smoothing_length", setup.settings.template get<double>("smoothing_length")},
            {"sound_speed", setup.model.c0()},
            {"emitted_particles", state.emitted},
            {"emitter_points_blocked", state.emitterBlocked},
            {"removed_particles", state.removed},
            {"outputs", state.outputIndex},
            {"conservation", c}};
}

}  // namespace num::app
