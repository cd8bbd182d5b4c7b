# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The `silhouette` technique (Valient & Bujnak): anti-aliased hard shadows
where geometry puts them, closer to an exact hard shadow than `hard` at the
same map size; soft penumbrae from the light's radius that widen with the
occluder's height and stay hard at contact, close to the ray-cast truth (on
other scenes: test_quality.py); and meshes the topology aware mesh cannot
fully describe (open sheets, non-manifold edges, degenerate faces, lines and
points) drawn without an error."""
import json
import os

import numpy as np

import shadowtest as st

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "..", "Examples", "Scenes", "quality")

# The hard variant's shadow where geometry says: away from its edge every
# ground pixel is in the ball's shadow exactly when the segment to the light
# passes through the ball.
scene = st.ball_scene(height=1.0, light_radius=0.0, technique="silhouette:hard", map_size=512)
visibility, _ = st.shadow_only(scene)
visible, shadowed, edge = st.expected_hard_shadow(scene)
away = visible & (edge > 1.5)
wrong = float(((visibility < 0.5) != shadowed)[away].mean())
st.check(shadowed[away].sum() > 500 and wrong < 0.001,
         "silhouette:hard: the ball's shadow where geometry says (%.3f%% of %d pixels wrong)"
         % (100 * wrong, away.sum()))

# Anti-aliasing against an exact hard shadow (ray casting, one ray a pixel),
# at a 512^2 map: a curved occluder and thin slats, RMSE and mismatch at
# most half of `hard`'s.
with open(os.path.join(SCENES, "grate.json")) as f:
    grate = json.load(f)
grate["lights"][0]["radius"] = 0.0
grate["size"] = [480, 360]  # the quality scenes' own size
grate["shadows"] = {"technique": "hard", "map_size": 512}
ball = st.ball_scene(height=1.0, light_radius=0.0, size=(320, 240), map_size=512)
for name, scene in (("ball", ball), ("grate", grate)):
    truth, _, mask = st.truth(scene, samples=1)
    figures = {}
    for technique in ("hard", "silhouette:hard"):
        visibility, _ = st.shadow_only(scene, technique)
        figures[technique] = (st.rmse(visibility, truth, mask),
                              float((np.abs(visibility - truth) > 0.5)[mask].mean()))
        print("%s, exact hard shadow: %-16s RMSE %.4f, mismatch %.3f%%"
              % (name, technique, figures[technique][0], 100 * figures[technique][1]))
    (rmse, mismatch), (hard_rmse, hard_mismatch) = figures["silhouette:hard"], figures["hard"]
    st.check(rmse <= 0.5 * hard_rmse and mismatch <= 0.5 * hard_mismatch,
             "%s: silhouette:hard at most half of hard's error against the exact shadow (RMSE "
             "%.4f vs %.4f, mismatch %.3f%% vs %.3f%%)"
             % (name, rmse, hard_rmse, 100 * mismatch, 100 * hard_mismatch))

# Soft: the penumbra widens as the ball rises, and against the ray-cast
# truth the error is well under hard's.
radius = 0.4
widths = []
for height in (0.75, 1.5, 2.25):
    scene = st.ball_scene(height=height, light_radius=radius, technique="silhouette")
    visibility, _ = st.shadow_only(scene)
    widths.append(st.penumbra_width(scene, visibility))
    truth, _, mask = st.truth(scene)
    errors = {t: st.rmse(st.shadow_only(scene, t)[0], truth, mask) for t in ("hard", "silhouette")}
    print("height %.2f: penumbra %.3f; RMSE silhouette %.4f, hard %.4f"
          % (height, widths[-1], errors["silhouette"], errors["hard"]))
    st.check(errors["silhouette"] < 0.4 * errors["hard"],
             "height %.2f: silhouette under 0.4 of hard's error against the truth (%.4f, %.4f)"
             % (height, errors["silhouette"], errors["hard"]))
st.check(widths[0] < widths[1] < widths[2], "silhouette penumbra widens as the ball rises: %s"
         % np.round(widths, 3).tolist())

# Overlapping penumbrae: under the grate, a wide light's penumbrae overlap
# several slats. Each sample follows its own nearest silhouette, so only
# samples spread over the penumbra add them up: with overlap_samples 8, a
# point whose distance map shows another silhouette within reach takes 8
# out to 0.6 half-widths. Against the paper's 4 at 0.25 everywhere (the
# default), that takes the error against the truth under half and fades the
# grate's stripes, which the truth nearly evens out (docs/quality.md);
# where an edge casts alone (grazing), the paper's samples stay, and the
# error with them.
for name in ("grate", "grazing"):
    with open(os.path.join(SCENES, name + ".json")) as f:
        scene = json.load(f)
    scene["size"] = [240, 180]
    truth, _, mask = st.truth(scene)
    under = mask & (truth > 0.2) & (truth < 0.6)  # penumbrae, overlapping under the grate
    figures = {}
    for setting, parameters in (("paper", {}), ("overlap", {"overlap_samples": 8})):
        scene["shadows"] = {"technique": "silhouette", "silhouette": parameters}
        visibility, _ = st.shadow_only(scene)
        figures[setting] = (st.rmse(visibility, truth, mask), float(np.std(visibility[under])))
        print("%s, %s samples: RMSE %.4f, spread in penumbrae %.3f (truth %.3f)"
              % (name, setting, figures[setting][0], figures[setting][1], np.std(truth[under])))
    if name == "grate":
        st.check(figures["overlap"][0] < 0.5 * figures["paper"][0],
                 "grate: overlap samples under half the error of the paper's (%.4f, %.4f)"
                 % (figures["overlap"][0], figures["paper"][0]))
        st.check(figures["overlap"][1] < 0.6 * figures["paper"][1],
                 "grate: the slats' stripes fade (%.3f, %.3f)"
                 % (figures["overlap"][1], figures["paper"][1]))
    else:
        st.check(figures["overlap"][0] < 1.05 * figures["paper"][0],
                 "grazing: a lone edge keeps the paper's samples' error (%.4f, %.4f)"
                 % (figures["overlap"][0], figures["paper"][0]))

# Where the occluder touches the receiver the edge stays hard; farther out
# it softens.
scene = st.post_scene(light_radius=radius, technique="silhouette")
visibility, _ = st.shadow_only(scene)
at_base = st.edge_width_pixels(scene, visibility, -0.2)
far_out = st.edge_width_pixels(scene, visibility, -1.4)
print("post: edge %.1f px at the base, %.1f px far out" % (at_base, far_out))
st.check(at_base <= 2.0, "at contact the edge is hard: %.1f px wide" % at_base)
st.check(far_out > at_base + 2.0, "away from contact it softens: %.1f px" % far_out)

# Meshes a topology aware mesh describes only in part (an open sheet, fins
# on a non-manifold edge, zero-area faces): no error, the sheets' shadows
# beneath them.
st.check_odd_meshes("silhouette")

# Casters without faces (scene files refuse them; the API does not): lines
# and points beside the ball cast their depth-map shadow only, with no error,
# and the ball's shadow is unchanged.
from vtksoftshadows import vtkSilhouetteShadowPass  # noqa: E402

plain, _, _ = st.render_line_casters(vtkSilhouetteShadowPass, False)
image, errors, shadows = st.render_line_casters(vtkSilhouetteShadowPass, True)
st.check(not errors, "lines and points among the casters: no error or warning (%d)" % len(errors))
st.check(shadows.GetTopologyAwareMeshBytes() > 0,
         "the ball's topology aware mesh is on the GPU: %d bytes" % shadows.GetTopologyAwareMeshBytes())
ball_shadow = plain < 20
st.check(ball_shadow.sum() > 100 and (image[ball_shadow] < 20).all(),
         "the ball's shadow is unchanged by the line and point casters (%d pixels)"
         % ball_shadow.sum())

# Pass 2's geometry and the TAM's layouts on the GPU: rectangles around
# silhouette edges (the default) and the paper's faces grown about their
# incenters (eq. 2), once a corner or instanced once a face, write the same
# map: the same picture. Half precision rounds the corners: nearly the same.
# The TAM's bytes: 72 a corner, 72 a face, 36 a face in half precision.
layouts = {}
for name, geometry, per_face, half in (("incenter, per corner", 0, False, False),
                                       ("incenter, per face", 0, True, False),
                                       ("edge rectangles", 1, False, False),
                                       ("edge rectangles, half", 1, False, True)):
    window, _, shadows = st.api_ball(vtkSilhouetteShadowPass, light_radius=0.3)
    shadows.SetSilhouetteGeometry(geometry)
    shadows.SetPerFaceAttributes(per_face)
    shadows.SetHalfPrecision(half)
    window.Render()
    layouts[name] = (st.grab_red(window).astype(int), shadows.GetTopologyAwareMeshBytes())
reference, faces = layouts["incenter, per corner"][0], layouts["incenter, per corner"][1] // 216
st.check(faces > 0 and layouts["incenter, per corner"][1] == 216 * faces,
         "per corner: 72 bytes a corner (%d faces)" % faces)
for name, bytes_a_face in (("incenter, per face", 72), ("edge rectangles", 72),
                           ("edge rectangles, half", 36)):
    image, uploaded = layouts[name]
    st.check(uploaded == bytes_a_face * faces, "%s: %d bytes a face (%d)"
             % (name, bytes_a_face, uploaded))
    changed = np.abs(image - reference) > 2
    if "half" in name:
        st.check(changed.mean() < 0.002, "%s: nearly the same picture (%.4f of pixels differ)"
                 % (name, changed.mean()))
    else:
        st.check(not changed.any(), "%s: the same picture as the paper's incenter scaling (%d "
                 "pixels differ)" % (name, changed.sum()))
