# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""How fast vtkLightVisibilityFilter casts: a ground plane of --points
receiver points under a dense isosurface (a thickened gyroid sheet in a
ball) of about --triangles triangles and a spot light of radius 0.5,
--samples rays a point; then the isosurface as its own receiver. Prints
each run's seconds, rays a second and peak memory. Run by
scripts/light-visibility-speed.sh.

    python3 scripts/light-visibility-speed.py [--points N] [--triangles N] [--samples N]
    mpirun -np 2 python3 -m mpi4py scripts/light-visibility-speed.py --split [...]

With --split, under MPI: the ground and the isosurface's triangles dealt
out among the processes (the ground in bands, the triangles in turn), as
ParaView's ranks hold pieces; the filter gathers them. Process 0 prints,
the seconds those of the slowest process.
"""
import argparse
import math
import resource
import time

import numpy as np
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkLight, vtkLightCollection
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

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


def piece(mesh, rank, ranks):
    """Every ranks-th triangle of `mesh` from the rank-th (all its points)."""
    triangles = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)[rank::ranks]
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtk(np.arange(0, 3 * len(triangles) + 1, 3, dtype=np.int64), deep=1),
                  numpy_to_vtk(triangles.ravel().astype(np.int64), deep=1))
    out = vtkPolyData()
    out.SetPoints(mesh.GetPoints())
    out.SetPolys(cells)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--triangles", type=int, default=1000000)
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--split", action="store_true")
    args = parser.parse_args()
    rank, ranks, controller = 0, 1, None
    total = int  # a count over every process
    if args.split:
        from mpi4py import MPI  # initializes MPI for vtkMPIController
        total = MPI.COMM_WORLD.allreduce
        from vtkmodules.vtkParallelCore import vtkMultiProcessController
        from vtkmodules.vtkParallelMPI import vtkMPIController
        controller = vtkMPIController()
        controller.Initialize()
        vtkMultiProcessController.SetGlobalController(controller)
        rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()

    sheet = gyroid(args.triangles)
    side = max(1, int(round(math.sqrt(args.points))) - 1)
    plane = vtkPlaneSource()
    band = 6.0 / ranks  # this process's band of the ground in x
    plane.SetOrigin(-3.0 + rank * band, 0.0, -3.0)
    plane.SetPoint1(-3.0 + rank * band, 0.0, 3.0)
    plane.SetPoint2(-3.0 + (rank + 1) * band, 0.0, -3.0)
    plane.SetResolution(side, max(1, side // ranks))
    plane.Update()
    if ranks > 1:
        sheet = piece(sheet, rank, ranks)
    light = vtkLight()
    light.SetPositional(True)
    light.SetPosition(1.0, 5.0, 1.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    light.SetConeAngle(60.0)
    vtkShadowLightSize.SetRadius(0.5, light)
    lights = vtkLightCollection()
    lights.AddItem(light)

    runs = [("ground", plane.GetOutput(), sheet)]
    if ranks == 1:  # (a piece of the sheet holds all its points)
        runs.append(("isosurface", sheet, None))
    for name, receiver, caster in runs:
        f = vtkLightVisibilityFilter()
        f.SetInputData(receiver)
        if caster is not None:
            f.AddCasterData(caster)
        f.SetLights(lights)
        f.SetSamples(args.samples)
        if controller:
            controller.Barrier()
        start = time.perf_counter()
        f.Update()
        if controller:
            controller.Barrier()
        seconds = time.perf_counter() - start
        visible = f.GetOutput().GetPointData().GetArray("LightVisibility")
        sampled = [visible.GetValue(i) for i in range(0, receiver.GetNumberOfPoints(), 101)]
        mean = total(float(np.sum(sampled))) / max(1, total(len(sampled)))
        points = total(receiver.GetNumberOfPoints())
        triangles = total(sheet.GetNumberOfPolys() + (receiver.GetNumberOfPolys() if caster else 0))
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
        rate = points * args.samples / seconds / 1e6
        if rank > 0:
            continue
        print("%s%s: %d receiver points, %d triangles, %d rays a point: %.2f s, %.1f M rays/s, "
              "mean visibility %.3f, peak %.0f MB"
              % (name, " (%d processes, process 0's memory)" % ranks if ranks > 1 else "",
                 points, triangles, args.samples, seconds, rate, mean, peak))
    if controller:
        controller.Finalize(1)


if __name__ == "__main__":
    main()
