# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A million-triangle caster, as scientific visualization draws them: the
`gyroid` source at resolution 183 (1.02M triangles, an isosurface of
tunnels whose walls shadow each other) over a floor, under a spherical spot
light, in a small window so that CI can afford it. Every technique draws it
(none refuses, none crashes) and is measured against the ray-cast truth:
its umbra dark, its error no worse than `hard`'s (`smoothies` barely moves
from `hard` on so fine a silhouette: within 2%), `contact`, `silhouette` and
`omni` under it, and `aliasfree` soft, exact but for its light samples, at
most a quarter of it (0.07 of it when written). Its frame takes seconds
here (docs/benchmarks.md, "`aliasfree` at scale"), not minutes as it did."""
import json
import os
import tempfile

import shadowtest as st

TECHNIQUES = ["hard", "contact", "omni", "silhouette", "smoothies", "aliasfree:hard", "aliasfree"]
SCENE = {
    "camera": {"position": [2.4, 2.8, 3.4], "focal_point": [0.0, 0.7, 0.0]},
    "lights": [{"type": "spot", "position": [2.5, 5.0, 1.5], "focal_point": [0.0, 0.0, 0.0],
                "cone_angle": 40, "radius": 0.3}],
    "actors": [{"source": "plane", "params": {"size": 5}},
               {"source": "gyroid", "params": {"radius": 1.0, "resolution": 183},
                "position": [0.0, 1.1, 0.0]}],
}

with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "gyroid.json")
    with open(path, "w") as f:
        json.dump(SCENE, f)
    rows = st.run(["quality", path, "--techniques", ",".join(TECHNIQUES), "--size", "96x96",
                   "--json"]).stdout
figures = {row["technique"]: row for row in map(json.loads, rows.splitlines())}
rmse = {t: figures[t]["rmse"] for t in figures}
for t in TECHNIQUES:
    print("%-15s RMSE %.4f (%.2f of hard's), umbra %.3f, penumbra %.2f of the truth's" % (
        t, rmse[t], rmse[t] / rmse["hard"], figures[t]["umbra"], figures[t]["penumbra_ratio"]))

failures = []
limits = {"hard": 1.0, "contact": 0.8, "omni": 0.95, "silhouette": 0.7, "smoothies": 1.02,
          "aliasfree:hard": 1.3, "aliasfree": 0.25}
for t in TECHNIQUES:
    if t not in figures:
        failures.append("%s drew nothing" % t)
        continue
    if rmse[t] > limits[t] * rmse["hard"]:
        failures.append("%s: RMSE %.4f is %.2f times hard's (at most %.2f)"
                        % (t, rmse[t], rmse[t] / rmse["hard"], limits[t]))
    if figures[t]["umbra"] > 0.05:
        failures.append("%s: the umbra is lit (mean visibility %.3f)" % (t, figures[t]["umbra"]))
for failure in failures:
    print("FAIL: " + failure)
st.check(not failures, "every technique draws a million-triangle caster, its umbra dark and "
         "its error no worse than hard's, contact, silhouette and omni under it, aliasfree "
         "soft at most a quarter of it")
