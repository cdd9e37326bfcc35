"""The five integrators at equal time: path tracing (pt), light tracing (lt), bidirectional path
tracing (bpt), stochastic progressive photon mapping (sppm) and pixel cache light tracing (pclt), each
given the same seconds, measured by relMSE against a path-traced reference.

    scripts/python examples/equal_time_integrators.py --scene cornell-box --seconds 5
"""

import argparse

import pathspace


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="cornell-box", help="built-in scene or scene file")
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--seconds", type=float, default=5.0, help="time per integrator")
    parser.add_argument("--reference-spp", type=int, default=1024)
    parser.add_argument("--write", action="store_true", help="also write each image as INTEGRATOR.png")
    args = parser.parse_args()

    scene = pathspace.Scene.load(args.scene, resolution=(args.size, args.size))
    reference = pathspace.render(scene, "pt", spp=args.reference_spp, seed=1000, progress=False)
    print("{:6} {:>8} {:>12}".format("", "passes", "relMSE"))
    for integrator in ["pt", "lt", "bpt", "sppm", "pclt"]:
        result = pathspace.render(scene, integrator, time=args.seconds, seed=1, progress=False)
        error = pathspace.compare(result.image, reference.image, reference.variance)["rel_mse"]
        print("{:6} {:8d} {:12.4g}".format(integrator, result.spp, error))
        if args.write:
            pathspace.write_image(integrator + ".png", result.image)


if __name__ == "__main__":
    main()
