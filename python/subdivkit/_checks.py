"""Checks of the arguments every front-end function shares, so that each refuses the same
way: a wrong type is an Error naming the argument and what to give, never a silent
conversion (int(2.5) would run 2 levels; int("8") would take a string)."""

import numpy as np

from ._subdivkit import Error
from .mesh import Mesh, _type_name


def check_mesh(mesh, what):
    if not isinstance(mesh, Mesh):
        raise Error(f"{what}: expected a subdivkit.Mesh (read_mesh or Mesh(points, faces)), got {_type_name(mesh)}")


def check_whole(value, name, hint):
    """value as an int if it is a whole number (Python's or numpy's, not bool) that fits a C
    int, else an Error saying `name=value: hint`."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise Error(f"{name}={value!r}: {hint}")
    # The library takes a C int: beyond it pybind11 would raise a TypeError listing signatures.
    if not -2**31 <= int(value) < 2**31:
        raise Error(f"{name}={value!r}: beyond a 32-bit int; {hint}")
    return int(value)


def check_threads(threads):
    return check_whole(threads, "threads", "give a whole number of worker threads (0: all cores)")


def check_progress(progress, what):
    """Refuses a progress= that is neither None nor callable before any work starts."""
    if progress is not None and not callable(progress):
        raise Error(f"{what}: progress={progress!r}: give a callable progress(phase, done), or None")
