"""The extension module of `pip install .` (pyproject.toml holds the package's metadata).

setuptools cannot compile pathspace itself; this build_ext runs CMake for the one target
`pathspace_python` and copies the module it makes into the wheel. The CMake build folder is
build/pip (kept, so a second install only relinks), or PATHSPACE_BUILD_DIR to reuse a configured
build such as the test suite's. Parallel jobs: CMAKE_BUILD_PARALLEL_LEVEL, else every core.
"""
import os
import pathlib
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = pathlib.Path(os.environ.get("PATHSPACE_BUILD_DIR") or ROOT / "build" / "pip").resolve()
        if not (build_dir / "CMakeCache.txt").exists():
            # Only what the module needs: no tests, benchmarks, CUDA check or MPI.
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), *generator, "-DCMAKE_BUILD_TYPE=Release",
                            "-DPATHSPACE_PYTHON=ON", f"-DPATHSPACE_PYTHON_EXECUTABLE={sys.executable}",
                            "-DPATHSPACE_BUILD_TESTS=OFF", "-DPATHSPACE_BUILD_BENCHMARKS=OFF", "-DPATHSPACE_CUDA=OFF",
                            "-DPATHSPACE_MPI=OFF"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "pathspace_python", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build_dir / "python" / "pathspace" / ("_core" + suffix)
        if not built.exists():
            sys.exit(f"pathspace: {built} was not built: the CMake build in {build_dir} is for another Python "
                     f"than {sys.executable} (PATHSPACE_PYTHON_EXECUTABLE)")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


(ROOT / "build").mkdir(exist_ok=True)  # egg_info's folder must exist
setup(
    ext_modules=[Extension("pathspace._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own build folder inside CMake's, not next to it under the same name.
    options={"build": {"build_base": "build/setuptools"}, "egg_info": {"egg_base": "build"}},
)
