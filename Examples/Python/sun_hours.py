# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Shadows as data: a small city block coloured by its hours of direct sun
on one day (vtkLightVisibilityFilter with SunHoursOn), at a latitude.
GIS axes: z up, y north, x east; lengths in metres.

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/sun_hours.py [OUTPUT.png]
          [--latitude DEG] [--day N] [--samples N]

writes OUTPUT.png (default sun_hours.png), prints its path, then the day's
daylight, the roofs' sun and the share of the streets under two hours of
it. Defaults: 48 degrees north, the December solstice (day 355), 16 rays.
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersModeling import vtkLinearSubdivisionFilter
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (the scalar bar's text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

from vtksoftshadows import vtkLightVisibilityFilter

parser = argparse.ArgumentParser()
parser.add_argument("output", nargs="?", default="sun_hours.png")
parser.add_argument("--latitude", type=float, default=48.0)
parser.add_argument("--day", type=int, default=355)
parser.add_argument("--samples", type=int, default=16)
args = parser.parse_args()

# Four by four buildings 10 m square, streets 8 m wide, heights 6 to 30 m.
HEIGHTS = [[12, 24, 9, 18], [6, 30, 15, 12], [21, 9, 27, 6], [15, 18, 12, 24]]
blocks = vtkAppendPolyData()
for row, heights in enumerate(HEIGHTS):
    for column, height in enumerate(heights):
        x, y = -27.0 + 18.0 * column, -27.0 + 18.0 * row
        box = vtkCubeSource()
        box.SetBounds(x - 5.0, x + 5.0, y - 5.0, y + 5.0, 0.0, float(height))
        box.Update()
        blocks.AddInputData(box.GetOutput())
# Fine triangles on the buildings, so that the walls show where the sun
# reaches down them.
triangles = vtkTriangleFilter()
triangles.SetInputConnection(blocks.GetOutputPort())
buildings = vtkLinearSubdivisionFilter()
buildings.SetInputConnection(triangles.GetOutputPort())
buildings.SetNumberOfSubdivisions(3)
ground = vtkPlaneSource()  # 90 m square in 1 m cells, normal +z
ground.SetOrigin(-45.0, -45.0, 0.0)
ground.SetPoint1(45.0, -45.0, 0.0)
ground.SetPoint2(-45.0, 45.0, 0.0)
ground.SetResolution(90, 90)
city = vtkAppendPolyData()
city.AddInputConnection(buildings.GetOutputPort())
city.AddInputConnection(ground.GetOutputPort())

sun = vtkLightVisibilityFilter()
sun.SetInputConnection(city.GetOutputPort())  # receives, and casts on itself
sun.SunHoursOn()
sun.SetSunLatitude(args.latitude)
sun.SetSunDayOfYear(args.day)
sun.SetSunTimeStep(0.25)
sun.SetSamples(args.samples)
sun.Update()
out = sun.GetOutput()

# What the day gives the roofs, which nothing shades, and the street level.
hours = vtk_to_numpy(out.GetPointData().GetArray("SunHours"))
fraction = vtk_to_numpy(out.GetPointData().GetArray("SunFraction"))
points = vtk_to_numpy(out.GetPoints().GetData())
normals = vtk_to_numpy(out.GetPointData().GetArray("Normals"))
up = normals[:, 2] > 0.99
roofs = up & (points[:, 2] > 1.0)
# The streets: the ground outside the buildings' footprints.
centres = np.array([[-27.0 + 18.0 * column, -27.0 + 18.0 * row]
                    for row in range(4) for column in range(4)])
offsets = np.abs(points[:, None, :2] - centres[None, :, :])
under = np.any(np.all(offsets <= 5.0, axis=2), axis=1)
street = up & (points[:, 2] < 1.0e-6) & ~under
daylight = float(np.max(hours[roofs] / np.maximum(fraction[roofs], 1e-9)))

lookup = vtkLookupTable()
lookup.SetHueRange(0.67, 0.12)  # blue (none) to yellow (all day)
lookup.SetRange(0.0, max(daylight, 1e-3))
lookup.Build()
mapper = vtkPolyDataMapper()
mapper.SetInputData(out)
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectColorArray("SunHours")
mapper.SetLookupTable(lookup)
mapper.UseLookupTableScalarRangeOn()
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetAmbient(0.5)  # the colours, with a little shading for shape
actor.GetProperty().SetDiffuse(0.5)
bar = vtkScalarBarActor()
bar.SetLookupTable(lookup)
bar.SetTitle("hours of sun")
bar.SetWidth(0.1)
bar.SetHeight(0.7)
bar.SetPosition(0.86, 0.12)
bar.SetVerticalTitleSeparation(8)
bar.SetLabelFormat("%.0f")
bar.UnconstrainedFontSizeOn()
for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
    text.SetFontSize(16)
    text.SetColor(0.15, 0.15, 0.2)
    text.ShadowOff()
    text.ItalicOff()
bar.SetNumberOfLabels(5)

renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.AddActor2D(bar)
renderer.SetBackground(0.95, 0.95, 0.97)
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(0.0, 0.0, 5.0)
camera.SetPosition(85.0, -115.0, 100.0)  # from the south-east, above
camera.SetViewUp(0.0, 0.0, 1.0)
renderer.ResetCameraClippingRange()
window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(640, 480)
window.AddRenderer(renderer)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetInputConnection(grab.GetOutputPort())
writer.SetFileName(args.output)
writer.Write()
print(args.output)
print("latitude %.1f, day %d: %.2f hours of daylight" % (args.latitude, args.day, daylight))
print("roofs: %.2f to %.2f hours of sun" % (hours[roofs].min(), hours[roofs].max()))
print("streets: %.0f%% under two hours of sun" % (100.0 * np.mean(hours[street] < 2.0)))
