# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""vtkLightVisibilityFilter split among MPI processes, as ParaView's pvbatch
ranks hold their pieces (run under mpirun -np 2). The ground is cut in two
at x = 0, a half on each process; the ball over it is on process 1 only,
and the light, to its right, throws its shadow on process 0's half. Each
process's values must be the ones a single process computes with all the
data (rays drawn from each point's position, whichever piece holds it),
process 0's half must hold the ball's shadow (which it sees only through
the exchange), and a refused piece on one process must stop both with an
error rather than hang them."""
import sys

import numpy as np

try:
    from mpi4py import MPI  # noqa: F401 (initializes MPI, which vtkMPIController expects)
    from vtkmodules.vtkParallelMPI import vtkMPIController
except ImportError as missing:
    print("skipped: %s" % missing)
    sys.exit(77)
from vtkmodules.vtkCommonCore import vtkCommand, vtkIntArray
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkParallelCore import vtkCommunicator, vtkMultiProcessController
from vtkmodules.vtkRenderingCore import vtkLight, vtkLightCollection
from vtkmodules.util.numpy_support import vtk_to_numpy

from vtksoftshadows import vtkLightVisibilityFilter, vtkShadowLightSize

controller = vtkMPIController()
controller.Initialize()
vtkMultiProcessController.SetGlobalController(controller)
rank = controller.GetLocalProcessId()
ranks = controller.GetNumberOfProcesses()
failures = []


def check(condition, message):
    print("%d/%d %s%s" % (rank, ranks, "ok: " if condition else "FAIL: ", message), flush=True)
    if not condition:
        failures.append(message)


def half(side):
    """Process `side`'s half of the ground (-2..0 or 0..2 in x), normal +y."""
    plane = vtkPlaneSource()
    x0, x1 = (-2.0, 0.0) if side == 0 else (0.0, 2.0)
    plane.SetOrigin(x0, 0, -1.5)
    plane.SetPoint1(x0, 0, 1.5)
    plane.SetPoint2(x1, 0, -1.5)
    plane.SetResolution(30, 20)
    plane.Update()
    return plane.GetOutput()


sphere = vtkSphereSource()
sphere.SetCenter(0.5, 1.0, 0.0)
sphere.SetRadius(0.5)
sphere.SetThetaResolution(64)
sphere.SetPhiResolution(32)
sphere.Update()
ball = sphere.GetOutput()

light = vtkLight()
light.SetPositional(True)
light.SetPosition(2.5, 3.0, 0.0)
light.SetFocalPoint(2.5, 0.0, 0.0)
light.SetConeAngle(180.0)
vtkShadowLightSize.SetRadius(0.3, light)
lights = vtkLightCollection()
lights.AddItem(light)


def visibility(receiver, casters, shared):
    f = vtkLightVisibilityFilter()
    f.SetController(controller if shared else None)
    f.SetInputData(receiver)
    for caster in casters:
        f.AddCasterData(caster)
    f.SetLights(lights)
    f.SetSamples(64)
    errors = []
    f.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
    f.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
    f.Update()
    out = f.GetOutput()
    values = out.GetPointData().GetArray("LightVisibility")
    points = vtk_to_numpy(out.GetPoints().GetData()) if out.GetPoints() else np.zeros((0, 3))
    return points, None if values is None else vtk_to_numpy(values).reshape(-1).copy(), errors


mine = half(rank)
points, shared, _ = visibility(mine, [ball] if rank == 1 else [], True)

# One process with all of it: both halves as the receiver, the ball as a caster.
whole = vtkAppendPolyData()
whole.AddInputData(half(0))
whole.AddInputData(half(1))
whole.Update()
all_points, all_values, _ = visibility(whole.GetOutput(), [ball], False)
alone = {tuple(p): v for p, v in zip(all_points.astype(np.float32).tolist(), all_values)}
expected = np.array([alone[tuple(p)] for p in points.astype(np.float32).tolist()])
difference = np.abs(shared - expected)
check(difference.max() < 1e-6,
      "%d points as one process with all the data computes them (largest difference %.2g)"
      % (len(points), difference.max()))
if rank == 0:
    check(shared.min() < 0.05 and (shared < 0.5).sum() > 20,
          "the ball on process 1 shadows process 0's ground: %d points below half, darkest %.3f"
          % ((shared < 0.5).sum(), shared.min()))
    # Without the exchange the shadow is missing: what the check above catches.
    _, own, _ = visibility(mine, [], False)
    check(own.min() > 0.999, "without the exchange, process 0's ground is all lit (darkest %.3f)"
          % own.min())

# A NaN point on process 1's piece: both processes stop, with an error each.
broken = half(rank)
if rank == 1:
    broken.GetPoints().SetPoint(5, float("nan"), 0.0, 0.0)
_, values, errors = visibility(broken, [], True)
check(values is None and errors,
      "a NaN point on process 1 stops every process with an error (%d error(s), %s)"
      % (len(errors), "no arrays" if values is None else "arrays computed"))

own_failures, all_failures = vtkIntArray(), vtkIntArray()
own_failures.InsertNextValue(len(failures))
controller.AllReduce(own_failures, all_failures, vtkCommunicator.SUM_OP)
controller.Finalize(1)  # mpi4py finalizes MPI
if all_failures.GetValue(0):
    print("%d/%d: %d failures across the processes" % (rank, ranks, all_failures.GetValue(0)))
    sys.exit(1)
print("%d/%d ok" % (rank, ranks))
