# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Shadows as data in ParaView: the plugin's Light Visibility filter on a
floor under an isosurface of ParaView's Wavelet source, with the spot light
of paraview_shadows.py taken from a view (its Radius the light's size).
The floor is coloured by how much of the light each of its points sees, in
ParaView's ordinary render view (the colours are the data, not a rendered
shadow); prints the share of the floor in umbra and in penumbra and saves
a screenshot. In pvbatch under MPI each rank holds its piece of the
isosurface, and every piece shadows the floor.

    PVPYTHON Examples/Python/paraview_light_visibility.py PLUGIN visibility.png
    mpirun -np 2 PVBATCH Examples/Python/paraview_light_visibility.py PLUGIN visibility.png

PLUGIN, PVPYTHON and PVBATCH are the three lines scripts/paraview.sh ends
with.
"""
import sys

from paraview import servermanager
from paraview.simple import (AddLight, ColorBy, Contour, CreateView, GetColorTransferFunction,
                             GetScalarBar, LoadPlugin, Plane, Render, SaveScreenshot, Show,
                             Wavelet)
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, output = sys.argv[1], sys.argv[2]
# remote=True: on the server too, i.e. on every rank of pvbatch or pvserver.
LoadPlugin(plugin, remote=True, ns=globals())

view = CreateView("RenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0  # else the palette's background wins
view.Background = [0.32, 0.34, 0.43]

# A blobby isosurface inside [-10, 10]^3 over a floor whose normal is +y
# (Point1 - Origin x Point2 - Origin): the side that receives light.
wavelet = Wavelet()
surface = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[200.0])
floor = Plane(Origin=[-25, -13, -25], Point1=[-25, -13, 25], Point2=[25, -13, -25],
              XResolution=120, YResolution=120)

# The view's spot light, its Radius the light's size in world units.
light = AddLight(view=view)
light.Coords = "Scene"
light.Type = "Positional"
light.Position = [8.0, 30.0, 12.0]
light.FocalPoint = [0.0, -13.0, 0.0]
light.ConeAngle = 45
light.Radius = 2.0

# How much of that light each point of the floor sees, the isosurface
# casting: LightVisibility (0 to 1) and Irradiance on the floor's points.
visibility = LightVisibility(Input=floor, Casters=[surface], LightsFrom="Lights",  # noqa: F821
                             Lights=[light], Samples=64)

floor_display = Show(visibility, view)
ColorBy(floor_display, ("POINTS", "LightVisibility"))
colours = GetColorTransferFunction("LightVisibility")
# ParaView 5.11 and 5.13 name the preset "Inferno (matplotlib)", 6 "Inferno"
# (an unknown name: False from 5.11, an error from 6.1).
for preset in ("Inferno (matplotlib)", "Inferno"):
    try:
        if colours.ApplyPreset(preset, True):
            break
    except RuntimeError:
        pass
colours.RescaleTransferFunction(0.0, 1.0)
floor_display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(colours, view)
bar.Title = "light visible"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
surface_display = Show(surface, view)
ColorBy(surface_display, None)
surface_display.DiffuseColor = [0.75, 0.75, 0.75]

# The values, gathered from every rank.
data = servermanager.Fetch(visibility)
seen = vtk_to_numpy(data.GetPointData().GetArray("LightVisibility"))
print("floor: %d points, %.1f%% in umbra, %.1f%% in penumbra" % (
    len(seen), 100 * (seen < 0.01).mean(), 100 * ((seen >= 0.01) & (seen <= 0.99)).mean()))

Render(view)  # the first render resets the camera: set it after
view.CameraPosition = [0.0, 38.0, 42.0]
view.CameraFocalPoint = [0.0, -10.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
SaveScreenshot(output, view, ImageResolution=view.ViewSize)
print("wrote " + output)
