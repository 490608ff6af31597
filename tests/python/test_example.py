"""examples/python/new_scheme.py runs and writes its plot (the example the docs walk through)."""
import os
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR


def test_new_scheme_example_writes_a_png(tmp_path):
    pytest.importorskip("matplotlib")
    png = tmp_path / "spectrum.png"
    env = dict(os.environ, MPLBACKEND="Agg", MPLCONFIGDIR=str(tmp_path))
    result = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "python" / "new_scheme.py"), str(png)],
                            capture_output=True, text=True, env=env)
    assert result.returncode == 0, result.stderr
    assert "stiff-loop t=0.0 : max distance to Loop 0.0000" in result.stdout  # t = 0 is Loop
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
