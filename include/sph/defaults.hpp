// The numerical defaults of the fluid solver, in one place: the library (FluidModel,
// RunSettings, Material), the scene reader (app/scene.hpp) and the documentation
// (docs/scenes.md, checked by a test) all take them from here. They are the configuration the
// validation report (docs/validation.md) measures: a scene that states only geometry,
// materials and resolution runs the validated scheme.
#pragma once

namespace num::sph::defaults {

// Kernel and smoothing length. Wendland C2 at h = 1.5 dx: its Morris Laplacian and gradient
// on a lattice are within 0.3 % (2D) and 0.1 % (3D) of exact (at h = 1.3 dx: 2.6 % and 2.1 %
// weak, which made channel flows 3-4 % slow); Wendland kernels do not pair (Dehnen & Aly
// 2012, Mon. Not. R. Astron. Soc. 425, 1068).
inline constexpr const char* kernel = "wendland_c2";
inline constexpr double hOverSpacing = 1.5;

// The pair loop: "asymmetric" (each particle gathers from all its neighbours) or "symmetric"
// (each pair once, both particles written; momentum conserved to round-off, other round-off).
// Asymmetric because it is the faster in 2D (the symmetric loop takes 1.17 times as long on the
// default scene, the 2D engine 1.03 to 1.3 times: docs/performance.md), it needs no per-thread
// sums (less memory), and it is the loop the validation report measures; the symmetric one is
// selectable from a scene (particles.evaluation).
inline constexpr const char* evaluation = "asymmetric";

// Time step: dt <= cfl h / (c0 + max|v|), cfl = 0.25, the acoustic limit of Morris, Fox & Zhu
// (1997, J. Comput. Phys. 136, 214).
inline constexpr double cfl = 0.25;

// Weakly-compressible equation of state: Tait, gamma = 7, c0 = 10 U for an "auto" sound speed
// (density variations near 1 %, Monaghan 1994).
inline constexpr const char* eos = "tait";
inline constexpr double taitExponent = 7;
inline constexpr double soundSpeedFactor = 10;

// Density by continuity with delta-SPH diffusion (Molteni & Colagrossi 2009), delta = 0.1.
inline constexpr double densityDiffusion = 0.1;

// Particle shifting dr = -A h c0 dt grad C with A = 0.5 (terms/particle_shifting.hpp: the law,
// its sources and its tests); without shifting natural convection at Ra = 1e4 comes out 10 %
// low (docs/validation.md).
inline constexpr bool shifting = true;
inline constexpr double shiftingCoefficient = 0.5;
// Within a kernel support of a wall or body, particles are shifted along the wall only: the
// component towards or away from it damps the boundary layer (lid-driven cavity, Re = 100,
// 50 x 50: error on Ghia et al.'s profiles 0.026 of the lid speed with shifting along walls
// only; terms/particle_shifting.hpp).
inline constexpr bool shiftingNormalToWalls = false;

// A tension limit at free surfaces (terms/free_surface.hpp): where a particle's kernel support is
// cut its density is held at or above 0.99 rho0, so its pressure at or above p(0.99 rho0), about
// -0.01 rho0 c0^2 (-rho0 U^2 with c0 = 10 U). With the floor at rho0 (no tension) water that hits
// a wall rebounds: its compression (rho0 c0 U_impact) is released with no tension to hold it, the
// negative half of the sound waves is cut and the wall pressure, averaged, is several times the
// momentum flux. Lobovsky et al.'s impact, H / 80 (docs/validation.md): peak 12.3 rho g H with
// the floor at rho0, 3.98 with 0.99, 3.01 with 0.98 (the experiment: 1.86). Without a limit
// thin sheets thin away until the run is lost.
inline constexpr bool freeSurfaceTensionLimit = true;
inline constexpr double freeSurfaceDensityFloor = 0.99;

// Cavitation: the most tension [Pa] liquid water holds anywhere, the atmosphere's pressure less
// the vapour pressure at 20 degC, 101325 - 2339 Pa (Brennen 1995, Cavitation and Bubble Dynamics,
// ch. 1: water, with the nuclei it holds in practice, cavitates near its vapour pressure).
// p_i = max(p(rho_i), p_b - maxTension) for every fluid particle (terms/equation_of_state.hpp).
// It acts only where rho0 c0^2 / 7 > maxTension, c0 > 26 m/s with water, and there only on
// water stretched by more than 3.5 % (c0 = 56 m/s, as in the default 2D scene). The default 2D
// scene without it: 7 of its 41 outputs hold particles below -1 atm (the lowest -200 kPa) and
// one particle under the cold body reaches 17.3 m/s (3.1 U) at t = 0.658 s; with it, no
// warning and the fastest particle of any output 12.2 m/s (19.4 without).
inline constexpr double maxTension = 98986;

// eta^2 / h^2 in the Laplacians of viscosity and heat conduction, 1 / (r^2 + eta^2): only a
// guard against r -> 0. Morris et al. (1997) use 0.01, which makes the Laplacian 1.3 % weak on
// a lattice at h = 1.5 dx and the Taylor-Green vortex decay 2.4 % too slowly; 0.001: 0.15 %.
inline constexpr double laplacianEta2 = 0.001;
// eta^2 / h^2 in 1 / (r^2 + eta^2) of the artificial viscosity (Monaghan 1992, eq. 4.2) and of
// delta-SPH (Antuono et al. 2010): their sources' 0.01.
inline constexpr double inverseR2Eta2 = 0.01;

// Monaghan's artificial viscosity alpha of a material, where none is given: 0.02 where the flow
// is not resolved, that is where the laminar viscosity nu is below the viscosity alpha brings,
// alpha h c0 / (2 (Dim + 2)) (Monaghan 2005, Rep. Prog. Phys. 68, 1703, eq. 4.10), as for water
// in a dam break at any practical spacing; else 0, since there the laminar term resolves the
// dissipation and alpha would only add to it (in the Taylor-Green vortex at Re = 100, 50 x 50,
// alpha = 0.02 would add 7.5 % to nu). Why 0.02 in a dam break: without it, the 2D dam break at
// a spacing of 0.02 m threw spray at 17 m/s (3 times the free-fall speed) and compressed water
// 20 % above rest; with 0.02, neither (nor in the default 2D scene, docs/scenes.md).
inline constexpr double artificialViscosity = 0.02;
inline double artificialViscosityFor(double nu, double h, double c0, int dim) {
    return nu < artificialViscosity * h * c0 / (2 * (dim + 2)) ? artificialViscosity : 0.0;
}

// Water at 20 degC.
inline constexpr double density = 1000;             // kg/m^3
inline constexpr double viscosity = 1.0e-6;         // m^2/s
inline constexpr double conductivity = 0.6;         // W/(m K)
inline constexpr double heatCapacity = 4186;        // J/(kg K)
inline constexpr double referenceTemperature = 20;  // degC
// b [1/K] in nu = nu0 exp(-b (T - T0)), the exponential law of viscosity (Reynolds 1886): about
// 0.02 for water near 20 degC.
inline constexpr double viscosityTemperatureCoefficient = 0.02;
// No thermal expansion [1/K]: buoyancy only where a material states it.
inline constexpr double thermalExpansion = 0;
// The temperature of fluid, bodies and emitted particles a scene does not give [degC]: the
// reference temperature, so that a scene without heat is at its rest density.
inline constexpr double temperature = referenceTemperature;

// The engine's material (sph::Material) where a program states nothing. Its sound speed is a
// number, 10 m/s (c0 = 10 U for flows up to 1 m/s), where the apps derive "auto" from the flow
// (soundSpeedFactor); its artificial viscosity is 0 (off) where the apps use "auto"
// (artificialViscosityFor): a program that builds its own model adds dissipation knowingly.
inline constexpr double flowSpeed = 1;  // U [m/s] of a FluidModel that states none
inline constexpr double materialSoundSpeed = soundSpeedFactor * flowSpeed;  // m/s
inline constexpr double materialArtificialViscosity = 0;                    // Monaghan's alpha

// The run's settings (RunSettings) a program or scene does not set.
// h [m] of a program that sets none: 1.3 times a spacing of 0.01 m (the apps set h =
// hOverSpacing times the scene's spacing).
inline constexpr double smoothingLength = 0.013;
// Worker threads of the parallel scheduler (the apps: --threads).
inline constexpr int threads = 1;
// Particle blocks of the symmetric pair loop: each block sums into its own buffers and the
// blocks are added in a fixed order, so results depend on the blocks, never on the threads.
inline constexpr int blocks = 4;
// Time-step factors besides the CFL: dt <= 0.25 sqrt(h / |a|) (the force limit of Monaghan
// 1992), dt <= 0.125 h^2 / nu (viscous diffusion, Morris et al. 1997), dt <= 0.1 h^2 / alpha
// (heat conduction: 0.2 is already unstable for a 2D lattice, cubic spline, h = 1.3 dx).
inline constexpr double accelerationFactor = 0.25;
inline constexpr double viscousFactor = 0.125;
inline constexpr double diffusionFactor = 0.1;
// Steps between reorderings of the particles by cell (neighbours near in memory); 0: never.
inline constexpr int reorderEvery = 25;
// Skin of the neighbour lists, a fraction of the support radius. 0.1: fluid_sim on the 2D dam
// break's first steps (slow flow) ran 10 % faster than with the cell grid at 0.1 and 0.2 alike,
// slower at 0.3; in 3D the candidates grow as (1 + skin)^3. In fast flow the lists then lasted
// 1.9 steps: the skin grows up to neighbourSkinMax (0.3: the default 2D scene's fast half 0.91x
// the time, 0.5 no faster than 0.3, and the lists' memory grows as (1 + skin)^Dim).
inline constexpr double neighbourSkin = 0.1;
inline constexpr double neighbourSkinMax = 0.3;

// Choices of a scene (the tables: sph/kernel_table.hpp, sph/integrator_choice.hpp,
// sph/evaluation_mode.hpp, sph/equation_of_state_choice.hpp, app/density_choice.hpp).
// Leapfrog (kick-drift-kick): second order and symplectic, one evaluation per step.
inline constexpr const char* integrator = "leapfrog";
// Density by summation in a full box closed by walls under gravity, else by continuity
// (docs/physics.md, "Closed boxes").
inline constexpr const char* densityMode = "auto";
// The CPU back end: every build has it (numerics.backend, --backend).
inline constexpr const char* backend = "cpu";

// A Scene built in code (a scene file must state these): its particle spacing [m] and end time
// [s], and an emitter's speed [m/s] and radius [m].
inline constexpr double spacing = 0.02;
inline constexpr double endTime = 1;
inline constexpr double emitterSpeed = 1;
inline constexpr double emitterRadius = 0.05;

}  // namespace num::sph::defaults
