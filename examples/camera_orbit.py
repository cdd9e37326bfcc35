"""A camera orbit: the camera turns about the scene's centre, one PNG per frame, filtered with the
hashed path space filter at a few samples per pixel.

    scripts/python examples/camera_orbit.py --frames 36 --out-dir orbit
    ffmpeg -i orbit/frame-%03d.png orbit.mp4
"""

import argparse
import math
import os

import numpy as np

import pathspace


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="cornell-box")
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--frames", type=int, default=36)
    parser.add_argument("--degrees", type=float, default=30.0, help="the whole orbit's angle")
    parser.add_argument("--spp", type=int, default=4)
    parser.add_argument("--out-dir", default="orbit")
    args = parser.parse_args()

    scene = pathspace.Scene.load(args.scene, resolution=(args.size, args.size))
    start = scene.camera
    centre = np.array(scene.bounding_sphere[0])
    offset = np.array(start.position) - centre
    os.makedirs(args.out_dir, exist_ok=True)
    for frame in range(args.frames):
        angle = math.radians(args.degrees) * (frame / max(1, args.frames - 1) - 0.5)
        c, s = math.cos(angle), math.sin(angle)
        camera = scene.camera
        camera.position = tuple(centre + np.array([c * offset[0] + s * offset[2], offset[1], -s * offset[0] + c * offset[2]]))
        camera.target = tuple(centre)
        camera.up = (0.0, 1.0, 0.0)
        scene.camera = camera
        result = pathspace.render(scene, "pt", spp=args.spp, filter="hashed", seed=frame, progress=False)
        path = os.path.join(args.out_dir, "frame-{:03d}.png".format(frame))
        pathspace.write_image(path, result.image)
        print(path)


if __name__ == "__main__":
    main()
