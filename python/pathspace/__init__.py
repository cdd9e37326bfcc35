"""pathspace: path space filtering and pixel cache light tracing, from Python.

    import pathspace
    scene = pathspace.Scene.load("cornell-box", resolution=(256, 256))
    result = pathspace.render(scene, "pt", spp=16, filter="hashed", psf_scale=12)
    result.image          # float32 numpy array, height x width x 3, linear RGB

The module is built for Debian's interpreter, /usr/bin/python3 (docs/python.md). Every integrator
and filter option is a keyword argument of render() with the CLI's name (--psf-scale: psf_scale);
see pathspace.options() and help(pathspace.render).
"""

from ._core import (  # noqa: F401  (the public API)
    Camera,
    Error,
    Scene,
    SceneError,
    build_type,
    builtin_scene_info,
    builtin_scenes,
    compare,
    devices,
    filters,
    integrators,
    read_image,
    write_image,
)
from ._options import options
from ._render import RenderInterrupted, RenderResult, render

__all__ = [
    "Camera",
    "Error",
    "RenderInterrupted",
    "RenderResult",
    "Scene",
    "SceneError",
    "build_type",
    "builtin_scene_info",
    "builtin_scenes",
    "compare",
    "devices",
    "filters",
    "integrators",
    "options",
    "read_image",
    "render",
    "write_image",
]
