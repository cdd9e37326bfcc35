"""The options are the registry's, defined once: keyword arguments, docstring and signature come from
the catalog the CLI uses, and a render's options round-trip."""

import inspect
import json
import os
import subprocess

import numpy as np

import pathspace


def cli_catalog():
    done = subprocess.run([os.environ["PATHSPACE_CLI"], "info", "--integrators", "--json"], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def test_every_cli_option_is_a_keyword_argument_with_its_contract():
    catalog = {o["cli"]: o for o in pathspace.options()}
    seen = set()
    info = cli_catalog()
    entries = info["integrators"] + info.get("filters", [])
    for entry in entries:
        for option in entry["options"]:
            ours = catalog["--" + option["name"]]
            assert ours["name"] == option["name"].replace("-", "_")
            assert ours["type"] == option["type"]
            seen.add(ours["cli"])
    assert seen == set(catalog), "options only one side knows: {}".format(seen ^ set(catalog))


def test_docstring_and_signature_list_every_option():
    signature = inspect.signature(pathspace.render)
    for option in pathspace.options():
        assert option["name"] in signature.parameters
        assert signature.parameters[option["name"]].default == option["default"]
        assert "    {} (".format(option["name"]) in pathspace.render.__doc__


def test_options_of_one_integrator_and_filter():
    names = {o["name"] for o in pathspace.options("pt", "hashed")}
    assert "psf_scale" in names and "max_depth" in names
    assert "sppm_alpha" not in names
    assert all("pt" in o["integrators"] for o in pathspace.options("pt"))


def test_options_round_trip(small_scene):
    first = pathspace.render(small_scene, "pt", spp=2, filter="hashed", psf_scale=7.5, max_depth=5, seed=2, progress=False)
    assert first.options["psf_scale"] == 7.5
    assert first.options["max_depth"] == 5
    every = {o["name"] for o in pathspace.options("pt", "hashed")}
    assert set(first.options) == every
    again = pathspace.render(small_scene, "pt", spp=2, filter="hashed", seed=2, progress=False, **first.options)
    assert again.options == first.options
    assert np.array_equal(again.image, first.image)


def test_defaults_given_explicitly_change_nothing(small_scene):
    plain = pathspace.render(small_scene, "bpt", spp=1, seed=4, progress=False)
    defaults = {o["name"]: o["default"] for o in pathspace.options("bpt")}
    explicit = pathspace.render(small_scene, "bpt", spp=1, seed=4, progress=False, **defaults)
    assert plain.options == explicit.options
    assert np.array_equal(plain.image, explicit.image)


def test_flags_are_bools(small_scene):
    flags = [o for o in pathspace.options("pt") if o["type"] == "flag"]
    assert flags, "pt has flag options (e.g. no_nee)"
    name = flags[0]["name"]
    on = pathspace.render(small_scene, spp=1, progress=False, **{name: True})
    off = pathspace.render(small_scene, spp=1, progress=False, **{name: False})
    assert on.options[name] is True and off.options[name] is False
