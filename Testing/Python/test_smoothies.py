# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The `smoothies` technique (Chan & Durand, as Volokh's report implements
them): the umbra where the hard shadow puts it and a soft edge only outside
it, for spot, point and directional lights; penumbrae that widen as the
occluder rises; nearer the ray-cast truth than `hard` on the ball, the fence
and a knot (the quality scenes: test_quality.py); thinner smoothies better
for a fence, as the report finds; no worse snapping than the reference on a
12-sided cylinder under a moving light; both silhouette searches, and
smoothies built on the GPU or on the CPU, giving the same image; and meshes the silhouette filter describes only in part, and
casters without faces, drawn without an error."""
import copy
import json
import math
import os
import tempfile

import numpy as np

import shadowtest as st


def soft_edge_checks(name, visibility, visible, hard_shadowed, edge, truth):
    """The umbra is the hard shadow's; lit beyond the true penumbra; darker
    than lit in the true penumbra's outer part, outside the hard shadow."""
    umbra = visible & hard_shadowed & (edge > 2.0)
    lit = visible & ~hard_shadowed & (truth > 0.999) & (edge > 2.0)
    band = visible & ~hard_shadowed & (truth < 0.9) & (edge > 1.0)
    bright = float((visibility[umbra] > 0.05).mean())
    dark = float((visibility[lit] < 0.95).mean())
    # How much of the true outer penumbra's shadow the smoothies give.
    soft = float((1.0 - visibility[band]).mean() / (1.0 - truth[band]).mean())
    print("%s: umbra %d px (%.3f%% above 0.05), lit %d px (%.3f%% under 0.95), outer penumbra "
          "%d px, %.2f of its shadow" % (name, umbra.sum(), 100 * bright, lit.sum(), 100 * dark,
                                         band.sum(), soft))
    st.check(umbra.sum() > 500 and bright < 0.001,
             "%s: the umbra where the hard shadow is (%.3f%% brighter than 0.05)"
             % (name, 100 * bright))
    st.check(lit.sum() > 500 and dark < 0.001,
             "%s: lit beyond the penumbra (%.3f%% darker than 0.95)" % (name, 100 * dark))
    st.check(band.sum() > 100 and 0.4 < soft < 1.2,
             "%s: the soft edge lies outside the hard shadow (%.2f of the true shadow there)"
             % (name, soft))


# 1. Spot and point lights: against the closed-form visibility of the ball.
for light_type in ("spot", "point"):
    scene = st.ball_scene(height=1.0, light_radius=0.4, technique="smoothies",
                          light_type=light_type, size=(320, 240))
    visibility, _ = st.shadow_only(scene)
    visible, shadowed, edge = st.expected_hard_shadow(scene)
    truth, _ = st.ball_visibility(scene)
    soft_edge_checks(light_type, visibility, visible, shadowed, edge, truth)

# A directional light (5 degrees), its hard shadow the ball's cylinder along
# the direction.
scene = st.ball_scene(height=1.0, technique="smoothies", size=(320, 240))
direction = np.array([-0.3, -1.0, -0.2]) / np.linalg.norm([-0.3, -1.0, -0.2])
scene["lights"] = [{"type": "directional", "direction": direction.tolist(), "radius": 5.0}]
visibility, _ = st.shadow_only(scene)
truth, visible = st.ball_visibility(scene)
points, _, pixel = st.ground_points(scene)
ball = np.array(scene["actors"][1]["position"], float)
offset = ball - points
miss = np.linalg.norm(offset - (offset @ -direction)[..., None] * -direction, axis=-1)
soft_edge_checks("directional", visibility, visible, miss < st.BALL_RADIUS,
                 np.abs(miss - st.BALL_RADIUS) / pixel, truth)

# 2. The penumbra widens as the ball rises.
widths = st.penumbra_widths("smoothies")
st.check(widths[0] < widths[1] < widths[2], "the soft edge widens as the ball rises: %s"
         % np.round(widths, 3).tolist())


# 3. Against the ray-cast truth: the ball, the fence and a knot.
def fence_scene(technique="smoothies", params=None):
    scene = st.ball_scene(light_radius=0.3, technique=technique, params=params, size=(320, 240))
    scene["lights"] = [{"type": "spot", "position": [0.5, 4.0, -4.0], "focal_point": [0, 0, 0.5],
                        "cone_angle": 40, "radius": 0.3}]
    scene["camera"] = {"position": [0.0, 4.5, 5.0], "focal_point": [0.0, 0.3, 0.2],
                       "view_up": [0.0, 1.0, 0.0], "view_angle": 35.0}
    scene["actors"][1] = {"source": "fence", "params": {"pickets": 9, "height": 1.2},
                          "position": [0.0, 0.0, -1.0], "color": [0.72, 0.56, 0.38]}
    return scene


knot = st.ball_scene(light_radius=0.3, technique="smoothies", size=(320, 240))
knot["actors"][1] = {"source": "knot", "params": {"ring_radius": 0.6, "tube_radius": 0.12},
                     "position": [0.0, 1.1, 0.0], "orientation": [20, 0, 0]}
scenes = {"ball": st.ball_scene(height=1.0, light_radius=0.4, technique="smoothies",
                                size=(320, 240)),
          "fence": fence_scene(), "knot": knot}
