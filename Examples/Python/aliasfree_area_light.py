# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A ball and a box under a rectangular area light, 0.8 by 0.4: alias-free
shadow maps (vtkAliasFreeShadowPass), shadows tested for exactly the points
the camera sees and soft shadows from light samples over the rectangle, in
OpenGL 4.3 compute.

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/aliasfree_area_light.py [OUTPUT.png] [--plain]
"""
import sys

from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource

from vtksoftshadows import vtkAliasFreeShadowPass

import example_scene as ex

ball = vtkSphereSource()
ball.SetRadius(0.5)
ball.SetThetaResolution(48)
ball.SetPhiResolution(24)
box = vtkCubeSource()
box.SetXLength(0.6)
box.SetYLength(0.6)
box.SetZLength(0.6)

shadows = vtkAliasFreeShadowPass()
shadows.SetLightShape(2)            # a square of side 2 radius across the light's axis,
shadows.SetLightScale(2.0, 1.0, 1.0)  # stretched to 4 radius by 2 radius
shadows.SetNumberOfLightSamples(128)
sys.exit(ex.render("aliasfree_area_light",
                   [ex.floor(), ex.actor(ball, (0.9, 0.3, 0.25), (-0.7, 1.0, 0.0)),
                    ex.actor(box, (0.4, 0.6, 0.9), (0.9, 0.3, 0.4))],
                   [ex.spot_light((0.0, 5.0, 0.5), 0.2)], shadows))
