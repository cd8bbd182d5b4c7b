# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A cylinder floating over a floor under a spot light of radius 0.5:
smoothies (vtkSmoothieShadowPass), soft edges drawn from geometry extruded
along the cylinder's silhouette as the light sees it, found anew as the
light moves.

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/smoothies_cylinder.py [OUTPUT.png] [--plain]
"""
import sys

from vtkmodules.vtkFiltersSources import vtkCylinderSource

from vtksoftshadows import vtkSmoothieShadowPass

import example_scene as ex

cylinder = vtkCylinderSource()
cylinder.SetRadius(0.4)
cylinder.SetHeight(1.2)
cylinder.SetResolution(24)

cylinder_actor = ex.actor(cylinder, (0.3, 0.7, 0.4), (0.0, 1.4, 0.0))
cylinder_actor.RotateZ(60.0)
sys.exit(ex.render("smoothies_cylinder", [ex.floor(), cylinder_actor],
                   [ex.spot_light((1.0, 5.0, 0.5), 0.5)], vtkSmoothieShadowPass()))
