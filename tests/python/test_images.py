"""Image files and metrics: read_image and write_image round-trip, compare equals `pathspace compare`."""

import json

import numpy as np
import pytest

import pathspace


@pytest.mark.parametrize("extension", ["exr", "pfm"])
def test_float_formats_round_trip_exactly(tmp_path, extension):
    rng = np.random.default_rng(1)
    image = (rng.random((7, 5, 3)) * 10).astype(np.float32)
    path = tmp_path / ("x." + extension)
    pathspace.write_image(str(path), image)
    assert np.array_equal(pathspace.read_image(path), image)


def test_png_is_srgb_8_bit(tmp_path):
    image = np.full((3, 4, 3), 0.5, np.float32)
    pathspace.write_image(tmp_path / "x.png", image)
    back = pathspace.read_image(tmp_path / "x.png")
    assert back.shape == (3, 4, 3)
    assert np.allclose(back, 0.5, atol=0.01)


def test_grey_arrays_and_other_dtypes_are_accepted(tmp_path):
    grey = np.arange(6, dtype=np.float64).reshape(2, 3)
    pathspace.write_image(tmp_path / "g.exr", grey)
    back = pathspace.read_image(tmp_path / "g.exr")
    assert np.array_equal(back, np.repeat(grey[:, :, None], 3, axis=2).astype(np.float32))


def test_write_replaces_a_file_whole(tmp_path):
    path = tmp_path / "x.exr"
    pathspace.write_image(path, np.ones((4, 4, 3)))
    pathspace.write_image(path, np.zeros((2, 2, 3)))
    assert pathspace.read_image(path).shape == (2, 2, 3)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.exr"]  # no temporary left behind


def test_compare_equals_the_cli(cli, tmp_path, small_scene):
    test = pathspace.render(small_scene, spp=2, seed=1, progress=False)
    reference = pathspace.render(small_scene, spp=16, seed=2, progress=False)
    paths = {name: tmp_path / (name + ".exr") for name in ("test", "reference", "variance")}
    pathspace.write_image(paths["test"], test.image)
    pathspace.write_image(paths["reference"], reference.image)
    pathspace.write_image(paths["variance"], reference.variance)
    ours = pathspace.compare(test.image, reference.image, reference.variance)
    from_files = pathspace.compare(paths["test"], str(paths["reference"]), reference_variance=paths["variance"])
    expected = json.loads(cli("compare", paths["test"], paths["reference"], "--reference-variance", paths["variance"], "--json").stdout)
    for key in ("mse", "rel_mse", "mean_image", "mean_reference", "block", "block_rel_mse", "blotched_share", "flip"):
        assert ours[key] == expected[key], key
        assert from_files[key] == expected[key], key
    assert pathspace.compare(test.image, test.image)["rel_mse"] == 0.0
    blocks = json.loads(cli("compare", paths["test"], paths["reference"], "--block", "4", "--flip-ppd", "30", "--json").stdout)
    ours = pathspace.compare(test.image, reference.image, block=4, flip_ppd=30)
    for key in ("block", "block_rel_mse", "blotched_share", "flip"):
        assert ours[key] == blocks[key], key
