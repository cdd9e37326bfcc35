#!/usr/bin/env bash
# python.pip_install (label python): `pip install` of this source tree into a fresh virtual
# environment, offline, as docs/python.md tells a user to; then the installed package renders and
# compares from a folder outside the tree. PATHSPACE_BUILD_DIR points setup.py at the suite's own
# CMake build, so the module is not compiled a second time (setup.py's fresh build is the same
# CMake target with tests off).
set -euo pipefail
src=$1 build=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/pathspace-pip.XXXXXX")
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$work/env"
PATHSPACE_BUILD_DIR="$build" "$work/env/bin/pip" install --no-build-isolation --no-index --no-deps -q "$src"
cd "$work"
"$work/env/bin/python" - "$work/env" <<'PY'
import pathlib, sys
import numpy as np
import pathspace
env = pathlib.Path(sys.argv[1]).resolve()
where = pathlib.Path(pathspace.__file__).resolve()
assert env in where.parents, f"imported {where}, not the venv's copy"
scene = pathspace.Scene.load("cornell-box", resolution=(24, 16))
r = pathspace.render(scene, "pt", spp=2, progress=False)
assert r.image.shape == (16, 24, 3) and r.image.dtype == np.float32, r.image.shape
assert np.isfinite(r.image).all() and r.image.mean() > 0.0
again = pathspace.render(scene, "pt", spp=2, progress=False)
assert np.array_equal(r.image, again.image)
print("pip_install: ok,", where)
PY
"$work/env/bin/pip" uninstall -y -q pathspace
! "$work/env/bin/python" -c "import pathspace" 2> /dev/null || { echo "FAIL: still importable after uninstall" >&2; exit 1; }
echo "ok"
