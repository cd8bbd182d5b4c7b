# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Every technique on every quality scene against the ray-cast truth
(`softshadows quality`), with frame times (`softshadows bench`): prints the
table and, unless --no-docs, rewrites docs/quality.md's table between its
markers, the pictures docs/quality/<scene>.png and the plot
docs/quality/rmse-vs-time.png. Run by scripts/quality.sh.

    python3 scripts/quality.py SOFTSHADOWS [--no-docs]
"""
import glob
import json
import os
import sys
import tempfile

import numpy as np

from common import run

TECHNIQUES = ["hard", "reference", "reference:sphere", "contact", "contact:gaussian",
              "contact:multipass", "omni", "silhouette", "smoothies", "aliasfree"]
SCENES = sorted(glob.glob("Examples/Scenes/quality/*.json"))
DOC = "docs/quality.md"
BEGIN, END = "<!-- quality table: scripts/quality.sh -->", "<!-- end of quality table -->"


def json_lines(text):
    return [json.loads(line) for line in text.splitlines() if line.startswith("{")]


def measure(program):
    """{scene: {technique: {"rmse", "mismatch", "umbra", "penumbra_ratio", "ratio"}}}"""
    figures = {}
    for path in SCENES:
        name = os.path.splitext(os.path.basename(path))[0]
        quality = json_lines(run(program, "quality", path, "--techniques", ",".join(TECHNIQUES),
                                 "--json"))
        timing = json_lines(run(program, "bench", path, "--techniques", ",".join(TECHNIQUES),
                                "--frames", "10", "--json"))
        ratios = {t["technique"]: t["ratio_to_hard"] for t in timing}
        figures[name] = {q["technique"]: dict(q, ratio=ratios[q["technique"]]) for q in quality}
    return figures


def table(figures):
    """Five markdown tables, scenes as rows: RMSE (and its ratio to
    `hard`'s), mismatch, the umbra's mean visibility, the penumbra's pixels
    over the truth's, frame time over `hard`'s."""
    def one(title, cell):
        lines = ["| %s | " % title + " | ".join("`%s`" % t for t in TECHNIQUES) + " |",
                 "|---|" + "---|" * len(TECHNIQUES)]
        for scene in figures:
            lines.append("| %s | " % scene + " | ".join(
                cell(figures[scene], t) for t in TECHNIQUES) + " |")
        return "\n".join(lines)

    def rmse(f, t):
        ratio = "" if t == "hard" else " (%.2f)" % (f[t]["rmse"] / f["hard"]["rmse"])
        return "%.4f%s" % (f[t]["rmse"], ratio)

    return "\n\n".join([
        one("RMSE (/ `hard`)", rmse),
        one("mismatch", lambda f, t: "%.1f%%" % (100 * f[t]["mismatch"])),
        one("umbra (mean visibility where the truth is umbra)", lambda f, t: "%.3f" % f[t]["umbra"]),
        one("penumbra pixels / the truth's", lambda f, t: "%.2f" % f[t]["penumbra_ratio"]),
        one("frame time / `hard`", lambda f, t: "%.2f" % f[t]["ratio"])])


def read_picture(path):
    """A shadow-only PNG as RGB for imshow, top row first: the visibility in
    grey, the background (alpha 0) dark blue."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[::-1] / 255.0
    grey = np.repeat(pixels[:, :, :1], 3, axis=2)
    return np.where(pixels[:, :, 1:2] > 0.5, grey, np.array([0.15, 0.2, 0.35]))


def pictures(program, figures):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs("docs/quality", exist_ok=True)
    with tempfile.TemporaryDirectory() as folder:
        for path in SCENES:
            name = os.path.splitext(os.path.basename(path))[0]
            images = [("truth", os.path.join(folder, "truth.png"))]
            run(program, "truth", path, "--output", images[0][1])
            for technique in TECHNIQUES:
                out = os.path.join(folder, technique.replace(":", "_") + ".png")
                run(program, "render", path, "--technique", technique, "--shadow-only",
                    "--output", out)
                images.append((technique, out))
            fig, axes = plt.subplots(1, len(images), figsize=(2.4 * len(images), 2.1))
            for axis, (label, image) in zip(axes, images):
                axis.imshow(read_picture(image), interpolation="nearest")
                rmse = "" if label == "truth" else "\n%.4f" % figures[name][label]["rmse"]
                axis.set_title(label + rmse, fontsize=7)
                axis.axis("off")
            fig.savefig("docs/quality/%s.png" % name, dpi=110, bbox_inches="tight",
                        pad_inches=0.05)
            plt.close(fig)

    fig, axis = plt.subplots(figsize=(6.0, 4.0))
    for technique in TECHNIQUES:
        x = [figures[s][technique]["ratio"] for s in figures]
        y = [figures[s][technique]["rmse"] for s in figures]
        axis.scatter(x, y, s=14, alpha=0.35)
        axis.scatter([np.median(x)], [np.mean(y)], s=60, marker="D",
                     color=axis.collections[-1].get_facecolor()[0][:3], label=technique)
    axis.set_xscale("log")
    axis.set_xlabel("frame time / hard's (log; each scene faint, median bold)")
    axis.set_ylabel("RMSE against the ray-cast truth (mean bold)")
    axis.legend(fontsize=7)
    axis.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig("docs/quality/rmse-vs-time.png", dpi=110)
    plt.close(fig)


def main():
    program = sys.argv[1]
    figures = measure(program)
    text = table(figures)
    print(text)
    if "--no-docs" in sys.argv:
        return
    with open(DOC) as f:
        doc = f.read()
    start, end = doc.index(BEGIN) + len(BEGIN), doc.index(END)
    with open(DOC, "w") as f:
        f.write(doc[:start] + "\n" + text + "\n" + doc[end:])
    pictures(program, figures)


if __name__ == "__main__":
    main()
