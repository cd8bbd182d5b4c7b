# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The Python examples (Examples/Python) run as the README writes them, with
this build's package, and each shows what it says: its shadowed image
darkens part of the scene against the same scene drawn without the pass
(--plain) and leaves most of it as VTK draws it; the ground-truth example's
reference is close to the ray-cast truth and hard is not."""
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

import shadowtest as st

examples = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Examples",
                        "Python")
SHADOWED = ("shadowed_scene", "point_light_room", "silhouette_fence", "smoothies_cylinder",
            "aliasfree_area_light", "reader_pipeline")
try:
    import pyvista  # noqa: F401
    SHADOWED += ("pyvista_shadows",)  # Debian 13 and later
except ImportError:
    print("PyVista is not installed: pyvista_shadows.py not run")


def run(name, *args):
    result = subprocess.run([sys.executable, os.path.join(examples, name + ".py")] + list(args),
                            capture_output=True, text=True, timeout=600)
    st.check(result.returncode == 0, "%s %s: runs (%d %s)" % (
        name, " ".join(args), result.returncode, result.stderr[-300:]))
    return result.stdout


with tempfile.TemporaryDirectory() as folder:
    for name in SHADOWED:
        shadowed = os.path.join(folder, name + ".png")
        plain = os.path.join(folder, name + "-plain.png")
        st.check(run(name, shadowed).strip() == shadowed, "%s: prints the image's path" % name)
        run(name, plain, "--plain")
        darkening = st.read_png(plain)[..., 0].astype(float) - st.read_png(shadowed)[..., 0]
        shadow = (darkening > 40).mean()
        same = (abs(darkening) < 8).mean()
        st.check(0.01 < shadow < 0.5 and same > 0.4,
                 "%s: %.1f%% of pixels in shadow, %.0f%% as VTK draws them" % (
                     name, 100 * shadow, 100 * same))
        # Soft: the light's radius gives a penumbra, partly darkened pixels
        # (15-85% of the umbra's darkening) beside the umbra's.
        deep = np.percentile(darkening[darkening > 40], 90)
        partial = ((darkening > 0.15 * deep) & (darkening < 0.85 * deep)).sum()
        umbra = (darkening >= 0.85 * deep).sum()
        st.check(partial > 0.15 * umbra, "%s: soft, %d penumbra pixels beside %d of umbra" % (
            name, partial, umbra))

    # Without an argument, the image is named after the example, here.
    subprocess.run([sys.executable, os.path.join(examples, "shadowed_scene.py")], cwd=folder,
                   check=True, capture_output=True)
    st.check(os.path.exists(os.path.join(folder, "shadowed_scene.png")),
             "shadowed_scene.py writes shadowed_scene.png without arguments")

    # Shadows as data: the city block's day at 48 degrees north in December
    # is as long as the sun's geometry says, the highest roofs see all of
    # it and many of the streets little.
    image = os.path.join(folder, "sun_hours.png")
    printed = run("sun_hours", image, "--samples", "4")
    numbers = [float(x) for x in re.findall(r"[0-9]+\.?[0-9]*", printed.split("\n", 1)[1])]
    latitude, day, daylight, roof_low, roof_high, street = numbers
    from vtksoftshadows import vtkSolarPosition
    declination = math.radians(vtkSolarPosition.GetDeclination(day, 12.0))
    expected = 2 * math.degrees(math.acos(-math.tan(math.radians(latitude)) *
                                          math.tan(declination))) / 15
    st.check(os.path.exists(image) and abs(daylight - expected) <= 0.25 and
             roof_high == daylight and roof_low < daylight and 10 < street < 95,
             "sun_hours: %.2f hours of daylight (%.2f by the sun's geometry), roofs %.2f to "
             "%.2f, %.0f%% of the streets under two hours" % (
                 daylight, expected, roof_low, roof_high, street))

    printed = run("ground_truth", os.path.join(folder, "ground_truth.png"))
    rmse = {m[0]: float(m[1]) for m in re.findall(r"^(\w+) +RMSE[^:]*: ([0-9.]+)", printed, re.M)}
    st.check(rmse.get("reference", 1) < 0.01 and rmse.get("hard", 0) > 3 * rmse["reference"],
             "ground_truth: reference %.4f, hard %.4f against the ray-cast truth" % (
                 rmse.get("reference", -1), rmse.get("hard", -1)))
