"""Scenes: numerics.Scene, a scene file or dict as the apps read it, and numerics.scenes()."""
import json
import os

from . import _arguments, _numerics
from ._paths import SCENES_DIR
from .errors import RunError, SceneError


class Scene:
    """A scene document: ``Scene.load(path)`` or ``Scene({...})``; ``set`` changes a value by
    its dotted path with the checks and messages of the apps' ``--set``."""

    def __init__(self, scene, _file="<dict>"):
        if isinstance(scene, _numerics.SceneDocument):
            self._doc = scene
        elif isinstance(scene, dict):
            self._doc = _numerics.SceneDocument.from_text(json.dumps(scene), _file)
        else:
            _arguments.refuse("scene", "a dict (or Scene.load(path) for a file)", scene,
                              SceneError)

    @classmethod
    def load(cls, path):
        """Reads and parses a scene file (SceneError: exit codes 3 and 4)."""
        path = _arguments.path("path", path, SceneError)
        return cls(_numerics.SceneDocument.from_file(path))

    def set(self, path, value):
        """Sets the value at a dotted path ("materials.water.viscosity", "fluids.0.temperature")
        to any JSON-able value. Returns the scene."""
        if not isinstance(path, str) or not path:
            _arguments.refuse("path", 'a dotted path such as "particles.spacing"', path,
                              SceneError)
        try:
            text = json.dumps(value, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise SceneError(f"value: expected a JSON value (a finite number, a string, a bool, "
                             f"None, a list or a dict of them), found {_arguments.found(value)}"
                             f" ({e})", 2) from None
        try:
            self._doc.set(f"{path}={text}")
        except RunError as e:  # the apps' usage errors of --set: a mistake in the scene here
            raise SceneError(e.message, e.exit_code) from None
        return self

    def to_dict(self):
        """The document as a new dict."""
        return json.loads(self._doc.dump())

    def check(self):
        """Reads and checks every key as a run does; raises its SceneError. Returns the scene."""
        self._doc.check()
        return self

    @property
    def dimension(self):
        """The scene's "dimension" (2 or 3)."""
        return self._doc.dimension

    @property
    def file(self):
        """The file the scene came from (or "<dict>"), as messages name it."""
        return self._doc.file

    def copy(self):
        return Scene(self._doc.copy())

    def __repr__(self):
        return f"numerics.Scene({self.file!r}, dimension={self.dimension})"


def scenes():
    """The shipped scenes, {name: path}: scenes/*.json and scenes/validation/*.json."""
    found = {}
    for sub in ("", "validation"):
        folder = os.path.join(SCENES_DIR, sub)
        if not os.path.isdir(folder):
            continue
        for name in sorted(os.listdir(folder)):
            if name.endswith(".json"):
                found[name[: -len(".json")]] = os.path.join(folder, name)
    return found
