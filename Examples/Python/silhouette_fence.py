# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A fence over a floor under a spot light of radius 0.3: silhouette-distance
shadow maps (vtkSilhouetteShadowPass, soft variant), which anti-alias the
thin slats' shadow edges and widen their penumbrae with the distance to the
floor.

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/silhouette_fence.py [OUTPUT.png] [--plain]
"""
import sys

from vtksoftshadows import vtkFenceSource, vtkSilhouetteShadowPass

import example_scene as ex

fence = vtkFenceSource()
fence.SetNumberOfPickets(9)
fence.SetHeight(1.6)

shadows = vtkSilhouetteShadowPass()  # SetVariantToHard(): anti-aliased hard shadows
sys.exit(ex.render("silhouette_fence",
                   [ex.floor(), ex.actor(fence, (0.75, 0.55, 0.35), (0.0, 0.3, 0.0))],
                   [ex.spot_light((0.5, 5.0, 3.0), 0.3)], shadows))
