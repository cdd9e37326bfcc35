#!/usr/bin/env python3
"""pathspace against SmallVCM, side by side (docs/results/cpu-throughput.md).

SmallVCM (github.com/SmallVCM/SmallVCM, MIT licence) is not part of this project: build it yourself
outside the repository with `g++ -o smallvcm src/smallvcm.cxx -O3 -std=c++0x -fopenmp` and give its
path. For each algorithm both renderers have, the two whole processes run in turn (A B A B ...)
with the same number of threads, resolution, path length and passes; the script prints the median
wall and CPU seconds of each and the median of the pairwise ratios SmallVCM / pathspace (the
speed-up), which holds when the machine's speed drifts between runs.

    bench/smallvcm/side_by_side.py --smallvcm ~/SmallVCM/smallvcm [--pathspace build/apps/pathspace/pathspace]
        [--runs 5] [--threads 2] [--scenes glm_c gbs_p] [--only pt,lt,bpt,ppm,ppm-default]
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

# SmallVCM's scene ids for pathspace's built-in names of the same scenes (docs/scenes.md).
SCENE_IDS = {"glm_c": 1, "gbs_p": 2}
# SmallVCM's fixed settings (src/config.hxx): 512x512, paths of at most 10 segments, the photon
# mapping radius 0.003 x the scene's bounding radius shrinking with alpha = 0.75.
RESOLUTION = "512x512"
MAX_SEGMENTS = 10
RADIUS_FACTOR = 0.003
RADIUS_ALPHA = 0.75


def scene_radius(pathspace, scene):
    """The scene's bounding radius as pathspace computes it: its default SPPM radius is 1% of it
    (--sppm-radius in docs/cli.md), read from a tiny render's --stats."""
    import json
    with tempfile.TemporaryDirectory() as tmp:
        stats = os.path.join(tmp, "s.json")
        subprocess.run([pathspace, "render", scene, "-i", "sppm", "-s", "1", "-r", "8x8", "-o", os.path.join(tmp, "o.pfm"),
                        "--stats", stats], check=True, capture_output=True)
        with open(stats) as f:
            return json.load(f)["statistics"]["sppm.initial_radius"] / 0.01


def configurations(scene, radius):
    """(name, pathspace arguments, SmallVCM arguments) for one scene."""
    sid = str(SCENE_IDS[scene])
    # SmallVCM picks its lights uniformly: the same estimator, not pathspace's default light tree.
    common = [scene, "-r", RESOLUTION, "-d", str(MAX_SEGMENTS), "--light-selection", "uniform"]
    ppm_radius = f"{RADIUS_FACTOR * radius:.6g}"
    return [
        ("pt", common + ["-i", "pt", "-s", "20"], ["-s", sid, "-a", "pt", "-i", "20"]),
        # SmallVCM's light tracer does not splat the light sources themselves.
        ("lt", common + ["-i", "lt", "-s", "20", "--lt-skip-emitter"], ["-s", sid, "-a", "lt", "-i", "20"]),
        ("bpt", common + ["-i", "bpt", "-s", "8"], ["-s", sid, "-a", "bpt", "-i", "8"]),
        ("ppm", common + ["-i", "sppm", "-s", "10", "--sppm-radius", ppm_radius, "--sppm-alpha", str(RADIUS_ALPHA)],
         ["-s", sid, "-a", "ppm", "-i", "10"]),
        # pathspace's own default radius (1% of the bounding radius) against SmallVCM's.
        ("ppm-default", common + ["-i", "sppm", "-s", "10", "--sppm-alpha", str(RADIUS_ALPHA)], ["-s", sid, "-a", "ppm", "-i", "10"]),
    ]


def timed(command, env):
    """Wall and CPU (user + sys) seconds of one whole process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        sys.exit(f"failed ({done.returncode}): {' '.join(command)}\n{done.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--smallvcm", required=True, help="a SmallVCM executable built outside this repository")
    parser.add_argument("--pathspace", default=os.path.join(os.path.dirname(__file__), "..", "..", "build", "apps", "pathspace", "pathspace"))
    parser.add_argument("--runs", type=int, default=5, help="counted runs of each command (after one warm-up pair)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--scenes", nargs="+", default=["glm_c", "gbs_p"], choices=sorted(SCENE_IDS))
    parser.add_argument("--only", default="", help="comma-separated subset of pt,lt,bpt,ppm,ppm-default")
    args = parser.parse_args()
    for path in (args.smallvcm, args.pathspace):
        if not os.access(path, os.X_OK):
            sys.exit(f"not an executable: {path}")
    only = set(filter(None, args.only.split(",")))
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    print(f"{'scene':7} {'algorithm':12} {'pathspace wall s':>16} {'SmallVCM wall s':>16} {'speed-up (wall)':>16} "
          f"{'pathspace cpu s':>16} {'SmallVCM cpu s':>15} {'speed-up (cpu)':>15}")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in args.scenes:
            radius = scene_radius(args.pathspace, scene)
            for name, ps_args, vcm_args in configurations(scene, radius):
                if only and name not in only:
                    continue
                ours = [args.pathspace, "render"] + ps_args + ["-j", str(args.threads), "-o", os.path.join(tmp, "pathspace.pfm")]
                theirs = [args.smallvcm] + vcm_args + ["-o", os.path.join(tmp, "smallvcm.hdr")]
                rows = []
                for run in range(args.runs + 1):  # the first pair warms the caches up and is not counted
                    a = timed(ours, env)
                    b = timed(theirs, env)
                    if run > 0:
                        rows.append((a, b))
                med = lambda xs: statistics.median(xs)
                print(f"{scene:7} {name:12} {med([a[0] for a, _ in rows]):16.3f} {med([b[0] for _, b in rows]):16.3f} "
                      f"{med([b[0] / a[0] for a, b in rows]):15.2f}x {med([a[1] for a, _ in rows]):16.3f} "
                      f"{med([b[1] for _, b in rows]):15.3f} {med([b[1] / a[1] for a, b in rows]):14.2f}x", flush=True)


if __name__ == "__main__":
    main()
