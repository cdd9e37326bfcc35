"""The Python bindings' overhead (issue: a 64x64 1-spp render through Python costs at most 1 ms more
than the same render in C++). Times pathspace.render() and the same render done in C++ alone
(pathspace._core._native_render_seconds: session, pass, snapshot and statistics, without the
conversions to Python) in one process, interleaved in rounds, and prints the medians and their
difference.

    scripts/python bench/python/overhead.py [--size 64] [--spp 1] [--rounds 15] [--repeats 20]
"""

import argparse
import statistics
import time

import pathspace
from pathspace import _core


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--spp", type=int, default=1)
    parser.add_argument("--rounds", type=int, default=15, help="interleaved rounds; the medians are over them")
    parser.add_argument("--repeats", type=int, default=20, help="renders per round and side")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--filter", default="none")
    args = parser.parse_args()

    scene = pathspace.Scene.load("cornell-box", resolution=(args.size, args.size))
    pathspace.render(scene, spp=args.spp, filter=args.filter, threads=args.threads, progress=False)  # builds the accel once
    python_ms, native_ms = [], []
    for _ in range(args.rounds):
        start = time.perf_counter()
        for _ in range(args.repeats):
            pathspace.render(scene, spp=args.spp, filter=args.filter, threads=args.threads, progress=False)
        python_ms.append((time.perf_counter() - start) / args.repeats * 1e3)
        seconds = _core._native_render_seconds(scene, "pt", args.filter, {}, args.spp, 0, args.threads, args.repeats)
        native_ms.append(sum(seconds) / len(seconds) * 1e3)
    py, cpp = statistics.median(python_ms), statistics.median(native_ms)
    print("{}x{} {} spp, filter {}: medians of {} rounds x {} renders".format(args.size, args.size, args.spp, args.filter,
                                                                              args.rounds, args.repeats))
    print("  C++ alone     {:8.3f} ms per render (min {:.3f}, max {:.3f})".format(cpp, min(native_ms), max(native_ms)))
    print("  from Python   {:8.3f} ms per render (min {:.3f}, max {:.3f})".format(py, min(python_ms), max(python_ms)))
    print("  overhead      {:8.3f} ms ({:.2f}x)".format(py - cpp, py / cpp))


if __name__ == "__main__":
    main()
