"""numerics: Smoothed Particle Hydrodynamics of water with heat transfer, from Python.

    import numerics
    sim = numerics.Simulation(numerics.Scene.load("scenes/dam_break_hot_cold_2d.json"))
    sim.run()
    print(sim.particles.temperature.mean(), sim.summary["status"])

docs/python.md describes the whole API.
"""
from .errors import Error, RunError, SceneError, StaleParticlesError
from .particles import Particles
from .scene import Scene, scenes
from .simulation import Simulation

__all__ = ["Error", "RunError", "SceneError", "StaleParticlesError", "Particles", "Scene",
           "scenes", "Simulation"]
