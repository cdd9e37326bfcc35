"""Every error path raises the documented exception: TypeError for a keyword render() does not take,
ValueError with the CLI's message for a bad value, SceneError with file:line:column for a scene file,
pathspace.Error for image files."""

import numpy as np
import pytest

import pathspace


def test_unknown_keyword_is_a_type_error_listing_the_valid_ones(small_scene):
    with pytest.raises(TypeError) as e:
        pathspace.render(small_scene, spp=1, progress=False, psf_scal=3)
    assert "psf_scal" in str(e.value) and "max_depth" in str(e.value)


def test_keyword_of_another_filter_names_where_it_applies(small_scene):
    with pytest.raises(TypeError) as e:
        pathspace.render(small_scene, spp=1, progress=False, psf_scale=3)
    assert "filter hashed" in str(e.value)


def test_keyword_with_dashes_is_a_type_error(small_scene):
    with pytest.raises(TypeError):
        pathspace.render(small_scene, spp=1, progress=False, **{"max-depth": 3})


@pytest.mark.parametrize("keyword,value,cli_option", [("max_depth", 0, "--max-depth"), ("psf_scale", -1, "--psf-scale"),
                                                       ("max_depth", "two", "--max-depth"), ("psf_scale", float("nan"), "--psf-scale")])
def test_bad_value_is_a_value_error_with_the_cli_message(cli, small_scene, keyword, value, cli_option):
    with pytest.raises(ValueError) as e:
        pathspace.render(small_scene, spp=1, filter="hashed", progress=False, **{keyword: value})
    done = cli("render", "cornell-box", "-s", 1, "--filter", "hashed", cli_option, value, "-q", check=False)
    assert done.returncode == 2
    assert str(e.value) in done.stderr


def test_bad_choice_is_a_value_error(small_scene):
    choice = next(o for o in pathspace.options("pt", "hashed") if o["type"] == "choice")
    with pytest.raises(ValueError) as e:
        pathspace.render(small_scene, spp=1, filter="hashed", progress=False, **{choice["name"]: "no-such-choice"})
    assert choice["cli"] in str(e.value)


def test_flag_needs_a_bool(small_scene):
    flag = next(o for o in pathspace.options("pt") if o["type"] == "flag")
    with pytest.raises(TypeError):
        pathspace.render(small_scene, spp=1, progress=False, **{flag["name"]: 1})


def test_bool_for_a_number_is_a_type_error(small_scene):
    with pytest.raises(TypeError):
        pathspace.render(small_scene, spp=1, progress=False, max_depth=True)


@pytest.mark.parametrize("integrator,filter", [("nope", "none"), ("pt", "nope"), ("lt", "hashed")])
def test_unknown_integrator_or_filter_or_bad_composition_is_a_value_error(small_scene, integrator, filter):
    with pytest.raises(ValueError):
        pathspace.render(small_scene, integrator, spp=1, filter=filter, progress=False)


@pytest.mark.parametrize("kwargs", [{"spp": 1, "time": 1.0}, {"spp": 0}, {"time": -1.0}, {"threads": -1}])
def test_bad_run_arguments_are_value_errors(small_scene, kwargs):
    with pytest.raises(ValueError):
        pathspace.render(small_scene, progress=False, **kwargs)


def test_unknown_device_is_a_value_error(small_scene):
    with pytest.raises(ValueError):
        pathspace.render(small_scene, spp=1, device="abacus", progress=False)


def test_scene_file_error_has_file_line_and_column(tmp_path):
    path = tmp_path / "broken.pbrt"
    path.write_text('LookAt 0 0 5  0 0 0  0 1 0\nCamera "perspective"\nWorldBegin\nShape "sphere" "float radius" [ -2 ]\n')
    with pytest.raises(pathspace.SceneError) as e:
        pathspace.Scene.load(str(path))
    assert str(e.value).startswith(str(path) + ":4:")
    assert e.value.file == str(path) and e.value.line == 4 and e.value.column > 0
    assert isinstance(e.value, pathspace.Error)


def test_missing_scene_and_unknown_builtin_are_scene_errors(tmp_path):
    with pytest.raises(pathspace.SceneError):
        pathspace.Scene.load(str(tmp_path / "missing.pbrt"))
    with pytest.raises(pathspace.SceneError) as e:
        pathspace.Scene.load("no-such-scene")
    assert "cornell-box" in str(e.value)


def test_file_only_load_options_on_a_builtin_are_value_errors():
    with pytest.raises(ValueError):
        pathspace.Scene.load("cornell-box", animation="walk")
    with pytest.raises(ValueError):
        pathspace.Scene.load("cornell-box", resolution=(0, 10))


def test_bad_camera_values_are_value_errors(small_scene):
    camera = small_scene.camera
    for attribute, value in [("fov", 0.0), ("fov", 200.0), ("resolution", (0, 5)), ("position", (float("inf"), 0, 0)),
                             ("lens_radius", -1.0)]:
        changed = small_scene.camera
        setattr(changed, attribute, value)
        with pytest.raises(ValueError):
            small_scene.camera = changed
    same = small_scene.camera
    same.target = same.position
    with pytest.raises(ValueError):
        small_scene.camera = same
    assert small_scene.camera == camera
    with pytest.raises(ValueError):
        small_scene.light_selection = "random"


def test_image_file_errors(tmp_path):
    with pytest.raises(pathspace.Error) as e:
        pathspace.read_image(str(tmp_path / "missing.exr"))
    assert "missing.exr" in str(e.value)
    (tmp_path / "junk.png").write_bytes(b"not a png at all")
    with pytest.raises(pathspace.Error):
        pathspace.read_image(tmp_path / "junk.png")
    with pytest.raises(pathspace.Error):
        pathspace.write_image(str(tmp_path / "out.tiff"), np.zeros((2, 2, 3), np.float32))
    assert not (tmp_path / "out.tiff").exists()
    with pytest.raises(pathspace.Error):
        pathspace.write_image(str(tmp_path / "no-such-folder" / "out.exr"), np.zeros((2, 2, 3), np.float32))


@pytest.mark.parametrize("array", [np.zeros((2, 2, 4)), np.zeros(5), np.zeros((0, 3, 3))])
def test_bad_arrays_are_value_errors(tmp_path, array):
    with pytest.raises(ValueError):
        pathspace.write_image(str(tmp_path / "x.exr"), array)


def test_compare_size_mismatch_is_a_value_error():
    with pytest.raises(ValueError):
        pathspace.compare(np.zeros((2, 2, 3)), np.zeros((3, 2, 3)))


def test_callback_exception_stops_the_render_and_propagates(small_scene):
    calls = []

    def progress(fraction, stats):
        calls.append(stats["spp"])
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        pathspace.render(small_scene, spp=50, progress=progress)
    assert calls == [1]
