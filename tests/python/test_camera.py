"""The camera can be read and set: position, target, up, fov, resolution, thin lens."""

import numpy as np
import pytest

import pathspace


def test_reading_and_setting_back_changes_nothing():
    scene = pathspace.Scene.load("cornell-box", resolution=(24, 20))
    before = pathspace.render(scene, spp=2, seed=3, progress=False).image
    scene.camera = scene.camera
    assert np.array_equal(pathspace.render(scene, spp=2, seed=3, progress=False).image, before)


def test_values_read_back_as_set():
    scene = pathspace.Scene.load("cornell-box", resolution=(24, 20))
    camera = scene.camera
    assert camera.resolution == (24, 20)
    camera.position = (0.1, 0.2, 3.0)
    camera.target = (0.0, 0.0, 0.0)
    camera.fov = 40.0
    camera.resolution = (30, 10)
    camera.lens_radius = 0.05
    camera.focus_distance = 2.5
    scene.camera = camera
    got = scene.camera
    assert got.position == pytest.approx((0.1, 0.2, 3.0))
    direction = np.subtract(got.target, got.position)
    assert direction / np.linalg.norm(direction) == pytest.approx(-np.array(camera.position) / np.linalg.norm(camera.position), abs=1e-6)
    assert got.fov == pytest.approx(40.0, abs=1e-4)
    assert got.resolution == (30, 10)
    assert (got.lens_radius, got.focus_distance) == pytest.approx((0.05, 2.5))
    result = pathspace.render(scene, spp=1, progress=False)
    assert result.image.shape == (10, 30, 3)


def test_moving_the_camera_changes_the_image():
    scene = pathspace.Scene.load("cornell-box", resolution=(24, 24))
    before = pathspace.render(scene, spp=2, seed=3, progress=False).image
    camera = scene.camera
    camera.position = tuple(np.add(camera.position, (0.3, 0.0, 0.0)))
    scene.camera = camera
    after = pathspace.render(scene, spp=2, seed=3, progress=False).image
    assert not np.array_equal(before, after)


def test_default_light_selection_is_the_cli_default():
    # `pathspace render` picks lights with bvh unless told otherwise, built-in scenes included.
    assert pathspace.Scene.load("cornell-box", resolution=(16, 16)).light_selection == "bvh"


def test_light_selection_equals_the_cli(cli, tmp_path):
    scene = pathspace.Scene.load("cornell-box", resolution=(16, 16))
    scene.light_selection = "power"
    assert scene.light_selection == "power"
    result = pathspace.render(scene, spp=2, seed=1, progress=False)
    out = tmp_path / "x.exr"
    cli("render", "cornell-box", "-r", "16x16", "-s", 2, "--seed", 1, "--light-selection", "power", "-o", out, "-q")
    assert np.array_equal(result.image, pathspace.read_image(out))


def test_builtin_scene_listing():
    names = pathspace.builtin_scenes()
    assert "cornell-box" in names
    info = {s["name"]: s for s in pathspace.builtin_scene_info()}
    assert info["cornell-box"]["id"]
    scene = pathspace.Scene.load(info["cornell-box"]["id"])
    assert scene.name == "cornell-box" and scene.file is None
    assert repr(scene) == "<pathspace.Scene 'cornell-box' 512x512>"
