// The key tables of the scene sections that are objects of values (scene/scene_keys.hpp): one
// entry per key, with the readers of the keys that are more than a value.
#include <algorithm>

#include "app/density_choice.hpp"
#include "scene/scene_keys.hpp"
#include "sph/defaults.hpp"
#include "sph/equation_of_state_choice.hpp"
#include "sph/evaluation_mode.hpp"
#include "sph/integrator_choice.hpp"
#include "sph/kernel_table.hpp"

namespace num::app {

using detail::At;
namespace d = sph::defaults;

namespace {

template <int Dim>
void readDomainMin(const At& a, DomainInput<Dim>& d) {
    d.min = detail::readVec<Dim>(a, "m");
}

/// Read after min: max > min on every axis.
template <int Dim>
void readDomainMax(const At& a, DomainInput<Dim>& d) {
    d.max = detail::readVec<Dim>(a, "m");
    for (int k = 0; k < Dim; ++k)
        if (!(d.max[k] > d.min[k])) a.fail("max > min on every axis");
}

template <int Dim>
const KeyTable<DomainInput<Dim>> kDomainKeys{
    {.name = "min",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "the lowest corner of the box the fluid lives in",
     .required = true,
     .read = readDomainMin<Dim>},
    {.name = "max",
     .type = KeyType::CUSTOM,
     .unit = "m",
     .meaning = "its highest corner: `max > min` on every axis, every axis at least 2 spacings",
     .required = true,
     .read = readDomainMax<Dim>},
};

const KeyTable<ParticleSpec> kParticleKeys{
    {.name = "spacing",
     .type = KeyType::NUMBER,
     .field = &ParticleSpec::spacing,
     .fallback = 0.0,
     .unit = "m",
     .lo = 0,
     .loOpen = true,
     .meaning = "see [limits](#limits)",
     .required = true},
    {.name = "h_over_spacing",
     .type = KeyType::NUMBER,
     .field = &ParticleSpec::hOverSpacing,
     .fallback = d::hOverSpacing,
     .lo = 0.8,
     .hi = 3,
     .meaning = "smoothing length h = h_over_spacing × spacing"},
    {.name = "kernel",
     .type = KeyType::CHOICE,
     .field = &ParticleSpec::kernel,
     .fallback = std::string(d::kernel),
     .choices = sph::choiceNames(sph::kernelTable),
     .meaning = "support 2h, the quintic spline's 3h (docs/kernels.md)"},
    {.name = "evaluation",
     .type = KeyType::CHOICE,
     .field = &ParticleSpec::evaluation,
     .fallback = std::string(d::evaluation),
     .choices = sph::choiceNames(sph::evaluationTable),
     .meaning = "the pair loop. `asymmetric`: each particle gathers over its neighbours "
                "(validated); "
                "`symmetric`: each pair once, both written, momentum conserved to round-off, "
                "results equal to round-off, 1.17 times the time in 2D "
                "(docs/performance.md). Both are bitwise the same for any thread count"},
};

const KeyTable<TimeSpec> kTimeKeys{
    {.name = "end",
     .type = KeyType::NUMBER,
     .field = &TimeSpec::endTime,
     .fallback = 0.0,
     .unit = "s",
     .lo = 0,
     .loOpen = true,
     .required = true},
    {.name = "cfl",
     .type = KeyType::NUMBER,
     .field = &TimeSpec::cfl,
     .fallback = d::cfl,
     .lo = 1e-6,
     .hi = 1,
     .meaning = "dt ≤ cfl h / (c + abs(v))"},  // sph/settings.hpp's range
    {.name = "integrator",
     .type = KeyType::CHOICE,
     .field = &TimeSpec::integrator,
     .fallback = std::string(d::integrator),
     .choices = sph::choiceNames(sph::integratorTable),
     .meaning = "`leapfrog` is kick-drift-kick"},
    {.name = "dt_max",
     .type = KeyType::NUMBER,
     .field = &TimeSpec::dtMax,
     .fallback = 0.0,
     .unit = "s",
     .lo = 0,
     .defaultNote = "(no limit)"},
};

const KeyTable<NumericsSpec> kNumericsKeys{
    {.name = "backend",
     .type = KeyType::CHOICE,
     .field = &NumericsSpec::backend,
     .fallback = std::string(d::backend),
     .choices = {"cpu", "cuda"},
     .meaning = "`cpu` runs on `--threads` cores, `cuda` on an NVIDIA GPU (below); "
                "`--backend` replaces it"},
};

const KeyTable<MaterialSpec> kMaterialKeys{
    // Below 1e-6 kg/m^3 no continuum fluid exists, and rho^2 (in p / rho^2) underflows
    // near 1e-154.
    {.name = "density",
     .type = KeyType::NUMBER,
     .field = &MaterialSpec::density,
     .fallback = d::density,
     .unit = "kg/m^3",
     .lo = 1e-6,
     .hi = 1e7,
     .meaning = "rest density ρ0"},
    {.name = "sound_speed",
     .type = KeyType::NUMBER_OR_AUTO,
     .field = &MaterialSpec::soundSpeed,
     .fallback = std::string("auto"),
     .unit = "m/s",
     .lo = 0,
     .hi = kMaxSoundSpeed,
     .loOpen = true,
     .meaning = "with `auto`, c0 = 10 U, U = `physics.max_speed` if given, else the largest of the "
                "initial fluid speeds, the speeds of moving walls and emitters and, under gravity, "
                "the free-fall speed sqrt(2 abs(g) H) (H the domain height along gravity) with a "
                "free surface, or in a closed box full of fluid the larger of sqrt(abs(g) H) and "
                "the buoyancy speed sqrt(abs(g) β ΔT H) (ΔT the spread of fluid, wall and body "
                "temperatures). Refused: `auto` above 1e6 m/s (naming U and its source); no speed "
                "at all (conduction in water at rest: give `physics.max_speed` or `sound_speed`)"},
    {.name = "viscosity",
     .type = KeyType::NUMBER,
     .field = &MaterialSpec::viscosity,
     .fallback = d::viscosity,
     .unit = "m^2/s",
     .lo = 0,
     .hi = 1e3,
     .meaning = "kinematic viscosity (Morris 1997 laminar term)"},
    {.name = "artificial_viscosity",
     .type = KeyType::NUMBER_OR_AUTO,
     .field = &MaterialSpec::artificialViscosity,
     .fallback = std::string("auto"),
     .lo = 0,
     .hi = 10,
     .meaning = "Monaghan's α; `auto`: 0.02 where the flow is not resolved, `viscosity` "
                "below α h c0 / (2 (D + 2)) (a dam break), else 0 (Taylor-Green, cavities, "
                "channels)"},
    {.name = "conductivity",
     .type = KeyType::NUMBER,
     .field = &MaterialSpec::conductivity,
     .fallback = d::conductivity,
     .unit = "W/(m K)",
     .lo = 0,
     .hi = 1e6},
    {.name = "heat_capacity",
     .type = KeyType::NUMBER,
     .field = &MaterialSpec::heatCapacity,
     .fallback = d::heatCapacity,
     .unit = "J/(kg K)",
     .lo = 0,
     .hi = 1e7,
     .loOpen = true},
    {.name = "thermal_expansion",
     .type = KeyType::NUMBER,
     .field = &MaterialSpec::thermalExpansion,
     .fallback = 0.0,
     .unit = "1/K",
     .lo = 0,
     .hi = 0.01,
     .meaning = "β of Boussinesq buoyancy"},
    {.name = "reference_temperature",
     .type = KeyType::NUMBER,
     .field = &MaterialSpec::referenceTemperature,
     .fallback = d::referenceTemperature,
     .unit = "degC",
     .lo = -273.15,
     .hi = 1e4,
     .meaning = "T0 of buoyancy; temperature of adiabatic walls"},
};

const KeyTable<PhysicsSpec> kPhysicsKeys{
    {.name = "heat",
     .type = KeyType::FLAG,
     .field = &PhysicsSpec::heat,
     .fallback = true,
     .meaning = "heat conduction (Cleary & Monaghan 1999), thermal walls and bodies"},
    {.name = "buoyancy",
     .type = KeyType::FLAG,
     .field = &PhysicsSpec::buoyancy,
     .fallback = true,
     .meaning = "Boussinesq buoyancy −β (T − T0) g when a material has "
                "`thermal_expansion` > 0"},
    {.name = "density",
     .type = KeyType::CHOICE,
     .field = &PhysicsSpec::density,
     .fallback = std::string(d::densityMode),
     .choices = sph::choiceNames(densityTable),
     .meaning = "`auto`: summation under gravity in a box closed by walls and full of fluid "
                "(no bodies, no emitters), else continuity (docs/physics.md, \"Closed "
                "boxes\")"},
    {.name = "density_diffusion",
     .type = KeyType::NUMBER,
     .field = &PhysicsSpec::densityDiffusion,
     .fallback = d::densityDiffusion,
     .lo = 0,
     .hi = 1,
     .meaning = "δ of δ-SPH (continuity only)"},
    {.name = "shifting",
     .type = KeyType::FLAG,
     .field = &PhysicsSpec::shifting,
     .fallback = d::shifting,
     .meaning = "particle shifting (δ+-SPH form, docs/physics.md): keeps the particles "
                "regular without damping the flow"},
    {.name = "shifting_normal_to_walls",
     .type = KeyType::FLAG,
     .field = &PhysicsSpec::shiftingNormalToWalls,
     .fallback = d::shiftingNormalToWalls,
     .meaning = "within a kernel support of a wall or body, also shift towards or away from "
                "it (by default only along it: the normal part damps the boundary layer); "
                "true for flow onto a body (docs/physics.md)"},
    {.name = "free_surface_clamp",
     .type = KeyType::FLAG,
     .field = &PhysicsSpec::freeSurfaceTensionLimit,
     .fallback = d::freeSurfaceTensionLimit,
     .meaning = "tension limit at free surfaces: where the kernel support is cut (kernel sum "
                "< 0.9) the density is held at or above `free_surface_density_floor` × rest "
                "density and the pressure at or above the equation of state's there "
                "(docs/physics.md)"},
    {.name = "free_surface_density_floor",
     .type = KeyType::NUMBER,
     .field = &PhysicsSpec::freeSurfaceDensityFloor,
     .fallback = d::freeSurfaceDensityFloor,
     .lo = 0,
     .hi = 1,
     .loOpen = true,
     .meaning = "that floor; it allows a tension of about (1 - floor) ρ0 c0², with 0.99 and "
                "c0 = 10 U about ρ0 U². 1 allows none, and water rebounds from a wall it "
                "hits"},
    {.name = "gravity_ramp",
     .type = KeyType::NUMBER,
     .field = &PhysicsSpec::gravityRamp,
     .fallback = 0.0,
     .unit = "s",
     .lo = 0,
     .meaning = "gravity rises smoothly from 0 over this time"},
    {.name = "max_speed",
     .type = KeyType::NUMBER,
     .field = &PhysicsSpec::maxSpeed,
     .fallback = 0.0,
     .unit = "m/s",
     .lo = 0,
     .hi = kMaxSoundSpeed / d::soundSpeedFactor,
     .meaning = "the velocity scale U of `\"auto\"` sound speeds and of the health check",
     .defaultNote = "(derived)"},
    {.name = "eos",
     .type = KeyType::CHOICE,
     .field = &PhysicsSpec::eos,
     .fallback = std::string(d::eos),
     .choices = sph::choiceNames(sph::eosTable)},
    {.name = "background_pressure",
     .type = KeyType::NUMBER,
     .field = &PhysicsSpec::backgroundPressure,
     .fallback = 0.0,
     .unit = "Pa",
     .lo = 0,
     .hi = 1e12,
     .meaning = "added to the equation of state"},
    {.name = "max_tension",
     .type = KeyType::NUMBER,
     .field = &PhysicsSpec::maxTension,
     .fallback = d::maxTension,
     .unit = "Pa",
     .lo = 0,
     .hi = 1e12,
     .loOpen = true,
     .meaning = "the tension (pressure below the background) water holds before it "
                "cavitates, one atmosphere less water's vapour pressure at 20 °C; pressures "
                "are held at or above `background_pressure` - `max_tension` "
                "(docs/physics.md, \"Cavitation\"). It acts only where ρ0 c0² / 7 exceeds "
                "it (c0 above 26 m/s with water)"},
};

/// A file-name prefix: not empty, no '/', '\\' or spaces.
void readPrefix(const At& a, OutputSpec& out) {
    out.prefix = a.string();
    if (out.prefix.empty() || out.prefix.find_first_of("/\\ ") != std::string::npos)
        a.fail("a non-empty file-name prefix without '/', '\\' or spaces");
}

void readProbesEvery(const At& a, OutputSpec& out) {
    out.probesEvery = a.number(0, 1e300, true, "s");
}

/// Writer names, each once, in the scene's order (checked against the writers when the run is
/// set up: the scene's plugins may add some).
void readFormats(const At& f, OutputSpec& out) {
    if (!f.v.is_array()) f.fail("an array of output format names, e.g. [\"vtu\", \"csv\"]");
    out.formats.clear();
    for (std::size_t i = 0; i < f.v.size(); ++i) {
        const std::string name = At{f.v.at(i), f.file, f.join(std::to_string(i))}.string();
        if (std::find(out.formats.begin(), out.formats.end(), name) == out.formats.end())
            out.formats.push_back(name);
    }
}

void readImageWidth(const At& a, OutputSpec& out) { out.imageWidth = int(a.integer(64, 8192)); }

/// The formats of the plots drawn after the run: "png" and "svg", each once; [] for none.
void readPlots(const At& f, OutputSpec& out) {
    if (!f.v.is_array()) f.fail("an array of plot formats, e.g. [\"png\", \"svg\"], or []");
    out.plots.clear();
    for (std::size_t i = 0; i < f.v.size(); ++i) {
        const std::string format = f[i].choice({"png", "svg"});
        if (std::find(out.plots.begin(), out.plots.end(), format) == out.plots.end())
            out.plots.push_back(format);
    }
}

void readColorRange(const At& c, OutputSpec& out) {
    c.array(2, "temperatures [degC] (low, high)");
    out.colorMin = c[0].number(-273.15, 1e4, false, "degC");
    out.colorMax = c[1].number(-273.15, 1e4, false, "degC");
    if (!(*out.colorMax > *out.colorMin)) c.fail("low < high");
}

const KeyTable<OutputSpec> kOutputKeys{
    {.name = "directory",
     .type = KeyType::TEXT,
     .field = &OutputSpec::directory,
     .fallback = std::string("out/scene"),
     .meaning = "created if missing"},
    {.name = "prefix",
     .type = KeyType::CUSTOM,
     .meaning = "file names `<prefix>_NNNN.vtu` and so on",
     .read = readPrefix,
     .shownDefault = "`\"particles\"`"},
    {.name = "every",
     .type = KeyType::NUMBER,
     .field = &OutputSpec::every,
     .fallback = 0.05,
     .unit = "s",
     .lo = 0,
     .loOpen = true,
     .meaning = "output interval (steps end exactly on output times); at most 100,000 "
                "outputs per run"},
    {.name = "probes_every",
     .type = KeyType::CUSTOM,
     .unit = "s",
     .meaning = "> 0: the probes' interval: a row at the first step that reaches each "
                "multiple (steps are not shortened for it; with longer steps, a row every "
                "step)",
     .read = readProbesEvery,
     .shownDefault = "0.001, or `every` where shorter"},
    {.name = "formats",
     .type = KeyType::CUSTOM,
     .meaning = "writers by name, each run at every output time (a name listed twice counts "
                "once): the built-in `\"vtu\"` and `\"csv\"` ([Outputs](#outputs)) and the "
                "writers of the scene's `plugins` (docs/extending.md, \"A writer of your "
                "own\"). An unknown name is exit code 5: `scene.json: output.formats.1: "
                "expected one of \"vtu\", \"csv\", found the string \"vtk\" (did you mean "
                "\"vtu\"?)`",
     .read = readFormats,
     .shownDefault = "`[\"vtu\"]`"},
    {.name = "images",
     .type = KeyType::FLAG,
     .field = &OutputSpec::images,
     .fallback = true,
     .meaning = "a PNG per output time"},
    {.name = "video",
     .type = KeyType::FLAG,
     .field = &OutputSpec::video,
     .fallback = true,
     .meaning = "an MP4 of the pictures at the end when `ffmpeg` is installed "
                "(`scripts/setup.sh` installs it); else the last line says `no movie: ...` "
                "and `summary.json`'s `video_note` why"},
    {.name = "image_width",
     .type = KeyType::CUSTOM,
     .unit = "px",
     .meaning = "[64, 8192]",
     .read = readImageWidth,
     .shownDefault = "960"},
    {.name = "plots",
     .type = KeyType::CUSTOM,
     .meaning = "formats of the plots drawn after the run, `\"png\"` and/or `\"svg\"`; "
                "`[]`: none",
     .read = readPlots,
     .shownDefault = "`[\"png\"]`"},
    {.name = "color_range",
     .type = KeyType::CUSTOM,
     .unit = "degC",
     .meaning = "`[low, high]` of the colour bar; default: the span of the initial fluid and "
                "body temperatures and of fixed-temperature walls (sides and interior) and "
                "emitters",
     .read = readColorRange,
     .shownDefault = "from the scene"},
};

}  // namespace

template <int Dim>
const KeyTable<DomainInput<Dim>>& domainKeys() {
    return kDomainKeys<Dim>;
}
template const KeyTable<DomainInput<2>>& domainKeys<2>();
template const KeyTable<DomainInput<3>>& domainKeys<3>();

const KeyTable<ParticleSpec>& particleKeys() { return kParticleKeys; }
const KeyTable<TimeSpec>& timeKeys() { return kTimeKeys; }
const KeyTable<NumericsSpec>& numericsKeys() { return kNumericsKeys; }
const KeyTable<MaterialSpec>& materialKeys() { return kMaterialKeys; }
const KeyTable<PhysicsSpec>& physicsKeys() { return kPhysicsKeys; }
const KeyTable<OutputSpec>& outputKeys() { return kOutputKeys; }

}  // namespace num::app
