"""Shared fixtures of the Python tests: the CLI binary that the bindings must agree with."""

import os
import subprocess
import sys

import pytest

if "PATHSPACE_SOURCE_DIR" in os.environ:
    sys.path.insert(0, os.path.join(os.environ["PATHSPACE_SOURCE_DIR"], "tests", "python"))


@pytest.fixture(scope="session")
def cli():
    """Runs `pathspace ARGS...`; returns the CompletedProcess (text output)."""
    binary = os.environ.get("PATHSPACE_CLI")
    if not binary:
        pytest.fail("PATHSPACE_CLI is not set (ctest sets it to the pathspace binary)")

    def run(*args, check=True):
        done = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, timeout=300)
        if check and done.returncode != 0:
            raise AssertionError("pathspace {} failed ({}):\n{}".format(" ".join(map(str, args)), done.returncode, done.stderr))
        return done

    return run


@pytest.fixture(scope="session")
def small_scene():
    import pathspace
    return pathspace.Scene.load("cornell-box", resolution=(24, 20))
