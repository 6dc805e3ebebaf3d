"""Particle views: shapes and types, read-only by default, writes that change the run, stale
views refused and kept arrays safe across steps."""
import numpy as np
import pytest

import numerics


def test_arrays(sim2d):
    p = sim2d.particles
    n = len(p)
    assert n > 0 and p.position.shape == (n, 2) and p.velocity.shape == (n, 2)
    assert p.position.dtype == np.float64
    for name in ("density", "pressure", "temperature", "mass"):
        assert getattr(p, name).shape == (n,) and getattr(p, name).dtype == np.float64
    assert p.id.dtype == np.intc and p.kind.dtype == np.intc
    assert len(set(p.id.tolist())) == n
    assert {"position", "velocity", "temperature", "id", "kind"} <= set(p.fields())
    assert np.array_equal(p.field("temperature"), p.temperature)
    assert np.all(p.density > 900)


def test_views_share_the_run_memory(sim2d):
    p = sim2d.particles
    assert np.shares_memory(p.temperature, sim2d.particles.temperature)
    assert not p.temperature.flags.writeable
    with pytest.raises(ValueError):
        p.temperature[0] = 5
    with pytest.raises(AttributeError, match="particles_writable"):
        p.temperature = 5


def test_unknown_field(sim2d):
    with pytest.raises(ValueError, match='no field "vorticity".*temperature'):
        sim2d.particles.field("vorticity")


def test_stale_particles_refused(sim2d):
    p = sim2d.particles
    sim2d.step()
    with pytest.raises(numerics.StaleParticlesError, match="read sim.particles again"):
        p.position
    with pytest.raises(numerics.StaleParticlesError):
        len(p)
    assert len(sim2d.particles) > 0


def test_kept_array_is_a_snapshot(sim2d):
    w = sim2d.particles_writable()
    t = w.temperature
    before = t.copy()
    sim2d.run(until=0.01, progress=False)  # particles leave through the open side, reorder
    assert np.array_equal(t, before)  # the old values, in memory the array still owns
    t[:] = 1e6  # writes to the snapshot change nothing in the run
    assert sim2d.particles.temperature.max() < 1000
    assert not np.shares_memory(t, sim2d.particles.temperature)


def fluid_mean_after(sim, until, field):
    sim.run(until=until, progress=False)
    p = sim.particles
    return getattr(p, field)[p.kind == 0].mean(axis=0)


def fluid_count(p):
    return (p.kind == 0).sum()


def test_heating_a_region_raises_later_temperatures(tiny2d, tmp_path):
    reference = numerics.Simulation(tiny2d, threads=2, out=tmp_path / "a", quiet=True)
    heated = numerics.Simulation(tiny2d, threads=2, out=tmp_path / "b", quiet=True)
    w = heated.particles_writable()
    region = (w.kind == 0) & (w.position[:, 0] < 0.05)
    assert region.sum() > 0
    w.temperature[region] += 50
    assert heated.particles.temperature.mean() > reference.particles.temperature.mean()
    # 12 of the 30 fluid particles 50 K hotter: their mean 20 K higher, of which conduction to
    # the walls takes a little in 0.01 s; half of it is the bound.
    raised = 50 * region.sum() / fluid_count(w)
    heated_mean = fluid_mean_after(heated, 0.01, "temperature")
    assert heated_mean > fluid_mean_after(reference, 0.01, "temperature") + raised / 2


def test_pushing_the_water_moves_it(tiny2d, tmp_path):
    reference = numerics.Simulation(tiny2d, threads=2, out=tmp_path / "a", quiet=True)
    pushed = numerics.Simulation(tiny2d, threads=2, out=tmp_path / "b", quiet=True)
    w = pushed.particles_writable()
    fluid = w.kind == 0
    velocity = w.velocity.copy()
    velocity[fluid, 0] += 1.0
    w.velocity = velocity  # assignment through the property, shape checked
    # 1 m/s carries the water 0.01 m in 0.01 s; pressure and the walls take some: a third.
    x_ref = fluid_mean_after(reference, 0.01, "position")[0]
    assert fluid_mean_after(pushed, 0.01, "position")[0] > x_ref + 0.01 / 3


def test_wrong_shapes_refused(sim2d):
    w = sim2d.particles_writable()
    n = len(w)
    with pytest.raises(ValueError, match=r"position has shape \(%d, 2\)" % n):
        w.position = np.zeros((n, 3))
    with pytest.raises(ValueError, match="temperature has shape"):
        w.temperature = np.zeros(n + 1)
    with pytest.raises(ValueError):
        w.temperature[:] = np.zeros(n - 1)  # NumPy's own check
    w.temperature = 25.0  # a scalar broadcasts
    assert np.all(sim2d.particles.temperature == 25.0)


def test_unstable_run_is_an_exception(sim2d):
    w = sim2d.particles_writable()
    # A finite temperature (a NaN is refused before the step), beyond what the heat terms hold.
    w.temperature[np.flatnonzero(w.kind == 0)[0]] = 1e300
    with pytest.raises(numerics.RunError) as e:
        sim2d.run(progress=False)
    assert e.value.exit_code == 9 and "sound speed" in str(e.value)
    assert sim2d.finished and sim2d.summary["status"] == "unstable"


def test_position_that_is_not_a_number_refused(sim2d):
    w = sim2d.particles_writable()
    w.position[3, 1] = np.nan
    with pytest.raises(numerics.RunError, match="particle 3 was given the position nan on axis 1") as e:
        sim2d.step()
    assert e.value.exit_code == 2


@pytest.mark.parametrize("field,value,text", [
    ("material", 10**9, "material 1000000000"), ("material", -1, "material -1"),
    ("material", 2, "material 2"), ("kind", 99, "kind 99"), ("kind", 1, "kind 1"),
    ("id", 12345, "id 12345"), ("mass", 0.0, "mass 0"), ("mass", -1.0, "mass -1"),
    ("density", np.inf, "density inf"), ("density", -1000.0, "density -1000"),
    ("density", 1e5, "density 100000 kg/m^3"), ("pressure", np.nan, "pressure nan"),
    ("temperature", np.inf, "temperature inf"), ("velocity", np.inf, "velocity inf on axis 0"),
    ("velocity", 1e4, "velocity 14142.1 m/s"), ("temperature", -500.0, "temperature -500 degC"),
    ("position", [0.3, 0.05], "position 0.3 on axis 0"),
    ("position", [0.05, -3.0], "position -3 on axis 1")])
def test_written_quantities_are_checked(sim2d, field, value, text):
    p = sim2d.particles_writable()
    fluid = int(np.flatnonzero(p.kind == 0)[0])
    original = getattr(p, field)[fluid].copy()
    getattr(p, field)[fluid] = value
    with pytest.raises(numerics.RunError) as e:
        sim2d.step()
    assert e.value.exit_code == 2
    assert f"particle {fluid} was given the {text}" in str(e.value), str(e.value)
    assert sim2d.steps == 0
    getattr(p, field)[fluid] = original  # written back, the run goes on
    assert sim2d.step() > 0
