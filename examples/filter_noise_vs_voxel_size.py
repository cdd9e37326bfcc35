"""The hashed path space filter's trade-off (2021 paper, fig. 4): larger voxels average more paths,
so less noise, at the price of blur. Renders the Cornell box at a few voxel sizes (--psf-scale, in
pixels) and plots the filtered image's noise (mean relative variance of the mean) and its error
(relMSE against a path-traced reference) against the voxel size.

    scripts/python examples/filter_noise_vs_voxel_size.py --out noise.png
"""

import argparse

import matplotlib

matplotlib.use("Agg")  # files only, no display needed

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pathspace  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=256, help="image width and height")
    parser.add_argument("--spp", type=int, default=4, help="samples per pixel of each filtered render")
    parser.add_argument("--reference-spp", type=int, default=1024)
    parser.add_argument("--scales", default="1,2,4,8,16,32", help="voxel sizes in pixels")
    parser.add_argument("--out", default="filter-noise.png")
    args = parser.parse_args()

    scene = pathspace.Scene.load("cornell-box", resolution=(args.size, args.size))
    reference = pathspace.render(scene, "pt", spp=args.reference_spp, seed=1000, progress=False)
    scales = [float(s) for s in args.scales.split(",")]
    noise, error = [], []
    plain = pathspace.render(scene, "pt", spp=args.spp, progress=False)
    for scale in scales:
        result = pathspace.render(scene, "pt", spp=args.spp, filter="hashed", psf_scale=scale, progress=False)
        noise.append(float(np.mean(result.variance / (result.image ** 2 + 1e-2))))
        error.append(pathspace.compare(result.image, reference.image, reference.variance)["rel_mse"])
        print("voxel size {:5.1f} px: noise {:.4g}  relMSE {:.4g}".format(scale, noise[-1], error[-1]))
    plain_error = pathspace.compare(plain.image, reference.image, reference.variance)["rel_mse"]

    figure, axis = plt.subplots(figsize=(6, 4))
    axis.loglog(scales, noise, "o-", label="noise (relative variance of the mean)")
    axis.loglog(scales, error, "s-", label="relMSE against the reference")
    axis.axhline(plain_error, color="grey", linestyle="--", label="path tracing alone, relMSE")
    axis.set_xlabel("voxel size (--psf-scale, pixels)")
    axis.set_title("Hashed path space filter, {} spp, {}x{}".format(args.spp, args.size, args.size))
    axis.legend()
    figure.tight_layout()
    figure.savefig(args.out, dpi=120)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
