"""Progress: a callback after every pass with the fraction done and the statistics so far, or a tqdm
bar; renders by time."""

import numpy as np
import pytest

import pathspace


def test_callback_after_every_pass(small_scene):
    calls = []
    result = pathspace.render(small_scene, spp=5, progress=lambda fraction, stats: calls.append((fraction, stats["spp"])))
    assert [spp for _, spp in calls] == [1, 2, 3, 4, 5]
    assert [f for f, _ in calls] == pytest.approx([0.2, 0.4, 0.6, 0.8, 1.0])
    assert result.spp == 5


def test_tqdm_bar(small_scene, capsys):
    pytest.importorskip("tqdm")
    result = pathspace.render(small_scene, spp=3, progress=True)
    assert result.spp == 3
    assert "pathspace" in capsys.readouterr().err


def test_render_by_time(small_scene):
    result = pathspace.render(small_scene, time=0.2, progress=False)
    assert result.spp >= 1
    assert result.stats["wall_time_s"] >= 0.0


def test_result_arrays_are_copies(small_scene):
    first = pathspace.render(small_scene, spp=1, progress=False)
    assert first.image.flags.owndata or first.image.base is not None
    image = first.image.copy()
    first.image[:] = 0  # writing to the array does not reach any later render
    second = pathspace.render(small_scene, spp=1, progress=False)
    assert np.array_equal(second.image, image)
    assert repr(second).startswith("<pathspace.RenderResult 24x20, 1 spp")


def test_aovs_are_arrays(small_scene):
    choice = [o for o in pathspace.options("pt", "hashed") if "aov" in o["name"]]
    if not choice:
        pytest.skip("the hashed filter has no AOV option")
    option = choice[0]
    value = True if option["type"] == "flag" else option["choices"][-1]
    result = pathspace.render(small_scene, spp=1, filter="hashed", progress=False, **{option["name"]: value})
    assert result.aovs
    for name, array in result.aovs.items():
        assert array.shape == (20, 24, 3), name
