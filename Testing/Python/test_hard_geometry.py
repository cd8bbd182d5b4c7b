# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""`hard` puts the ball's shadow exactly where geometry says, on a
non-square window: every ground pixel more than two pixels from the
predicted shadow edge is lit (1) or in umbra (0) as predicted."""
import numpy as np

import shadowtest as st

for params, label in [({"pcf_radius": 0, "hardware_filtering": False}, "binary"),
                      ({}, "default"),
                      ({"pcf_radius": 2}, "PCF radius 2")]:
    scene = st.ball_scene(height=1.0, params=params, size=(240, 180))
    visibility, geometry = st.shadow_only(scene)
    ground, shadowed, edge = st.expected_hard_shadow(scene)

    st.check(visibility.shape == (180, 240), "%s: output has the render size" % label)
    st.check(geometry[ground].all(), "%s: alpha marks every ground pixel" % label)
    st.check(not geometry[0, :].any(), "%s: bottom row (off the ground) is background" % label)

    # Two pixels from the edge, plus the PCF footprint (about 1.5 screen
    # pixels per map texel here).
    margin = 2.0 + 1.5 * params.get("pcf_radius", 0)
    far = ground & (edge > margin)
    umbra = far & shadowed
    lit = far & ~shadowed
    st.check(umbra.sum() > 300 and lit.sum() > 10000,
             "%s: enough pixels to judge (%d umbra, %d lit)" % (label, umbra.sum(), lit.sum()))
    st.check(np.all(visibility[umbra] < 0.02),
             "%s: predicted umbra is dark (max %.3f)" % (label, visibility[umbra].max()))
    st.check(np.all(visibility[lit] > 0.98),
             "%s: predicted lit ground is fully lit (min %.3f)" % (label, visibility[lit].min()))
