"""Shared fixtures: where the sources, example meshes and the `subdiv` command line are.

ctest sets SUBDIV_SOURCE_DIR, SUBDIV_CLI and PYTHONPATH (tests/python/CMakeLists.txt); run by
hand as
    PYTHONPATH=build/python SUBDIV_CLI=build/tools/subdiv/subdiv /usr/bin/python3 -m pytest tests/python
"""
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

SOURCE_DIR = Path(os.environ.get("SUBDIV_SOURCE_DIR", Path(__file__).resolve().parents[2]))
MESHES = SOURCE_DIR / "examples" / "meshes"
CURVES = SOURCE_DIR / "examples" / "curves"
SCHEMES = SOURCE_DIR / "schemes"


def cli_path():
    return Path(os.environ.get("SUBDIV_CLI", SOURCE_DIR / "build" / "tools" / "subdiv" / "subdiv"))


def run_cli(*args, check=True):
    """Runs `subdiv ARGS`; returns the completed process (stdout and stderr as text)."""
    exe = cli_path()
    if not exe.exists():
        pytest.skip(f"the subdiv command line is not built at {exe}")
    result = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"subdiv {' '.join(map(str, args))} failed: {result.stderr}")
    return result


def cli_error(*args):
    """The message `subdiv ARGS` fails with, without its 'subdiv: error: ' prefix."""
    result = run_cli(*args, check=False)
    assert result.returncode == 1, f"expected subdiv to fail with a user error, got {result.returncode}"
    prefix = "subdiv: error: "
    line = result.stderr.strip()
    assert line.startswith(prefix), line
    return line[len(prefix):]


def parse_obj(path):
    """Points and faces of an OBJ file, parsed here with float() (full precision), not by the
    library, so that comparisons with the CLI's output have an independent reader."""
    points, faces = [], []
    for line in Path(path).read_text().splitlines():
        words = line.split()
        if not words:
            continue
        if words[0] == "v":
            points.append([float(w) for w in words[1:4]])
        elif words[0] == "f":
            faces.append([int(w.split("/")[0]) - 1 for w in words[1:]])
    return np.array(points, dtype=np.float64), faces


@pytest.fixture
def cube_path():
    return str(MESHES / "cube.obj")
