# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The `contact` technique (Cherry & Kooima): contact-hardening penumbrae that
widen with the occluder's height, and, with kernels sized from the light's
radius, closer to the ray-cast truth than hard shadows (on other scenes:
test_quality.py)."""
import copy

import numpy as np

import shadowtest as st

radius = 0.4

# Penumbra width against height: monotonic, and near similar triangles.
widths = []
for height in (0.75, 1.5, 2.25):
    scene = st.ball_scene(height=height, light_radius=radius, technique="contact")
    visibility, _ = st.shadow_only(scene)
    widths.append(st.penumbra_width(scene, visibility))
    print("height %.2f: penumbra %.3f" % (height, widths[-1]))
st.check(widths[0] < widths[1] < widths[2], "contact penumbra widens as the ball rises: %s"
         % np.round(widths, 3).tolist())

# Where the occluder touches the receiver the edge stays hard: a post on the
# ground, its shadow's side edge just beside its base, and farther out; with
# screen-space buffers at full and (the default) half resolution.
for divisor in (1, 2):
    scene = st.post_scene(light_radius=radius)
    scene["shadows"]["contact"] = {"resolution_divisor": divisor}
    visibility, _ = st.shadow_only(scene)
    at_base = st.edge_width_pixels(scene, visibility, -0.2)
    far_out = st.edge_width_pixels(scene, visibility, -1.4)
    print("resolution divisor %d: edge %.1f px at the base, %.1f px far out"
          % (divisor, at_base, far_out))
    st.check(at_base <= 2.0, "divisor %d: at contact the edge is hard: %.1f px wide"
             % (divisor, at_base))
    st.check(far_out > at_base + 2.0, "divisor %d: away from contact it softens: %.1f px"
             % (divisor, far_out))

# A light too small for any blur: every variant draws `hard`'s shadow, its
# edges filtered as smoothly (the receivers once compared an unfiltered map
# and stair-stepped where `hard` does not).
scene = st.post_scene(light_radius=0.01)
hard, mask = st.shadow_only(scene, "hard")
for variant in ("pcf", "gaussian", "multipass"):
    visibility, _ = st.shadow_only(scene, "contact:" + variant)
    worst = float(np.abs(visibility - hard)[mask].max())
    print("light radius 0.01, contact:%s against hard: largest difference %.3f" % (variant, worst))
    st.check(worst < 0.02, "contact:%s with a tiny light is hard's shadow (largest difference %.3f)"
             % (variant, worst))

# Quality against the ray-cast truth: RMSE of visibility over SPEC's pixels.
scene = st.ball_scene(height=1.5, light_radius=radius, size=(240, 180))
truth, _, mask = st.truth(scene)
errors = {}
for technique in ("hard", "contact:pcf", "contact:gaussian", "contact:multipass"):
    visibility, _ = st.shadow_only(scene, technique)
    errors[technique] = st.rmse(visibility, truth, mask)
    print("RMSE %-18s %.4f" % (technique, errors[technique]))
full = dict(scene, shadows=dict(scene["shadows"], contact={"resolution_divisor": 1}))
for variant in ("pcf", "multipass"):
    visibility, _ = st.shadow_only(full, "contact:" + variant)
    label = "contact:%s, full resolution" % variant
    errors[label] = st.rmse(visibility, truth, mask)
    print("RMSE %-18s %.4f" % (label, errors[label]))
for technique in errors:
    if technique != "hard":
        st.check(errors[technique] < 0.5 * errors["hard"],
                 "%s under half of hard's error against the truth (%.4f, hard %.4f)"
                 % (technique, errors[technique], errors["hard"]))


# Scale: the same scene 100,000 times larger (a kilometre-scale mesh in
# metres, say) must look the same; camera distances stored as half floats
# overflowed there, and every pixel fell back to the hard shadow.
def scaled(scene, k):
    s = copy.deepcopy(scene)
    for key in ("position", "focal_point"):
        s["camera"][key] = [k * x for x in s["camera"][key]]
        for light in s["lights"]:
            light[key] = [k * x for x in light[key]]
    for light in s["lights"]:
        light["radius"] *= k
    for actor in s["actors"]:
        params = actor["params"]
        for key in ("size", "radius"):
            if key in params:
                params[key] = [k * x for x in params[key]] if key == "size" else k * params[key]
        if "position" in actor:
            actor["position"] = [k * x for x in actor["position"]]
    return s


scene = st.ball_scene(height=1.5, light_radius=radius, technique="contact")
unit, mask = st.shadow_only(scene)
large, _ = st.shadow_only(scaled(scene, 1.0e5))
difference = st.rmse(large, unit, mask)
print("scene scaled by 1e5: RMSE to the unit scene %.4f" % difference)
st.check(difference < 0.005, "a scene 1e5 times larger looks the same (RMSE %.4f)" % difference)


# Lights beyond the eighth: one camera pass writes the distance maps of up to
# eight lights (colour targets); the ninth and tenth go through a second one,
# and must shade as the same light does alone.
many = copy.deepcopy(scene)
extra = []
for i in range(9):
    angle = 2.0 * np.pi * i / 9.0
    extra.append({"type": "spot", "position": [3.0 * np.cos(angle), 4.0, 3.0 * np.sin(angle)],
                  "focal_point": [0, 0, 0], "cone_angle": 45, "intensity": 0.1,
                  "radius": radius})
many["lights"] = extra + scene["lights"]
alone, mask = st.shadow_only(scene)
tenth, _ = st.shadow_only(many, light=len(many["lights"]) - 1)
difference = st.rmse(tenth, alone, mask)
print("tenth light of ten against the same light alone: RMSE %.4f" % difference)
st.check(difference < 0.005,
         "a light in the second camera pass shades as alone (RMSE %.4f)" % difference)
