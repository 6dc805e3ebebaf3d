"""numerics.Particles: a run's particles as NumPy arrays over its own storage.

The arrays show the particles as they are until the next step (particles are reordered, added
and removed by steps). After a step this object refuses access (StaleParticlesError): ask
``sim.particles`` again. An array kept across a step keeps the values it had (a copy the run no
longer uses): it is never a dangling pointer, and writing into it changes nothing.
"""
import numpy as np

from . import _arguments
from .errors import StaleParticlesError

_STANDARD = ("position", "velocity", "density", "pressure", "temperature", "mass", "id", "kind",
             "material")


class Particles:
    """The particles of a run between two steps: ``p.position`` (N, dim), ``p.velocity``,
    ``p.density``, ``p.pressure``, ``p.temperature``, ``p.mass``, ``p.id``, ``p.kind``,
    ``p.material`` and ``p.field(name)`` for any other quantity (``p.fields()``)."""

    def __init__(self, driver, writable):
        self._driver = driver
        self._generation = driver.generation
        self._writable = writable

    @property
    def writable(self):
        return self._writable

    def _check(self):
        if self._driver.generation != self._generation:
            raise StaleParticlesError(
                "these particles are from before a step (particles move, are reordered, added "
                "and removed by steps): read sim.particles again")

    def field(self, name):
        """The array of field `name` (ValueError, naming the fields, when there is none)."""
        if not isinstance(name, str):
            raise TypeError(f"particles: name: expected a field's name (str), found "
                            f"{_arguments.found(name)}")
        self._check()
        return self._driver.view(name, self._writable)

    def fields(self):
        """The names of the fields of this run's particles."""
        self._check()
        return list(self._driver.fields())

    def __len__(self):
        self._check()
        return self._driver.count

    def set(self, name, values):
        """Writes `values` into field `name` (the shape of the field, or one that broadcasts to
        it). Only on writable particles (sim.particles_writable())."""
        if not self._writable:
            raise AttributeError(
                f"particles: {name} is read-only here: write through sim.particles_writable()")
        target = self.field(name)
        values = np.asarray(values)
        try:
            shape = np.broadcast_shapes(values.shape, target.shape)
        except ValueError:
            shape = None
        if shape != target.shape:
            raise ValueError(f"particles: {name} has shape {target.shape}, the values given "
                             f"{values.shape}")
        target[...] = values

    def __repr__(self):
        state = "stale" if self._driver.generation != self._generation else f"{len(self)} particles"
        return f"numerics.Particles({state}{', writable' if self._writable else ''})"


def _field_property(name):
    return property(lambda self: self.field(name), lambda self, v: self.set(name, v),
                    doc=f"The particles' {name}.")


for _name in _STANDARD:
    setattr(Particles, _name, _field_property(_name))
