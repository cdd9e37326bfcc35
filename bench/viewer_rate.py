#!/usr/bin/python3
"""`pathspace view`'s frame rate and latency in a browser (docs/viewer.md, docs/benchmarks.md).

In rounds, alternately: the renderer alone (`pathspace render -t S --stats`, passes per second) and
the viewer watched by headless chromium for S seconds (frames delivered to the page per second);
then camera moves in the page (a key press) timed from the key to the first frame of the new view.
Prints the medians and the ratio delivered / alone; the viewer's own passes per second too (what
serving costs the renderer).

    bench/viewer_rate.py --pathspace build/apps/pathspace/pathspace [--resolution 640x360]
        [--seconds 5] [--rounds 3] [--moves 10] [--preview 2] [-- extra render options]
Default options: cornell-box --filter hashed --temporal integrate.
"""
import argparse
import json
import os
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "browser"))
from browser_support import make_driver  # noqa: E402


def renderer_alone(args, extra):
    with tempfile.TemporaryDirectory() as folder:
        stats = os.path.join(folder, "stats.json")
        subprocess.run([args.pathspace, "render", "cornell-box", "-r", args.resolution, "-t", str(args.seconds), "-q",
                        "-o", os.path.join(folder, "out.exr"), "--stats", stats] + extra, check=True)
        with open(stats) as f:
            j = json.load(f)
    return j["spp"] / j["wall_time_s"]


def viewer_round(args, extra, driver, moves):
    view = [args.pathspace, "view", "cornell-box", "-r", args.resolution, "--preview", str(args.preview)]
    proc = subprocess.Popen(view + extra, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    url = re.search(r"open (http://\S+)", proc.stdout.readline()).group(1)
    try:
        driver.get(url)
        frames = "return Number(document.getElementById('frame').dataset.frames || 0)"
        while driver.execute_script(frames) < 2:
            time.sleep(0.05)
        f0, t0 = driver.execute_script(frames), time.monotonic()
        time.sleep(args.seconds)
        f1, t1 = driver.execute_script(frames), time.monotonic()
        status = driver.execute_script("return document.getElementById('status').textContent")
        passes = float(re.search(r"([\d.]+) passes/s", status).group(1))
        latencies = []
        for view in range(1, moves + 1):
            # The key and the wait for its view in one script: the time is measured in the page.
            ms = driver.execute_async_script("""
const done = arguments[arguments.length - 1], view = arguments[0];
const img = document.getElementById('frame'), status = document.getElementById('status');
const start = performance.now();
document.dispatchEvent(new KeyboardEvent('keydown', {key: view % 2 ? 'a' : 'd'}));
const poll = () => { if (status.textContent.includes('view ' + view + ',')) done(performance.now() - start); else setTimeout(poll, 1); };
poll();""", view)
            latencies.append(ms)
            time.sleep(0.2)
        return (f1 - f0) / (t1 - t0), passes, latencies
    finally:
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=30)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pathspace", required=True)
    parser.add_argument("--resolution", default="640x360")
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--moves", type=int, default=10)
    parser.add_argument("--preview", type=int, default=2, help="the viewer's --preview (1: off)")
    parser.add_argument("extra", nargs="*", help="render options (after --)")
    args = parser.parse_args()
    extra = args.extra or ["--filter", "hashed", "--temporal", "integrate"]
    driver = make_driver(window="1200,800", script_timeout=60)
    alone, delivered, serving, latencies = [], [], [], []
    try:
        for _ in range(args.rounds):
            alone.append(renderer_alone(args, extra))
            fps, passes, lat = viewer_round(args, extra, driver, args.moves)
            delivered.append(fps)
            serving.append(passes)
            latencies += lat
    finally:
        driver.quit()
    med = statistics.median
    print(f"{args.resolution} {' '.join(extra)}, --preview {args.preview}, {args.rounds} rounds of {args.seconds} s")
    print(f"renderer alone:        {med(alone):.2f} passes/s  {[round(x, 2) for x in alone]}")
    print(f"frames to the page:    {med(delivered):.2f} per s   {[round(x, 2) for x in delivered]}")
    print(f"renderer while served: {med(serving):.2f} passes/s  {[round(x, 2) for x in serving]}")
    print(f"delivered / alone:     {med(delivered) / med(alone):.3f}")
    print(f"key to new view:       median {med(latencies):.0f} ms, max {max(latencies):.0f} ms over {len(latencies)} moves")
    print(f"each move (ms):        {[round(x) for x in latencies]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
