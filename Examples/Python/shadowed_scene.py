# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A ball above a floor, lit by a spot light of radius 0.3, with soft
contact-hardening shadows: the smallest use of the module, one pass set on
a renderer.

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/shadowed_scene.py [OUTPUT.png] [--plain]
"""
import sys

from vtkmodules.vtkFiltersSources import vtkSphereSource

from vtksoftshadows import vtkContactHardeningShadowPass

import example_scene as ex

ball = vtkSphereSource()
ball.SetRadius(0.5)
ball.SetThetaResolution(48)
ball.SetPhiResolution(24)

# Any of the module's passes is set the same way: vtkHardShadowPass,
# vtkReferenceShadowPass, vtkOmnidirectionalShadowPass...
shadows = vtkContactHardeningShadowPass()
sys.exit(ex.render("shadowed_scene",
                   [ex.floor(), ex.actor(ball, (0.9, 0.3, 0.25), (0.0, 1.0, 0.0))],
                   [ex.spot_light((1.0, 5.0, 0.5), 0.3)], shadows))
