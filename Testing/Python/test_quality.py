# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Quality against physics on scenes unlike the ball (Examples/Scenes/quality,
480x360): every `contact` variant's RMSE against the ray-cast truth is at
most 0.7 times `hard`'s, its umbrae nearly as dark as the truth's and its
penumbrae about as wide, and the default variant is the best or within 10%
of the best. `grazing` is the exception docs/quality.md documents: on a
floor seen nearly edge-on the half-resolution buffers cannot hold a
penumbra a texel tall, and every variant is held to 0.9 times `hard`
there, and to 0.7 with `refine_unresolved` on, which filters those
penumbrae again in light space. `reference:sphere` is close to the truth
everywhere, and under the point light closer than `reference`'s disc.
`silhouette` (soft) is at least 20% under `hard` on every scene;
`smoothies` at least 10% (its target of 20% is not met: its umbra is the
hard shadow's, docs/quality.md). `aliasfree` (soft, 256 light samples) is
within 0.015 of the truth and at most half `hard`'s error on every scene."""
import json
import os
import tempfile

import shadowtest as st

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "..", "Examples", "Scenes", "quality")
VARIANTS = ["contact", "contact:gaussian", "contact:multipass"]
TECHNIQUES = ["hard"] + VARIANTS + ["reference:sphere", "silhouette", "smoothies"]

failures = []
for name in ("columns", "grate", "blob", "resting", "room", "grazing"):
    path = os.path.join(SCENES, name + ".json")
    extra = ["aliasfree"] + (["reference"] if name == "room" else [])
    rows = st.run(["quality", path, "--techniques", ",".join(TECHNIQUES + extra),
                   "--json"]).stdout
    figures = {row["technique"]: row for row in map(json.loads, rows.splitlines())}
    rmse = {t: figures[t]["rmse"] for t in figures}
    ratios = {v: rmse[v] / rmse["hard"] for v in VARIANTS}
    best = min(rmse[v] for v in VARIANTS)
    print("%-8s hard %.4f; %s; reference:sphere %.4f" % (name, rmse["hard"], ", ".join(
        "%s %.4f (%.2f, umbra %.3f, penumbra %.2f)" % (
            v, rmse[v], ratios[v], figures[v]["umbra"], figures[v]["penumbra_ratio"])
        for v in VARIANTS), rmse["reference:sphere"]))
    # Silhouette-distance shadow maps: at least 20% under hard's error.
    print("%-8s silhouette %.4f (%.2f)" % (name, rmse["silhouette"], rmse["silhouette"] / rmse["hard"]))
    if rmse["silhouette"] > 0.8 * rmse["hard"]:
        failures.append("%s: silhouette is %.2f times hard's RMSE (at most 0.80)"
                        % (name, rmse["silhouette"] / rmse["hard"]))
    # Smoothies: at least 10% under hard's error.
    print("%-8s smoothies %.4f (%.2f)" % (name, rmse["smoothies"], rmse["smoothies"] / rmse["hard"]))
    if rmse["smoothies"] > 0.9 * rmse["hard"]:
        failures.append("%s: smoothies is %.2f times hard's RMSE (at most 0.90)"
                        % (name, rmse["smoothies"] / rmse["hard"]))
    # Alias-free shadow maps: near the truth.
    print("%-8s aliasfree %.4f (%.2f)" % (name, rmse["aliasfree"], rmse["aliasfree"] / rmse["hard"]))
    if rmse["aliasfree"] > min(0.015, 0.5 * rmse["hard"]):
        failures.append("%s: aliasfree is %.4f off the truth (%.2f times hard's RMSE)"
                        % (name, rmse["aliasfree"], rmse["aliasfree"] / rmse["hard"]))
    limit = 0.9 if name == "grazing" else 0.7
    for variant in VARIANTS:
        if ratios[variant] > limit:
            failures.append("%s: %s is %.2f times hard's RMSE (at most %.2f)"
                            % (name, variant, ratios[variant], limit))
        if figures[variant]["umbra"] > 0.05:
            failures.append("%s: %s's umbra is lighter than the truth's (mean visibility %.3f)"
                            % (name, variant, figures[variant]["umbra"]))
        if not 0.7 <= figures[variant]["penumbra_ratio"] <= 1.5:
            failures.append("%s: %s's penumbrae cover %.2f times the truth's pixels"
                            % (name, variant, figures[variant]["penumbra_ratio"]))
    if rmse["contact"] > 1.1 * best:
        failures.append("%s: the default variant (%.4f) is more than 10%% off the best (%.4f)"
                        % (name, rmse["contact"], best))
    if rmse["reference:sphere"] > 0.015:
        failures.append("%s: reference:sphere is %.4f off the truth" % (name, rmse["reference:sphere"]))
    if name == "room":
        print("room: reference (disc) %.4f" % rmse["reference"])
        if rmse["reference:sphere"] > 0.5 * rmse["reference"]:
            failures.append("room: reference:sphere (%.4f) not well under the disc's %.4f"
                            % (rmse["reference:sphere"], rmse["reference"]))

# grazing with the light-space refinement on.
with open(os.path.join(SCENES, "grazing.json")) as f:
    scene = json.load(f)
scene["shadows"]["contact"] = {"refine_unresolved": True}
with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "grazing-refined.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    rows = st.run(["quality", path, "--techniques", ",".join(["hard"] + VARIANTS),
                   "--json"]).stdout
rmse = {row["technique"]: row["rmse"] for row in map(json.loads, rows.splitlines())}
print("grazing, refine_unresolved: hard %.4f; %s" % (rmse["hard"], ", ".join(
    "%s %.4f (%.2f)" % (v, rmse[v], rmse[v] / rmse["hard"]) for v in VARIANTS)))
for variant in VARIANTS:
    if rmse[variant] > 0.7 * rmse["hard"]:
        failures.append("grazing, refine_unresolved: %s is %.2f times hard's RMSE (at most 0.70)"
                        % (variant, rmse[variant] / rmse["hard"]))

for failure in failures:
    print("FAIL: " + failure)
st.check(not failures, "every contact variant well under hard, the default the best or near it; "
         "silhouette at least 20% under hard, smoothies at least 10%, aliasfree within 0.015 "
         "of the truth")
