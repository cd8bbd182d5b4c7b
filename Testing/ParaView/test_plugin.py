"""The ParaView plugin in pvpython (scripts/paraview.sh runs it): a ball over
a plane under a spot light, drawn by ParaView's own render view and by the
plugin's, under every choice of Shadow Technique. The plugin's view darkens
the ground under the ball, where the light's shadow falls, and leaves the
rest as ParaView draws it.

The plugin's view is one view whose technique changes, as a user changes it.
The script ends by falling off its end or by an exception, never sys.exit():
Debian's pvpython 5.11 crashes while tearing down its views after
sys.exit(), plugin or not.

    PVPYTHON test_plugin.py PLUGIN
"""
import os
import sys
import tempfile

import numpy as np
from paraview.simple import (AddLight, CreateView, LoadPlugin, Plane, Render, SaveScreenshot,
                             Show, Sphere)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

SIZE = [160, 120]
failures = []


def check(condition, message):
    print(("ok: " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def grey(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)
    return pixels[:, :3].mean(axis=1).reshape(SIZE[1], SIZE[0])


def scene(proxy, technique=None):
    view = CreateView(proxy)
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseLight = 0  # the light kit off: only the spot light below
    if technique is not None:
        view.ShadowTechnique = technique
    Show(Plane(Origin=[-3, 0, -3], Point1=[3, 0, -3], Point2=[-3, 0, 3]), view)
    Show(Sphere(Center=[0, 1, 0], Radius=0.5, ThetaResolution=32, PhiResolution=32), view)
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Positional"
    light.Position = [0.0, 5.0, 0.0]
    light.FocalPoint = [0.0, 0.0, 0.0]
    light.ConeAngle = 50
    Render(view)  # the first render resets the camera: set it after
    view.CameraPosition = [0, 5, 7]
    view.CameraFocalPoint = [0, 0.5, 0]
    view.CameraViewUp = [0, 1, 0]
    Render(view)
    return view


LoadPlugin(sys.argv[1], remote=False, ns=globals())
with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "plain.png")
    SaveScreenshot(path, scene("RenderView"), ImageResolution=SIZE)
    plain = grey(path)
    view = scene("ShadowRenderView")
    names = view.GetProperty("ShadowTechnique").Available
    check(len(names) == 12 and names[0] == "hard" and "smoothies" in names,
          "Shadow Technique offers every technique and variant: %s" % names)
    for name in names:
        view.ShadowTechnique = name
        Render(view)
        path = os.path.join(folder, name.replace(":", "-") + ".png")
        SaveScreenshot(path, view, ImageResolution=SIZE)
        shaded = grey(path)
        darker = (plain - shaded) > 40
        share = darker.mean()
        rows, columns = np.nonzero(darker)
        # The shadow lies on the ground under the ball: below the image's
        # middle (VTK's images start at the bottom), around its centre.
        where = 1.0 - rows.mean() / SIZE[1] if rows.size else 0.0
        across = abs(columns.mean() / SIZE[0] - 0.5) if columns.size else 1.0
        same = (np.abs(plain - shaded) < 8).mean()
        check(0.005 < share < 0.2 and where > 0.45 and across < 0.1 and same > 0.75,
              "%s: %.1f%% of pixels in shadow, centred at %.2f down and %.2f across, "
              "%.0f%% as ParaView draws them" % (name, 100 * share, where, across, 100 * same))

if failures:
    raise RuntimeError("%d failures" % len(failures))
print("ok")
