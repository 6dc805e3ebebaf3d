"""Checks of the arguments of the module's functions: each bad one raises numerics.RunError (or
SceneError for a Scene's), exit code 2 (the apps' bad command line), naming the parameter, what
was expected and what was found."""
import math
import numbers
import os

from .errors import RunError

# run(every=...): at most this many callback times in one run() (each is a step landing on it).
MAX_CALLBACKS = 10_000_000


def found(value):
    """`value` as messages show it: its repr, and its type unless it is an int or a float."""
    text = repr(value)
    if len(text) > 60:
        text = text[:57] + "..."
    return text if type(value) in (int, float) else f"{text} ({type(value).__name__})"


def refuse(name, expected, value, error=RunError, extra=""):
    raise error(f"{name}: expected {expected}, found {found(value)}{extra}", 2)


def is_number(value):
    """A real number that is not a bool (True is 1 to Python, not to a user)."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def number(name, value, positive=False, error=RunError):
    """`value` as a finite float (> 0 where `positive`), else the error naming `name`."""
    expected = "a finite number" + (" > 0" if positive else "")
    if not is_number(value):
        refuse(name, expected, value, error)
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        refuse(name, expected, value, error)
    if not math.isfinite(x) or (positive and not x > 0):
        refuse(name, expected, value, error)
    return x


def whole(name, value, low, high, error=RunError):
    """`value` as an int from low to high."""
    if not isinstance(value, numbers.Integral) or isinstance(value, bool) or \
            not low <= int(value) <= high:
        refuse(name, f"a whole number from {low} to {high}", value, error)
    return int(value)


def flag(name, value, error=RunError):
    """`value` as a bool: True, False (or NumPy's)."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return bool(value)
    refuse(name, "True or False", value, error)


def path(name, value, error=RunError):
    """`value` as a path: a non-empty str or os.PathLike."""
    if isinstance(value, (str, os.PathLike)):
        text = os.fspath(value)
        if isinstance(text, str) and text and "\0" not in text:
            return text
    refuse(name, "a path (a non-empty str or os.PathLike)", value, error)


def callable_or_none(name, value, error=RunError):
    if value is not None and not callable(value):
        refuse(name, "a function (or None)", value, error)
    return value
