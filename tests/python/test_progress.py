"""refine(progress=callable) hears each phase and the share of the levels' work done."""
import pytest

import subdivkit as sk
from conftest import MESHES


def test_progress_hears_every_level_and_a_share_that_only_grows():
    calls = []
    sk.refine(sk.read_mesh(MESHES / "cube.obj"), "catmull-clark", 3, progress=lambda phase, done: calls.append((phase, done)))
    phases = [p for p, done in calls if done is None]
    assert [p for p in phases if p.startswith("level")] == ["level 1/3: 24 faces", "level 2/3: 96 faces",
                                                             "level 3/3: 384 faces"]
    shares = [done for _, done in calls if done is not None]
    assert shares[0] == 0.0 and shares[-1] == pytest.approx(1.0)
    assert all(a <= b for a, b in zip(shares, shares[1:]))
    # Faces weigh: the last of the three levels is 384 of the 504 faces made (plus one each),
    # and the share also moves inside it, after each kind of new point.
    level_2_end = (24 + 1 + 96 + 1) / (24 + 96 + 384 + 3)
    assert any(s == pytest.approx(level_2_end) for s in shares)
    assert len([s for s in shares if level_2_end + 1e-9 < s < 1 - 1e-9]) == 2


def test_an_exception_in_progress_stops_the_refinement():
    def stop(phase, done):
        if phase.startswith("level 2"):
            raise KeyboardInterrupt("stop")
    with pytest.raises(KeyboardInterrupt):
        sk.refine(sk.read_mesh(MESHES / "cube.obj"), "catmull-clark", 3, progress=stop)


def test_adaptive_refinement_tells_its_levels_and_limit_and_stops_on_an_exception():
    calls = []
    mesh = sk.read_mesh(MESHES / "cube.obj")
    sk.refine_adaptive(mesh, "catmull-clark", 4, limit=True, progress=lambda phase, done: calls.append((phase, done)))
    assert calls[0] == ("refining adaptively to level 4", None)
    shares = [done for _, done in calls if done is not None]
    assert shares and all(0 <= s <= 1 for s in shares)
    assert shares == sorted(shares), "the share only grows"
    assert any(0 < s < 1 for s in shares), shares

    def stop(phase, done):
        if done is not None and done > 0.3:
            raise KeyboardInterrupt("stopped")

    with pytest.raises(KeyboardInterrupt):
        sk.refine_adaptive(mesh, "catmull-clark", 4, limit=True, progress=stop)


@pytest.mark.parametrize("call", [lambda m, p: sk.refine(m, "catmull-clark", 2, progress=p),
                                  lambda m, p: sk.refine_adaptive(m, "catmull-clark", 2, progress=p)])
def test_a_progress_that_is_not_callable_is_refused_before_any_work(call):
    with pytest.raises(sk.Error, match=r"progress=5: give a callable progress\(phase, done\), or None"):
        call(sk.read_mesh(MESHES / "cube.obj"), 5)
