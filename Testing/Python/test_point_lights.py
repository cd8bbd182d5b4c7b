# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Point lights (Gerasimov, GPU Gems ch. 12): a point light inside a closed
room with an occluder towards each wall. Two views between them show all six
walls; on each, the shadow-only output matches ray-cast geometry away from
edges, and pixels along the cube map's face borders show no seam."""
import numpy as np

import shadowtest as st

# Two corners of the room, each looking past the light at the opposite one.
views = [
    {"position": [-3.5, -3.5, 3.5], "focal_point": [1.0, 1.0, -1.0],
     "view_up": [0, 1, 0], "view_angle": 100},
    {"position": [3.5, 3.5, -3.5], "focal_point": [-1.0, -1.0, 1.0],
     "view_up": [0, 1, 0], "view_angle": 100},
]
walls_seen = np.zeros((6, 2), dtype=int)  # per wall: shadowed, lit pixels checked
# Both ways of drawing the cube, one layered pass and six passes, and the
# paper's RGBA8-packed distances.
for camera, technique, packed in [(v, t, p) for v in views for t, p in
                                  (("hard", False), ("hard:sixpass", False), ("hard", True))]:
    scene = st.room_scene(camera)
    scene["shadows"]["hard"] = {"packed_cube_maps": packed}
    visibility, geometry = st.shadow_only(scene, technique)
    technique += " packed" if packed else ""
    wall, points, hidden = st.room_expected(scene)
    umbra = st.interior(wall & hidden, 2)
    lit = st.interior(wall & ~hidden, 2)
    st.check(np.all(visibility[umbra] < 0.02),
             "%s: predicted shadows on the walls are dark (%d px, max %.3f)"
             % (technique, umbra.sum(), visibility[umbra].max()))
    st.check(np.all(visibility[lit] > 0.98),
             "%s: predicted lit walls are lit (%d px, min %.3f)"
             % (technique, lit.sum(), visibility[lit].min()))
    # Which wall each pixel shows: the axis and sign of its largest coordinate.
    axis = np.argmax(np.abs(points), axis=2)
    side = axis * 2 + (np.take_along_axis(points, axis[:, :, None], 2)[:, :, 0] < 0)
    for w in range(6):
        walls_seen[w, 0] += np.sum(umbra & (side == w))
        walls_seen[w, 1] += np.sum(lit & (side == w))

    # Face borders: directions from the light whose two largest components
    # are within 2% of each other.
    magnitudes = np.sort(np.abs(points), axis=2)
    border = lit & (magnitudes[:, :, 2] - magnitudes[:, :, 1] < 0.02 * magnitudes[:, :, 2])
    st.check(border.sum() > 50 and np.all(visibility[border] > 0.98),
             "no seam along cube face borders (%d px, min %.3f)"
             % (border.sum(), visibility[border].min() if border.any() else 1.0))

names = ["+x", "-x", "+y", "-y", "+z", "-z"]
for w in range(6):
    st.check(walls_seen[w, 0] > 20 and walls_seen[w, 1] > 200,
             "wall %s: shadow and light checked (%d, %d px)"
             % (names[w], walls_seen[w, 0], walls_seen[w, 1]))

# The reference shadows point lights too: with radius 0, one cube map at the
# light, it is `hard`; with a radius its shadows soften.
scene = st.room_scene(views[0])
hard, geometry = st.shadow_only(scene, "hard")
reference, _ = st.shadow_only(scene, "reference")
differ = geometry & (np.abs(hard - reference) > 0.02)
st.check(differ.sum() <= 0.002 * geometry.sum(),
         "radius 0: reference equals hard for point lights (%d of %d pixels differ)"
         % (differ.sum(), geometry.sum()))
soft_scene = st.room_scene(views[0], light_radius=0.3, technique="reference")
soft_scene["shadows"]["reference"] = {"samples": 64}
soft, _ = st.shadow_only(soft_scene)
penumbra = geometry & (soft > 0.05) & (soft < 0.95)
st.check(penumbra.sum() > 4 * np.sum(geometry & (hard > 0.05) & (hard < 0.95)),
         "radius 0.3: the reference grows penumbrae (%d px)" % penumbra.sum())

# Techniques that read float cube maps draw those when PackedCubeMaps is on
# (one warning), leaving the setting as the user made it: the same shadow.
for technique in ("silhouette", "smoothies"):
    scene = st.room_scene(views[0], light_radius=0.2)
    floats, _ = st.shadow_only(scene, technique)
    scene["shadows"][technique] = {"packed_cube_maps": True}
    packed, _ = st.shadow_only(scene, technique)
    st.check(np.array_equal(floats, packed),
             "%s with packed_cube_maps: the float cube maps' shadow (%d pixels differ)"
             % (technique, np.sum(floats != packed)))
