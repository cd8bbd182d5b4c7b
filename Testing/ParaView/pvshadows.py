# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""What the ParaView tests share: the scene (a ball over a plane under a spot
light of radius 0.3), reading screenshots, projecting world points to
pixels, and checks that count failures."""
import os
import sys

import numpy as np
import paraview.simple as pvsimple
from paraview.simple import AddLight, CreateView, Plane, Render, SaveScreenshot, Show, Sphere

# The module's own test helpers, for what does not depend on which VTK runs them.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from shadowtest import read_png  # noqa: E402

SIZE = [240, 180]
LIGHT = [0.0, 3.0, 0.0]
BALL = [0.0, 1.2, 0.0]
BALL_RADIUS = 0.5
LIGHT_RADIUS = 0.3
failures = []


def check(condition, message):
    print(("ok: " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        failures.append(message)


def finish():
    """Raises when a check failed. (Never sys.exit(): Debian's pvpython 5.11
    crashes while tearing down its views after it.)"""
    if failures:
        raise RuntimeError("%d failures:\n  %s" % (len(failures), "\n  ".join(failures)))
    print("ok", flush=True)


def grey(path):
    """The screenshot at `path` as grey levels, row 0 at the image's top."""
    return read_png(path)[:, :, :3].astype(float).mean(axis=2)[::-1]


def image_path(folder, name):
    """Where screenshot() puts the image called `name` (a technique's spec, maybe)."""
    return os.path.join(folder, name.replace(":", "-") + ".png")


def screenshot(view, folder, name):
    path = image_path(folder, name)
    SaveScreenshot(path, view, ImageResolution=SIZE)
    return grey(path), path


def check_alike(image, reference, what, mean, share):
    """`image` as `reference`: on average within `mean` levels, and less than
    `share` of its pixels off by more than 24."""
    off = np.abs(image - reference)
    check(off.mean() < mean and (off > 24).mean() < share,
          "%s (mean difference %.2f levels, %.2f%% of pixels off by more than 24)" % (
              what, off.mean(), 100 * (off > 24).mean()))


def scene_light(view, position, focal_point, cone_angle, radius):
    """A positional ParaView light in `view`, in scene coordinates."""
    light = AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Positional"
    light.Position = position
    light.FocalPoint = focal_point
    light.ConeAngle = cone_angle
    light.Radius = radius
    return light


def scene(proxy, technique=None, ball_resolution=32, light_position=LIGHT, ball_center=BALL):
    """A view of the ball over the plane, lit by a spot light only. Returns
    the view, the light and the ball's source."""
    view = CreateView(proxy)
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseLight = 0  # the light kit off: only the spot light below
    # The baselines' blue grey, which ParaView 6 no longer takes by default.
    view.UseColorPaletteForBackground = 0
    view.Background = [0.32, 0.34, 0.43]
    if technique is not None:
        view.ShadowTechnique = technique
    plane = Plane(Origin=[-3, 0, -3], Point1=[3, 0, -3], Point2=[-3, 0, 3])
    ball = Sphere(Center=ball_center, Radius=BALL_RADIUS, ThetaResolution=2 * ball_resolution,
                  PhiResolution=ball_resolution)
    Show(plane, view)
    Show(ball, view)
    light = scene_light(view, light_position, [0.0, 0.0, 0.0], 60,
                        LIGHT_RADIUS if proxy != "RenderView" else 0.0)
    Render(view)  # the first render resets the camera: set it after
    view.CameraPosition = [0, 4.5, 5.5]
    view.CameraFocalPoint = [0, 0.3, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraViewAngle = 30
    Render(view)
    return view, light, ball


def side_lit_scene():
    """The parallel tests' scene: a coarser ball off the centre, lit from
    the side, so that the lower half of the ball casts the tip of its long
    shadow (test_parallel.py)."""
    return scene("ShadowRenderView", ball_resolution=16, light_position=[3.6, 2.4, 0.0],
                 ball_center=[1.2, 1.2, 0.0])


def pixel(view, point):
    """Where the world `point` shows in the view's screenshots: (row, column),
    row 0 at the top."""
    camera = view.GetActiveCamera()
    aspect = SIZE[0] / SIZE[1]
    matrix = camera.GetCompositeProjectionTransformMatrix(aspect, -1, 1)
    m = np.array([[matrix.GetElement(i, j) for j in range(4)] for i in range(4)])
    x, y, _, w = m @ np.array(list(point) + [1.0])
    column = (x / w * 0.5 + 0.5) * SIZE[0]
    row = (1.0 - (y / w * 0.5 + 0.5)) * SIZE[1]
    return int(row), int(column)


def ground_shadow_radius():
    """The hard shadow's radius on the ground (y = 0) of the ball under a
    point light at LIGHT: the cone of rays tangent to the ball."""
    d = LIGHT[1] - BALL[1]
    half_angle = np.arcsin(BALL_RADIUS / d)
    return LIGHT[1] * np.tan(half_angle)


def process_ids_range(source):
    """The range of ranks holding pieces of `source`."""
    # Looked up when called: test_client_server.py imports this module before
    # it connects. Process Ids from 5.13 on (6.0 removed Process Id Scalars).
    if hasattr(pvsimple, "ProcessIds"):
        ids, array = pvsimple.ProcessIds(Input=source), "PointProcessIds"
    else:
        ids, array = pvsimple.ProcessIdScalars(Input=source), "ProcessId"
    ids.UpdatePipeline()
    return ids.PointData[array].GetRange()


# The Light Visibility filter's scene (test_light_visibility.py): a ball
# over the ground under a spherical light.
VISIBILITY_BALL = [0.4, 1.2, 0.0]
VISIBILITY_LIGHT = [1.0, 3.0, 0.5]
VISIBILITY_FOCAL_POINT = [1.0, 0.0, 0.5]


def visibility_scene():
    """The ground, its normal +y (Point1 - Origin x Point2 - Origin), and
    the ball (which ParaView's sphere source splits into one band of
    latitudes a rank)."""
    ground = Plane(Origin=[-3, 0, -3], Point1=[-3, 0, 3], Point2=[3, 0, -3], XResolution=60,
                   YResolution=60)
    ball = Sphere(Center=VISIBILITY_BALL, Radius=BALL_RADIUS, ThetaResolution=128,
                  PhiResolution=64)
    return ground, ball


def visibility_light(view, radius=0.3):
    """A ParaView light in `view` where the parameters put the light."""
    return scene_light(view, VISIBILITY_LIGHT, VISIBILITY_FOCAL_POINT, 90, radius)


def visibility_values(filter, array="LightVisibility"):
    """The filter's points (all ranks' pieces) and `array` on them."""
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy
    data = servermanager.Fetch(filter)
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    found = data.GetPointData().GetArray(array)
    return points, None if found is None else vtk_to_numpy(found).astype(float).reshape(-1)


def check_visibility_as_saved(points, visibility, saved, what):
    """`visibility` at `points` as the values saved in `saved` (.npz) at the
    same points, in whatever order."""
    one = np.load(saved)
    alone = {tuple(p): v for p, v in zip(one["points"].astype(np.float32).tolist(),
                                         one["visibility"])}
    found = [alone.get(tuple(p)) for p in points.astype(np.float32).tolist()]
    missing = sum(v is None for v in found)
    difference = np.abs(visibility - np.array([1e9 if v is None else v for v in found]))
    check(missing == 0 and difference.max() < 1e-6,
          "%s: %d points, %d not in the one-rank result, largest difference %.2g"
          % (what, len(points), missing, difference.max()))
