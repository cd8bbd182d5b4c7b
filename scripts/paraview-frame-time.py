# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Frame time of the plugin's view in pvbatch with the light moving every
frame: a ball of 2 x RESOLUTION^2 triangles, split across the ranks, over a
plane (docs/paraview.md). Run under mpirun -np 1 and -np 2 and compare; on
more than one rank it also times each technique without combining the
shadow maps across the ranks (wrong shadows, but the cost of combining).

    [mpirun -np N] PVBATCH scripts/paraview-frame-time.py PLUGIN [TECHNIQUE...]
"""
import math
import sys
import time

from paraview import servermanager
from paraview.simple import (AddLight, CreateView, LoadPlugin, Plane, Render, Show,
                             Sphere)

FRAMES = 40
RESOLUTION = 256
SIZE = [640, 480]

LoadPlugin(sys.argv[1], remote=True, ns=globals())
techniques = sys.argv[2:] or ["hard", "contact", "omni"]
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()

view = CreateView("ShadowRenderView")
view.ViewSize = SIZE
view.OrientationAxesVisibility = 0
view.UseLight = 0
Show(Plane(Origin=[-3, 0, -3], Point1=[3, 0, -3], Point2=[-3, 0, 3]), view)
Show(Sphere(Center=[0, 1.2, 0], Radius=0.5, ThetaResolution=RESOLUTION,
            PhiResolution=RESOLUTION), view)
light = AddLight(view=view)
light.Coords = "Scene"
light.Type = "Positional"
light.FocalPoint = [0.0, 0.0, 0.0]
light.ConeAngle = 60
light.Radius = 0.3
view.CameraPosition = [0, 4.5, 5.5]
view.CameraFocalPoint = [0, 0.3, 0]
view.CameraViewUp = [0, 1, 0]

print("%d rank(s), %dx%d, %d frames, light moving" % (ranks, SIZE[0], SIZE[1], FRAMES))


def median_frame_time():
    times = []
    for frame in range(FRAMES + 3):
        angle = 0.05 * frame
        light.Position = [1.5 * math.cos(angle), 3.0, 1.5 * math.sin(angle)]
        start = time.perf_counter()
        Render(view)
        if frame >= 3:  # after shaders are built
            times.append(time.perf_counter() - start)
    times.sort()
    return 1000 * times[len(times) // 2]


for name in techniques:
    view.ShadowTechnique = name
    view.CombineShadowMaps = 1
    line = "%-18s median %.1f ms a frame" % (name, median_frame_time())
    if ranks > 1:
        # What combining the maps across the ranks costs.
        view.CombineShadowMaps = 0
        line += ", %.1f ms without combining the maps" % median_frame_time()
    print(line, flush=True)
