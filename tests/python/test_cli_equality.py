"""render() from Python equals `pathspace render` bit for bit, for each integrator and filter."""

import numpy as np
import pytest

import pathspace

CASES = [
    ("pt", "none", {}),
    ("pt", "hashed", {"psf_scale": 6}),
    ("pt", "consistent", {"psf_radius_pixels": 4}),
    ("lt", "none", {}),
    ("bpt", "none", {"max_depth": 4}),
    ("sppm", "none", {}),
    ("pclt", "none", {}),
]


def cli_arguments(options):
    out = []
    for name, value in options.items():
        out.append("--" + name.replace("_", "-"))
        if value is not True:
            out.append(str(value))
    return out


@pytest.mark.parametrize("integrator,filter,options", CASES, ids=["{}-{}".format(i, f) for i, f, _ in CASES])
def test_image_and_variance_equal_the_cli(cli, tmp_path, integrator, filter, options):
    scene = pathspace.Scene.load("cornell-box", resolution=(24, 20))
    result = pathspace.render(scene, integrator, spp=3, filter=filter, seed=7, threads=2, progress=False, **options)
    image, variance = tmp_path / "cli.exr", tmp_path / "cli-var.exr"
    cli("render", "cornell-box", "-r", "24x20", "-s", 3, "--seed", 7, "-j", 2, "-i", integrator, "--filter", filter,
        *cli_arguments(options), "-o", image, "--variance-out", variance, "-q")
    assert result.image.dtype == np.float32 and result.image.shape == (20, 24, 3)
    assert np.array_equal(result.image, pathspace.read_image(image))
    assert np.array_equal(result.variance, pathspace.read_image(variance))
    assert result.image.tobytes() == pathspace.read_image(image).tobytes()  # signed zeros too


def test_stats_have_the_cli_stats_content(cli, tmp_path):
    import json
    scene = pathspace.Scene.load("cornell-box", resolution=(16, 16))
    result = pathspace.render(scene, spp=2, filter="hashed", seed=3, progress=False)
    stats_file = tmp_path / "stats.json"
    cli("render", "cornell-box", "-r", "16x16", "-s", 2, "--filter", "hashed", "--seed", 3, "-o", tmp_path / "x.exr",
        "--stats", stats_file, "-q")
    expected = json.loads(stats_file.read_text())
    assert list(result.stats) == list(expected)
    assert list(result.stats["statistics"]) == list(expected["statistics"])
    for key in ("scene", "integrator", "filter", "width", "height", "spp", "seed", "max_segments", "build_type"):
        assert result.stats[key] == expected[key], key
    for key in ("rays", "paths", "shadow_rays"):
        assert result.stats[key] == expected[key], key  # counts are a function of the seed


def test_scene_file_with_camera_set_from_python_equals_cli_camera_options(cli, tmp_path):
    scene_file = tmp_path / "quad.obj"
    scene_file.write_text("v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 0.5 0\nf 1 2 3\nf 1 3 4\nf 1 2 5\n")
    scene = pathspace.Scene.load(str(scene_file), resolution=(20, 16))
    camera = scene.camera
    camera.position = (0.5, 2.0, 3.0)
    camera.target = (0.0, 0.1, 0.0)
    camera.up = (0.0, 1.0, 0.0)
    camera.fov = 35.0
    scene.camera = camera
    result = pathspace.render(scene, spp=2, seed=1, progress=False)
    out = tmp_path / "cli.exr"
    cli("render", scene_file, "-r", "20x16", "-s", 2, "--seed", 1, "--camera-pos", "0.5,2,3", "--camera-target", "0,0.1,0",
        "--camera-up", "0,1,0", "--fov", 35, "-o", out, "-q")
    assert np.array_equal(result.image, pathspace.read_image(out))
