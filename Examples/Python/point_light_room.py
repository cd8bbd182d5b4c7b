# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A point light (cone of 180 degrees) of radius 0.15 in a corner of a room
with a column and a ball: omnidirectional cube-map shadows, softened from
the light's radius (vtkOmnidirectionalShadowPass, its Poisson filter).

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/point_light_room.py [OUTPUT.png] [--plain]
"""
import sys

from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkCylinderSource, vtkSphereSource

from vtksoftshadows import vtkOmnidirectionalShadowPass

import example_scene as ex

walls = []
for center, extent in (((0, -0.05, 0), (6, 0.1, 6)), ((0, 1.5, -3.05), (6, 3, 0.1)),
                       ((-3.05, 1.5, 0), (0.1, 3, 6))):
    wall = vtkCubeSource()
    wall.SetCenter(*center)
    wall.SetXLength(extent[0])
    wall.SetYLength(extent[1])
    wall.SetZLength(extent[2])
    walls.append(ex.actor(wall))
column = vtkCylinderSource()
column.SetRadius(0.25)
column.SetHeight(2.0)
column.SetResolution(32)
ball = vtkSphereSource()
ball.SetRadius(0.45)
ball.SetThetaResolution(48)
ball.SetPhiResolution(24)

# A positional light with a cone of 90 degrees or more lights every way:
# its shadows come from a cube map.
light = ex.spot_light((0.5, 2.2, 0.8), 0.15, cone_angle=180.0)
sys.exit(ex.render("point_light_room",
                   walls + [ex.actor(column, (0.4, 0.6, 0.9), (-1.2, 1.0, -1.0)),
                            ex.actor(ball, (0.9, 0.3, 0.25), (-0.6, 0.45, 0.8))],
                   [light], vtkOmnidirectionalShadowPass(),
                   camera_position=(3.0, 3.5, 6.0), focal_point=(-0.8, 0.8, -0.5)))
