# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The `reference` technique: with radius 0 it is `hard` without filtering,
and its penumbra widens as the occluder rises, as similar triangles say:
w = (d_receiver - d_blocker) * light_diameter / d_blocker."""
import numpy as np

import shadowtest as st

binary = {"pcf_radius": 0, "hardware_filtering": False}

# Radius 0: one sample at the light's centre, the same test as `hard`.
scene = st.ball_scene(height=1.0, light_radius=0.0, params=binary)
hard, geometry = st.shadow_only(scene, "hard")
reference, _ = st.shadow_only(scene, "reference")
differ = geometry & (np.abs(hard - reference) > 0.02)
st.check(differ.sum() <= 0.001 * geometry.sum(),
         "radius 0: reference equals hard (%d of %d pixels differ)" % (differ.sum(), geometry.sum()))

# Penumbra width against height, light radius 0.4 at height 5.
radius = 0.4
widths = []
for height in (0.75, 1.5, 2.25):
    scene = st.ball_scene(height=height, light_radius=radius, technique="reference",
                          params={"samples": 256})
    visibility, _ = st.shadow_only(scene)
    measured = st.penumbra_width(scene, visibility)
    # Blocker: the ball's silhouette seen from the light, near height h.
    d_blocker = st.LIGHT[1] - height
    predicted = (st.LIGHT[1] - d_blocker) * 2.0 * radius / d_blocker
    widths.append(measured)
    print("height %.2f: penumbra %.3f, predicted %.3f" % (height, measured, predicted))
    st.check(abs(measured - predicted) <= 0.25 * predicted + 0.05,
             "height %.2f: penumbra width %.3f within 25%% of %.3f" % (height, measured, predicted))
st.check(widths[0] < widths[1] < widths[2], "penumbra widens as the ball rises: %s" % widths)
