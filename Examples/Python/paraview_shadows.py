# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""ParaView with soft shadows: an isosurface of ParaView's Wavelet source
over a floor, in the plugin's "Render View (Soft Shadows)", lit by a spot
light whose Radius (ParaView's own light property) softens the shadows.
Saves a screenshot. In pvbatch under MPI each rank draws its piece of the
data and the shadows still fall across the pieces.

    PVPYTHON Examples/Python/paraview_shadows.py PLUGIN shadows.png [TECHNIQUE]
    mpirun -np 2 PVBATCH Examples/Python/paraview_shadows.py PLUGIN shadows.png

PLUGIN, PVPYTHON and PVBATCH are the three lines scripts/paraview.sh ends
with; TECHNIQUE is one of the view's Shadow Technique choices (default
contact).
"""
import sys

from paraview.simple import (AddLight, ColorBy, Contour, CreateView, LoadPlugin, Plane,
                             Render, SaveScreenshot, Show, Wavelet)

plugin, output = sys.argv[1], sys.argv[2]
technique = sys.argv[3] if len(sys.argv) > 3 else "contact"
# remote=True: on the server too, i.e. on every rank of pvbatch or pvserver.
LoadPlugin(plugin, remote=True, ns=globals())

view = CreateView("ShadowRenderView")
view.ViewSize = [800, 600]
view.ShadowTechnique = technique
view.ShadowMapSize = 2048
view.UseLight = 0  # only the spot light below lights the scene
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0  # else the palette's background wins
view.Background = [0.32, 0.34, 0.43]

# The data: a blobby isosurface inside [-10, 10]^3, over a floor below it.
wavelet = Wavelet()
surface = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[200.0])
floor = Plane(Origin=[-25, -13, -25], Point1=[25, -13, -25], Point2=[-25, -13, 25])
surface_display = Show(surface, view)
ColorBy(surface_display, None)  # one colour, not the contour value
floor_display = Show(floor, view)
# Some ambient light, so that what the spot light does not reach is not black.
for display in (surface_display, floor_display):
    display.Ambient = 0.15
surface_display.DiffuseColor = [0.9, 0.55, 0.3]
surface_display.AmbientColor = [0.9, 0.55, 0.3]

# ParaView's own light controls: a spot light, its Radius the light's size
# in world units (for a directional light, its angular radius in degrees).
light = AddLight(view=view)
light.Coords = "Scene"
light.Type = "Positional"
light.Position = [8.0, 30.0, 12.0]
light.FocalPoint = [0.0, -13.0, 0.0]
light.ConeAngle = 45
light.Radius = 2.0

Render(view)  # the first render resets the camera: set it after
view.CameraPosition = [0.0, 22.0, 52.0]
view.CameraFocalPoint = [0.0, -5.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
SaveScreenshot(output, view, ImageResolution=view.ViewSize)
print("wrote " + output)
