# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""What a first frame costs over the next (shader compiles, map allocation)
against the number of lights: a ball over a plane at 64x48 with N lights
around it, under plain VTK and the techniques named in PASSES (default
none,hard,omni); CONE is the lights' cone angle (default 180: point lights).
Run without Mesa's shader cache, as a fresh machine has none
(docs/benchmarks.md):

    MESA_SHADER_CACHE_DISABLE=true PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a python3 scripts/first-frame.py 1 4 8 16 28
"""
import math
import os
import sys
import time

from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkRenderWindow, vtkRenderer)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory)

import vtksoftshadows

PASSES = {"none": None, "hard": vtksoftshadows.vtkHardShadowPass,
          "reference": vtksoftshadows.vtkReferenceShadowPass,
          "contact": vtksoftshadows.vtkContactHardeningShadowPass,
          "omni": vtksoftshadows.vtkOmnidirectionalShadowPass}


def scene(lights, cone):
    renderer = vtkRenderer()
    ground = vtkPlaneSource()
    ground.SetOrigin(-3, 0, -3)
    ground.SetPoint1(3, 0, -3)
    ground.SetPoint2(-3, 0, 3)
    ball = vtkSphereSource()
    ball.SetCenter(0, 1, 0)
    ball.SetRadius(0.5)
    for source in (ground, ball):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    for i in range(lights):
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPositional(True)
        light.SetConeAngle(cone)
        light.SetPosition(2 * math.cos(i), 3, 2 * math.sin(i))
        light.SetFocalPoint(0, 0, 0)
        light.SetIntensity(1.0 / lights)
        renderer.AddLight(light)
    renderer.GetActiveCamera().SetPosition(0, 6, 6)
    renderer.ResetCameraClippingRange()
    return renderer


def first_frame_extra(lights, cone, pass_class):
    """Seconds the first frame takes beyond the second."""
    renderer = scene(lights, cone)
    shadows = pass_class() if pass_class else None
    if shadows:
        renderer.SetPass(shadows)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(64, 48)
    window.AddRenderer(renderer)
    start = time.perf_counter()
    window.Render()
    first = time.perf_counter()
    window.Render()
    second = time.perf_counter()
    if shadows:
        shadows.ReleaseGraphicsResources(window)
    window.Finalize()
    return (first - start) - (second - first)


names = os.environ.get("PASSES", "none,hard,omni").split(",")
cone = float(os.environ.get("CONE", "180"))
print("first frame minus second (s), cone %g; lights, %s" % (cone, ", ".join(names)))
for lights in [int(a) for a in sys.argv[1:]]:
    extras = [first_frame_extra(lights, cone, PASSES[name]) for name in names]
    print("%6d" % lights + "".join("  %5.2f" % e for e in extras))