for name, scene in scenes.items():
    truth, _, mask = st.truth(scene, samples=128)
    errors = {t: st.rmse(st.shadow_only(scene, t)[0], truth, mask) for t in ("hard", "smoothies")}
    print("%s: RMSE against the truth: smoothies %.4f, hard %.4f (%.2f)"
          % (name, errors["smoothies"], errors["hard"], errors["smoothies"] / errors["hard"]))
    st.check(errors["smoothies"] < 0.9 * errors["hard"],
             "%s: smoothies under 0.9 of hard's error against the truth (%.4f, %.4f)"
             % (name, errors["smoothies"], errors["hard"]))

# 4. A fence lying over the ground (the report's figure 7): thinner
# smoothies beat thick ones, which darken its gaps (section 6.2); sized from
# the light they are thin enough.
def lying_fence(params=None):
    scene = st.ball_scene(light_radius=0.2, technique="smoothies", params=params, size=(320, 240))
    scene["actors"][1] = {"source": "fence", "params": {"pickets": 9, "height": 1.2},
                          "position": [-0.4, 1.2, 0.6], "orientation": [-90, 0, 0]}
    return scene


truth, _, mask = st.truth(lying_fence(), samples=128)
errors = {}
for label, params in (("radius", None), ("16 texels", {"thickness": 16}),
                      ("64 texels", {"thickness": 64})):
    errors[label] = st.rmse(st.shadow_only(lying_fence(params))[0], truth, mask)
print("fence RMSE by thickness: %s" % {k: round(v, 4) for k, v in errors.items()})
st.check(errors["16 texels"] < errors["64 texels"],
         "fence: 16-texel smoothies nearer the truth than 64-texel ones, which fill its gaps "
         "(%.4f, %.4f)" % (errors["16 texels"], errors["64 texels"]))
st.check(errors["radius"] < errors["64 texels"],
         "fence: smoothies sized from the light nearer the truth than thick fixed ones (%.4f, %.4f)"
         % (errors["radius"], errors["64 texels"]))

# 5. Snapping (the report, section 7): a 12-sided cylinder under a light
# stepping 0.05 rad a frame; the mean change of the shadow-only image from
# frame to frame at most 1.2 times the reference's.
def cylinder_frame(angle, technique):
    scene = st.ball_scene(light_radius=0.3, technique=technique, size=(200, 150))
    scene["lights"][0]["position"] = [2.0 * math.cos(angle), 5.0, 2.0 * math.sin(angle)]
    scene["actors"][1] = {"source": "cylinder", "params": {"radius": 0.5, "height": 0.8,
                                                           "resolution": 12},
                          "position": [0.0, 1.2, 0.0]}
    return st.shadow_only(scene)[0]


change = {}
for technique in ("smoothies", "reference"):
    frames = [cylinder_frame(0.3 + 0.05 * k, technique) for k in range(8)]
    change[technique] = float(np.mean([np.abs(b - a).mean() for a, b in zip(frames, frames[1:])]))
print("frame-to-frame change: smoothies %.5f, reference %.5f (%.2f)"
      % (change["smoothies"], change["reference"], change["smoothies"] / change["reference"]))
st.check(change["smoothies"] <= 1.2 * change["reference"],
         "snapping: smoothies change at most 1.2 times the reference's from frame to frame "
         "(%.2f)" % (change["smoothies"] / change["reference"]))

# 6. Both silhouette searches find the same edges: the same image.
scene = st.ball_scene(height=1.0, light_radius=0.4, technique="smoothies")
tree, _ = st.shadow_only(scene)
scene["shadows"]["smoothies"] = {"silhouette_search": 0}
brute, _ = st.shadow_only(scene)
st.check(np.array_equal(tree, brute), "brute force and the normal-cone tree: the same image")

# Built on the CPU per frustum (the report's way), the same smoothies as the
# geometry shader's, under a spot and a point light.
for light_type in ("spot", "point"):
    scene = st.ball_scene(height=1.0, light_radius=0.4, technique="smoothies",
                          light_type=light_type)
    gpu, _ = st.shadow_only(scene)
    scene["shadows"]["smoothies"] = {"build_on_gpu": False}
    cpu, _ = st.shadow_only(scene)
    differ = float((np.abs(gpu - cpu) > 2.0 / 255.0).mean())
    st.check(differ < 0.001, "%s: smoothies built on the CPU as on the GPU (%.3f%% of pixels "
             "differ)" % (light_type, 100 * differ))

# 7. Meshes the silhouette filter describes only in part, and casters
# without faces.
st.check_odd_meshes("smoothies")
from vtksoftshadows import vtkSmoothieShadowPass  # noqa: E402

plain, _, _ = st.render_line_casters(vtkSmoothieShadowPass, False)
image, errors, shadows = st.render_line_casters(vtkSmoothieShadowPass, True)
st.check(not errors, "lines and points among the casters: no error or warning (%d)" % len(errors))
st.check(shadows.GetNumberOfSilhouetteEdges() > 0,
         "the ball's silhouette found: %d edges" % shadows.GetNumberOfSilhouetteEdges())
ball_shadow = plain < 20
st.check(ball_shadow.sum() > 100 and (image[ball_shadow] < 20).all(),
         "the ball's shadow is unchanged by the line and point casters (%d pixels)"
         % ball_shadow.sum())
