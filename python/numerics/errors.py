"""The exceptions of numerics: each carries the one-line message the apps print after
"error:" and the exit code they return for it (docs/scenes.md)."""


class Error(Exception):
    """A numerics error: ``str(e)`` is the apps' message, ``e.exit_code`` their exit code."""

    def __init__(self, message, exit_code):
        super().__init__(message)
        self.message = message
        self.exit_code = exit_code


class SceneError(Error):
    """A scene the apps refuse: file missing (3), bad JSON (4), bad content (5), expression (6)."""


class RunError(Error):
    """A run that cannot start or go on: bad options (2), output (7), checkpoint (8),
    unstable (9), plugin (10), resources (11), no GPU (12), internal (1)."""


class StaleParticlesError(Error):
    """Particles read after a step: ``sim.particles`` again gives the current ones."""

    def __init__(self, message):
        super().__init__(message, 2)
