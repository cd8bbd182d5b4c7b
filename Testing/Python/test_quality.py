"""Quality against physics on scenes unlike the ball (Examples/Scenes/quality,
480x360): every `contact` variant's RMSE against the ray-cast truth is at
most 0.7 times `hard`'s, and the default variant is the best or within 10%
of the best. `grazing` is the exception docs/quality.md documents:
screen-space kernels do no better than `hard` on floors seen nearly
edge-on; there every variant stays within 1.1 times `hard`."""
import json
import os

import shadowtest as st

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "..", "Examples", "Scenes", "quality")
VARIANTS = ["contact", "contact:gaussian", "contact:multipass"]

failures = []
for name in ("columns", "grate", "blob", "resting", "room", "grazing"):
    path = os.path.join(SCENES, name + ".json")
    rows = st.run(["quality", path, "--techniques", ",".join(["hard"] + VARIANTS),
                   "--json"]).stdout
    rmse = {row["technique"]: row["rmse"] for row in map(json.loads, rows.splitlines())}
    ratios = {v: rmse[v] / rmse["hard"] for v in VARIANTS}
    best = min(rmse[v] for v in VARIANTS)
    print("%-8s hard %.4f; %s" % (name, rmse["hard"], ", ".join(
        "%s %.4f (%.2f)" % (v, rmse[v], ratios[v]) for v in VARIANTS)))
    limit = 1.1 if name == "grazing" else 0.7
    for variant in VARIANTS:
        if ratios[variant] > limit:
            failures.append("%s: %s is %.2f times hard's RMSE (at most %.2f)"
                            % (name, variant, ratios[variant], limit))
    if rmse["contact"] > 1.1 * best:
        failures.append("%s: the default variant (%.4f) is more than 10%% off the best (%.4f)"
                        % (name, rmse["contact"], best))

for failure in failures:
    print("FAIL: " + failure)
st.check(not failures, "every contact variant well under hard, the default the best or near it")
