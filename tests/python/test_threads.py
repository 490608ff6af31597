"""The GIL is released while the engine refines: other Python threads keep running."""
import threading
import time

import numpy as np
import pytest

import subdivkit as sk
from conftest import MESHES


def test_other_threads_run_during_refinement():
    cube = sk.read_mesh(MESHES / "cube.obj")
    started = time.perf_counter()
    sk.refine(cube, "catmull-clark", 8, threads=1)
    duration = time.perf_counter() - started
    if duration < 0.05:
        pytest.skip(f"refinement took {duration:.3f} s: too fast to observe")

    ticks = []
    worker = threading.Thread(target=lambda: sk.refine(cube, "catmull-clark", 8, threads=1))
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    # Holding the GIL would stall this loop for the whole refinement: one long gap.
    gaps = np.diff(ticks) if len(ticks) > 1 else np.array([duration])
    assert len(ticks) >= 5
    assert gaps.max() < duration / 2
