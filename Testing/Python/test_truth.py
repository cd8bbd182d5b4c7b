# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The ray-cast ground truth (`softshadows truth`, vtkRayCastLightVisibility)
against closed forms: a ball over the ground under spot, point and
directional lights of several sizes, where the visible share of the light is
the part of its disc the ball's disc does not cover. Then `reference`, the
fast approximation of it, is measured against it, and the `quality` command
prints the table."""
import numpy as np

import shadowtest as st

cases = [
    ("spot, radius 0.4", {}, 0.4),
    ("spot, radius 0.15", {}, 0.15),
    ("point, radius 0.4", {"light_type": "point"}, 0.4),
]
for label, options, radius in cases:
    scene = st.ball_scene(height=1.5, light_radius=radius, **options)
    visibility, geometry, mask = st.truth(scene)
    expected, ground = st.ball_visibility(scene)
    where = ground & mask
    error = np.abs(visibility - expected)[where]
    rmse = float(np.sqrt(np.mean(error ** 2)))
    print("%s: %d ground pixels, RMSE %.4f, largest error %.3f" % (label, where.sum(), rmse,
                                                                   error.max()))
    # 256 stratified rays: an edge crossing the 16 x 16 strata errs by up to
    # about 16 / 256 in a pixel.
    st.check(where.sum() > 10000 and rmse < 0.006 and error.max() < 0.08,
             "%s: the truth follows the closed form (RMSE %.4f, largest %.3f)"
             % (label, rmse, error.max()))

# A directional light of 2 degrees, from the side: a cone of directions.
scene = st.ball_scene(height=1.0)
scene["lights"] = [{"type": "directional", "direction": [-2.0, -5.0, -1.0], "radius": 2.0}]
visibility, geometry, mask = st.truth(scene)
expected, ground = st.ball_visibility(scene)
where = ground & mask
error = np.abs(visibility - expected)[where]
rmse = float(np.sqrt(np.mean(error ** 2)))
print("directional, 2 degrees: RMSE %.4f, largest error %.3f" % (rmse, error.max()))
st.check(rmse < 0.006 and error.max() < 0.08,
         "directional light: the truth follows the closed form (RMSE %.4f)" % rmse)

# A point-sized light: exactly the geometric hard shadow, away from its edge.
scene = st.ball_scene(height=1.0)
visibility, geometry, mask = st.truth(scene)
ground, shadowed, edge_pixels = st.expected_hard_shadow(scene)
clear = ground & (edge_pixels > 1.0)
wrong = int(np.sum((visibility[clear] > 0.5) == shadowed[clear]))
print("radius 0: %d of %d ground pixels off the hard shadow" % (wrong, clear.sum()))
st.check(wrong == 0, "radius 0: the truth is the hard shadow (%d pixels wrong)" % wrong)
seen = st.surface_ids(scene) > 0
differ = float(np.mean(geometry != seen))
st.check(differ < 0.002, "the truth sees the ground and the ball where they are (%.2f%% of "
         "pixels differ)" % (100 * differ))

# `reference` against the truth: close on the ball (the team measured about
# 0.003 with an independent ray tracer).
scene = st.ball_scene(height=1.5, light_radius=0.4, technique="reference",
                      params={"samples": 256})
truth, _, mask = st.truth(scene)
reference, _ = st.shadow_only(scene)
error = st.rmse(reference, truth, mask)
print("reference (256 maps) against the truth: RMSE %.4f" % error)
st.check(error < 0.006, "reference is close to the truth on the ball (RMSE %.4f)" % error)

# The table: one row a technique, RMSE as measured here.
table = st.run(["quality", "-", "--techniques", "hard,reference"], check=False)
st.check(table.returncode == 2 and table.stderr.count("\n") == 1,
         "quality without a scene file: one line, exit 2 (%r)" % table.stderr)
