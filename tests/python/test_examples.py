"""The three examples (examples/) run, at tiny sizes, and write what they say."""

import os
import subprocess
import sys

import pytest

EXAMPLES = os.path.join(os.environ.get("PATHSPACE_SOURCE_DIR", ""), "examples")


def run(tmp_path, script, *args):
    done = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), *args], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300, env=dict(os.environ, MPLBACKEND="Agg"))
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_filter_noise_vs_voxel_size(tmp_path):
    pytest.importorskip("matplotlib")
    out = run(tmp_path, "filter_noise_vs_voxel_size.py", "--size", "32", "--spp", "2", "--reference-spp", "16", "--scales", "2,8",
              "--out", "noise.png")
    assert (tmp_path / "noise.png").stat().st_size > 1000
    assert out.count("voxel size") == 2


def test_equal_time_integrators(tmp_path):
    out = run(tmp_path, "equal_time_integrators.py", "--size", "24", "--seconds", "0.2", "--reference-spp", "8", "--write")
    for integrator in ["pt", "lt", "bpt", "sppm", "pclt"]:
        assert integrator in out
        assert (tmp_path / (integrator + ".png")).exists()


def test_camera_orbit(tmp_path):
    run(tmp_path, "camera_orbit.py", "--size", "24", "--frames", "3", "--spp", "1", "--out-dir", "orbit")
    frames = sorted(p.name for p in (tmp_path / "orbit").iterdir())
    assert frames == ["frame-000.png", "frame-001.png", "frame-002.png"]
