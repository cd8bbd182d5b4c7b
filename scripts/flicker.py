# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""How much a technique's shadow changes from frame to frame while the light
moves, against how much the ray-cast truth's does: a shadow that snaps or
shimmers changes more than the truth. Run by scripts/flicker.sh.

For every quality scene and a dense isosurface, the first light turns about
the vertical axis through the camera's focal point, --step radians a frame
(default 0.05), for --frames frames. Each frame is drawn with --shadow-only
by each technique and by `softshadows truth`; the change of a frame is the
mean absolute difference of the visibility from the frame before, over the
pixels quality is measured on in both. Prints, per scene and technique, the
mean change over the truth's mean change (1.0: as steady as the truth) and
the mean RMSE against the truth over the frames. A shadow sharper than the
truth's changes more than it as its edges move, steady or not: `hard` is
the yardstick.

    python3 scripts/flicker.py SOFTSHADOWS [--techniques silhouette,...]
        [--scenes columns,...,gyroid] [--frames N] [--step RADIANS]
        [--size WxH] [--samples N] [--shadows JSON] [--json]

--shadows merges technique parameters into every scene's "shadows" object,
e.g. '{"silhouette": {"overlap_samples": 8}}'.
"""
import argparse
import glob
import json
import math
import os
import sys
import tempfile

import numpy as np

from common import read_png, run
from scale import isosurface_scene  # the scale benchmark's dense isosurface

QUALITY = sorted(glob.glob("Examples/Scenes/quality/*.json"))


def turned(scene, angle):
    """`scene` with its first light turned by `angle` about the vertical (+y)
    axis through the camera's focal point."""
    scene = json.loads(json.dumps(scene))
    centre = np.array(scene.get("camera", {}).get("focal_point", [0.0, 0.0, 0.0]), float)
    c, s = math.cos(angle), math.sin(angle)
    rotation = np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    light = scene["lights"][0]
    for key in ("position", "focal_point"):
        if key in light:
            light[key] = (centre + rotation @ (np.array(light[key], float) - centre)).tolist()
    if "direction" in light:
        light["direction"] = (rotation @ np.array(light["direction"], float)).tolist()
    return scene


def frames(program, scene, techniques, count, step, size, samples):
    """{technique or "truth": [visibility]}, and the quality masks."""
    drawn = {name: [] for name in ["truth"] + techniques}
    masks = []
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "scene.json")
        image = os.path.join(folder, "frame.png")
        mask = os.path.join(folder, "mask.png")
        for k in range(count):
            with open(path, "w") as f:
                json.dump(turned(scene, k * step), f)
            run(program, "truth", path, "--size", size, "--samples", str(samples), "--output",
                image, "--mask", mask, "--quiet")
            drawn["truth"].append(read_png(image)[:, :, 0] / 255.0)
            masks.append(read_png(mask)[:, :, 0] == 255)
            for technique in techniques:
                run(program, "render", path, "--technique", technique, "--size", size,
                    "--shadow-only", "--output", image, "--quiet")
                drawn[technique].append(read_png(image)[:, :, 0] / 255.0)
    return drawn, masks


def measure(drawn, masks):
    """{technique: {"change": mean change / the truth's, "rmse": mean RMSE}}"""
    def change(images):
        return float(np.mean([np.abs(b - a)[m0 & m1].mean() for a, b, m0, m1 in
                              zip(images, images[1:], masks, masks[1:])]))
    truth = change(drawn["truth"])
    figures = {}
    for technique, images in drawn.items():
        if technique == "truth":
            continue
        rmse = np.mean([math.sqrt(((image - t)[m] ** 2).mean())
                        for image, t, m in zip(images, drawn["truth"], masks)])
        figures[technique] = {"change": change(images) / truth, "rmse": float(rmse),
                              "truth_change": truth}
    return figures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("program")
    parser.add_argument("--techniques", default="hard,silhouette,smoothies,contact")
    parser.add_argument("--scenes", default=",".join(
        [os.path.splitext(os.path.basename(p))[0] for p in QUALITY] + ["gyroid"]))
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--step", type=float, default=0.05)
    parser.add_argument("--size", default="160x120")
    parser.add_argument("--samples", type=int, default=256)
    parser.add_argument("--gyroid-resolution", type=int, default=100)
    parser.add_argument("--shadows", type=json.loads, default={},
                        help="technique parameters merged into each scene's \"shadows\"")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    techniques = args.techniques.split(",")
    for name in args.scenes.split(","):
        if name == "gyroid":
            scene = isosurface_scene(args.gyroid_resolution)
        else:
            with open("Examples/Scenes/quality/%s.json" % name) as f:
                scene = json.load(f)
        shadows = scene.setdefault("shadows", {})
        for technique, parameters in args.shadows.items():
            shadows[technique] = dict(shadows.get(technique, {}), **parameters)
        drawn, masks = frames(args.program, scene, techniques, args.frames, args.step, args.size,
                              args.samples)
        for technique, figure in measure(drawn, masks).items():
            if args.json:
                print(json.dumps(dict(figure, scene=name, technique=technique)))
            else:
                print("%-10s %-12s change %.2f x truth's, RMSE %.4f" % (
                    name, technique, figure["change"], figure["rmse"]))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
