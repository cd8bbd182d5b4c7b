# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""How fast vtkLightVisibilityFilter casts: a ground plane of --points
receiver points under a dense isosurface (a thickened gyroid sheet in a
ball) of about --triangles triangles and a spot light of radius 0.5,
--samples rays a point; then the isosurface as its own receiver. Prints
each run's seconds, rays a second and peak memory. Run by
scripts/light-visibility-speed.sh.

    python3 scripts/light-visibility-speed.py [--points N] [--triangles N] [--samples N]
"""
import argparse
import math
import resource
import time

import numpy as np
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkLight, vtkLightCollection
from vtkmodules.util.numpy_support import numpy_to_vtk

from vtksoftshadows import vtkLightVisibilityFilter, vtkShadowLightSize


def gyroid(triangles):
    """The sheet |sin x cos y + sin y cos z + sin z cos x| < 0.3 (6 periods
    across) inside a unit ball over the plane, positive inside so that its
    normals point out; the grid grows with the square root of the
    triangles."""
    n = max(16, int(round(225 * math.sqrt(triangles / 1.0e6))))
    x = np.linspace(-1.0, 1.0, n)
    X, Y, Z = np.meshgrid(x, x, x, indexing="ij")
    k = 6.0
    g = (np.sin(k * X) * np.cos(k * Y) + np.sin(k * Y) * np.cos(k * Z)
         + np.sin(k * Z) * np.cos(k * X))
    field = np.where(X * X + Y * Y + Z * Z < 1.0, 0.3 - np.abs(g), -1.0)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(2.0 / (n - 1), 2.0 / (n - 1), 2.0 / (n - 1))
    image.SetOrigin(-1.0, 0.2, -1.0)
    image.GetPointData().SetScalars(numpy_to_vtk(field.ravel(order="F").astype(np.float32)))
    contour = vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, 0.0)
    contour.Update()
    return contour.GetOutput()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--triangles", type=int, default=1000000)
    parser.add_argument("--samples", type=int, default=64)
    args = parser.parse_args()

    sheet = gyroid(args.triangles)
    side = max(1, int(round(math.sqrt(args.points))) - 1)
    plane = vtkPlaneSource()
    plane.SetOrigin(-3.0, 0.0, -3.0)
    plane.SetPoint1(-3.0, 0.0, 3.0)
    plane.SetPoint2(3.0, 0.0, -3.0)
    plane.SetResolution(side, side)
    plane.Update()
    light = vtkLight()
    light.SetPositional(True)
    light.SetPosition(1.0, 5.0, 1.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    light.SetConeAngle(60.0)
    vtkShadowLightSize.SetRadius(0.5, light)
    lights = vtkLightCollection()
    lights.AddItem(light)

    runs = [("ground", plane.GetOutput(), sheet), ("isosurface", sheet, None)]
    for name, receiver, caster in runs:
        f = vtkLightVisibilityFilter()
        f.SetInputData(receiver)
        if caster is not None:
            f.AddCasterData(caster)
        f.SetLights(lights)
        f.SetSamples(args.samples)
        start = time.perf_counter()
        f.Update()
        seconds = time.perf_counter() - start
        points = receiver.GetNumberOfPoints()
        triangles = sheet.GetNumberOfPolys() + (receiver.GetNumberOfPolys() if caster else 0)
        visible = f.GetOutput().GetPointData().GetArray("LightVisibility")
        mean = float(np.mean([visible.GetValue(i) for i in range(0, points, 101)]))
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
        rate = points * args.samples / seconds / 1e6
        print("%s: %d receiver points, %d triangles, %d rays a point: %.2f s, %.1f M rays/s, "
              "mean visibility %.3f, peak %.0f MB"
              % (name, points, triangles, args.samples, seconds, rate, mean, peak))


if __name__ == "__main__":
    main()
