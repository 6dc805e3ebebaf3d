"""numerics.Scene and numerics.scenes(): reading, --set's overrides, and the apps' errors."""
import json

import pytest

import numerics
from conftest import TINY_2D


def test_load_and_dict_give_the_same_document(tiny2d):
    assert tiny2d.dimension == 2
    d = tiny2d.to_dict()
    assert d["particles"]["spacing"] == 0.02
    again = numerics.Scene(d)
    assert again.to_dict() == d and again.dimension == 2
    assert tiny2d.file == TINY_2D and again.file == "<dict>"


def test_set_changes_values_of_any_json_type(tiny2d):
    tiny2d.set("materials.water.viscosity", 1e-3)
    tiny2d.set("fluids.0.temperature", "20 + 50*y")
    tiny2d.set("gravity", [0, -1])
    tiny2d.set("output.images", False)
    d = tiny2d.to_dict()
    assert d["materials"]["water"]["viscosity"] == 1e-3
    assert d["fluids"][0]["temperature"] == "20 + 50*y"
    assert d["gravity"] == [0, -1] and d["output"]["images"] is False
    assert tiny2d.check() is tiny2d


def test_to_dict_is_a_copy(tiny2d):
    tiny2d.to_dict()["particles"]["spacing"] = 1
    assert tiny2d.to_dict()["particles"]["spacing"] == 0.02


def test_shipped_scenes():
    found = numerics.scenes()
    assert "dam_break_hot_cold_2d" in found and "poiseuille_2d" in found
    assert numerics.Scene.load(found["dam_break_3d"]).dimension == 3
    assert all(path.endswith(name + ".json") for name, path in found.items())


def expect_error(kind, code, text, action):
    with pytest.raises(kind) as e:
        action()
    assert e.value.exit_code == code, str(e.value)
    assert text in str(e.value)
    assert isinstance(e.value, numerics.Error)
    return e.value


def test_missing_file():
    expect_error(numerics.SceneError, 3, "no_such_scene.json", lambda: numerics.Scene.load(
        "no_such_scene.json"))


def test_bad_json(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"dimension": 2,,}')
    expect_error(numerics.SceneError, 4, "bad.json", lambda: numerics.Scene.load(bad))


def test_bad_set_path(tiny2d):
    expect_error(numerics.SceneError, 2, "is an array of 1 values",
                 lambda: tiny2d.set("fluids.7.temperature", 3))
    expect_error(numerics.SceneError, 2, "empty key", lambda: tiny2d.set("physics..x", 3))


def test_bad_value_refused_by_check_and_by_the_run(tiny2d, tmp_path):
    tiny2d.set("particles.spacing", -1)
    e = expect_error(numerics.SceneError, 5, "particles.spacing", tiny2d.check)
    e2 = expect_error(numerics.SceneError, 5, "particles.spacing",
                      lambda: numerics.Simulation(tiny2d, out=tmp_path, quiet=True))
    assert str(e) == str(e2)


def test_unknown_key_and_bad_expression(tiny2d, tmp_path):
    d = tiny2d.to_dict()
    d["particles"]["spacin"] = 0.02
    expect_error(numerics.SceneError, 5, "spacin", numerics.Scene(d).check)
    tiny2d.set("fluids.0.temperature", "20 + nosuchvariable")
    expect_error(numerics.SceneError, 6, "nosuchvariable",
                 lambda: numerics.Simulation(tiny2d, out=tmp_path, quiet=True))


def test_not_a_scene():
    expect_error(numerics.SceneError, 2, "scene: expected a dict", lambda: numerics.Scene([1, 2]))
    expect_error(numerics.SceneError, 5, "dimension", lambda: numerics.Scene({"dimension": 4})
                 .dimension)
