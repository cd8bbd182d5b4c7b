# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""How closely each technique's pictures agree between releases: the
folders scripts/release-images.sh writes, each against the first, as a
Markdown table (docs/releases.md).

    /usr/bin/python3 scripts/compare-releases.py out/releases/bookworm \\
        out/releases/trixie out/releases/sid

Shaded pictures: the mean absolute difference in 8-bit levels over the
three channels and the share of pixels off by more than 8 levels in any.
Shadow-only pictures: the RMSE of the visibility where both have geometry
and the share of such pixels more than 0.1 apart."""
import os
import sys

import numpy as np

from common import read_png


def read(path):
    return read_png(path).astype(float)


def main(folders):
    base, others = folders[0], folders[1:]
    names = sorted(f[:-4] for f in os.listdir(base)
                   if f.endswith(".png") and not f.endswith("-shadow.png"))
    release = [os.path.basename(os.path.normpath(f)) for f in folders]
    head = ["technique"]
    for r in release[1:]:
        head += ["%s shaded: mean, >8 levels" % r, "%s shadow-only: RMSE, >0.1" % r]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for name in names:
        row = ["`%s`" % name.replace("-", ":", 1)]
        for other in others:
            a, b = read(os.path.join(base, name + ".png")), read(os.path.join(other, name + ".png"))
            diff = np.abs(a[..., :3] - b[..., :3])
            row.append("%.2f, %.2f%%" % (diff.mean(), 100 * (diff.max(axis=2) > 8).mean()))
            shadow = name + "-shadow.png"
            if os.path.exists(os.path.join(base, shadow)):
                a, b = read(os.path.join(base, shadow)), read(os.path.join(other, shadow))
                both = (a[..., 1] > 0) & (b[..., 1] > 0)
                d = (a[..., 0] - b[..., 0])[both] / 255.0
                row.append("%.4f, %.2f%%" % (np.sqrt(np.mean(d * d)),
                                             100 * np.mean(np.abs(d) > 0.1)))
            else:
                row.append("(none)")
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: compare-releases.py BASE_FOLDER OTHER_FOLDER...")
    main(sys.argv[1:])
