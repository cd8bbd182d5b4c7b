# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Shadows as data (vtkLightVisibilityFilter): each light's visible fraction
and the irradiance it brings on a mesh's points and cells, against closed
forms: a ball over a ground plane under spherical lights (the share of the
light's disc the ball's disc leaves open, as test_truth.py checks the
truth), a wall's shadow under a small sun, a bare point's irradiance under
VTK's attenuation and spot cone; the back of a surface; the sun over a day
(vtkSolarPosition against published equinoxes and solstices, 12 hours at
the equator on the equinox, a wall's north and south sides in winter); and
bad input."""
import json
import math
import os
import tempfile

import numpy as np
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCellCenters, vtkReverseSense
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkLight, vtkLightCollection
from vtkmodules.util.numpy_support import vtk_to_numpy

from vtksoftshadows import vtkLightVisibilityFilter, vtkShadowLightSize, vtkSolarPosition

import shadowtest as st


def ground(size=6.0, resolution=60, flip=False):
    plane = vtkPlaneSource()
    plane.SetOrigin(-size / 2, 0, -size / 2)
    plane.SetPoint1(-size / 2, 0, size / 2)  # normal +y (point1 x point2)
    plane.SetPoint2(size / 2, 0, -size / 2)
    if flip:
        plane.SetPoint1(size / 2, 0, -size / 2)
        plane.SetPoint2(-size / 2, 0, size / 2)
    plane.SetResolution(resolution, resolution)
    plane.Update()
    return plane


def ball(center, radius=st.BALL_RADIUS):
    sphere = vtkSphereSource()
    sphere.SetCenter(*center)
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(128)
    sphere.SetPhiResolution(64)
    sphere.Update()
    return sphere


def lights(*items):
    collection = vtkLightCollection()
    for light in items:
        collection.AddItem(light)
    return collection


def positional(position, radius, cone=None, intensity=1.0):
    light = vtkLight()
    light.SetPositional(True)
    light.SetPosition(*position)
    light.SetFocalPoint(position[0], 0, position[2])
    light.SetConeAngle(cone if cone is not None else 180.0)
    light.SetIntensity(intensity)
    vtkShadowLightSize.SetRadius(radius, light)
    return light


def run(receiver, collection, casters=(), samples=256, cells=False):
    f = vtkLightVisibilityFilter()
    f.SetInputConnection(receiver.GetOutputPort())
    for caster in casters:
        f.AddCasterConnection(caster.GetOutputPort())
    f.SetLights(collection)
    f.SetSamples(samples)
    if cells:
        f.CellVisibilityOn()
    f.Update()
    return f, f.GetOutput()


def array(data, name, cells=False):
    attributes = data.GetCellData() if cells else data.GetPointData()
    values = attributes.GetArray(name)
    return None if values is None else vtk_to_numpy(values)


# A ball over the ground under a point light of two sizes, and the two as
# one collection: one component a light.
center = (0.3, 1.5, -0.2)
floor, sphere = ground(), ball(center)
small = positional((0.0, 4.0, 0.0), 0.15)
large = positional((1.0, 4.0, 0.5), 0.6)
f, out = run(floor, lights(small, large), casters=[sphere])
points = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
visibility = array(out, "LightVisibility")
st.check(visibility is not None and visibility.shape == (out.GetNumberOfPoints(), 2),
         "one LightVisibility component a light on every point (%s)"
         % (None if visibility is None else visibility.shape,))
widest = []
for k, (light, radius) in enumerate([(small, 0.15), (large, 0.6)]):
    expected = st.ball_light_visibility(points, center, light.GetPosition(), radius)
    penumbra = (expected > 0.02) & (expected < 0.98)
    widest.append(penumbra.sum())
    # Over the points in shadow, where a wrong sampling would show: 256
    # stratified rays err by up to about 16 / 256 where an edge crosses.
    error = np.abs(visibility[:, k] - expected)[expected < 0.98]
    rmse = float(np.sqrt(np.mean(error ** 2)))
    print("light of radius %.2f: %d points in shadow, %d in penumbra, RMSE %.4f there, "
          "largest error %.3f" % (radius, len(error), penumbra.sum(), rmse, error.max()))
    st.check(len(error) > 100 and rmse < 0.015 and error.max() < 0.08,
             "radius %.2f: the visibility follows the closed form (RMSE %.4f, largest %.3f)"
             % (radius, rmse, error.max()))
    st.check(np.all(visibility[expected > 0.999, k] > 0.99),
             "radius %.2f: points the ball cannot hide see all of the light" % radius)
st.check(widest[1] > 2 * widest[0],
         "the larger light's penumbra covers more points (%d against %d)" % tuple(widest[::-1]))

# The receiver casts onto itself: the ball and the ground as one mesh, no
# casters, give the ground the same values.
both = vtkAppendPolyData()
both.AddInputConnection(floor.GetOutputPort())
both.AddInputConnection(sphere.GetOutputPort())
_, merged = run(both, lights(small, large))
same = array(merged, "LightVisibility")[:len(points)]
st.check(np.array_equal(same, visibility),
         "a receiver shadows itself as a caster would (%d values differ)"
         % int(np.sum(same != visibility)))

# Irradiance without an occluder: intensity x cos x VTK's attenuation, and
# a spot light's cone (exponent inside, nothing outside).
lamp = positional((0.0, 2.0, 0.0), 0.0, intensity=0.8)
lamp.SetAttenuationValues(1.0, 0.5, 0.25)
spot = positional((0.0, 2.0, 0.0), 0.0, cone=30.0, intensity=1.0)
spot.SetExponent(2.0)
_, lit = run(floor, lights(lamp, spot), samples=1)
points = vtk_to_numpy(lit.GetPoints().GetData()).astype(float)
to_light = np.array([0.0, 2.0, 0.0]) - points
distance = np.linalg.norm(to_light, axis=-1)
cosine = to_light[:, 1] / distance
cone_dot = cosine  # the spot points straight down
expected = 0.8 * cosine / (1.0 + 0.5 * distance + 0.25 * distance ** 2) + np.where(
    cone_dot >= math.cos(math.radians(30.0)), cosine * cone_dot ** 2, 0.0)
irradiance = array(lit, "Irradiance")
error = float(np.max(np.abs(irradiance - expected)))
st.check(error < 1e-5, "irradiance is visibility x cos x intensity x VTK's falloff (largest "
         "error %.2g)" % error)
lamp.SwitchOff()
_, off = run(floor, lights(lamp), samples=1)
st.check(np.all(array(off, "Irradiance") == 0) and np.all(array(off, "LightVisibility") == 1),
         "a switched-off light brings no irradiance but is still seen")

# The back of a surface sees nothing of a light in front of its normal's
# opposite side.
_, back = run(ground(flip=True), lights(positional((0.0, 2.0, 0.0), 0.2)))
st.check(np.all(array(back, "LightVisibility") == 0) and np.all(array(back, "Irradiance") == 0),
         "points whose normal faces away from the light read 0")

# A wall under a small sun: the ground beyond it dark to where its top's
# shadow reaches, lit elsewhere; cells as well as points.
wall = vtkCubeSource()
wall.SetBounds(-0.05, 0.05, 0.0, 1.0, -2.0, 2.0)
sun = vtkLight()
sun.SetPositional(False)
sun.SetPosition(1.0, 1.0, 0.0)  # 45 degrees from the +x side
sun.SetFocalPoint(0.0, 0.0, 0.0)
vtkShadowLightSize.SetRadius(0.27, sun)
_, shade = run(ground(resolution=120), lights(sun), casters=[wall], samples=64, cells=True)
for cells in (False, True):
    if cells:
        centers = vtkCellCenters()
        centers.SetInputData(shade)
        centers.Update()
        where = vtk_to_numpy(centers.GetOutput().GetPoints().GetData()).astype(float)
    else:
        where = vtk_to_numpy(shade.GetPoints().GetData()).astype(float)
    seen = array(shade, "LightVisibility", cells)
    kind = "cells" if cells else "points"
    st.check(seen is not None and len(seen) == len(where), "LightVisibility on the %s" % kind)
    seen = seen.reshape(-1)
    x, z = where[:, 0], where[:, 2]
    inner = np.abs(z) < 1.8
    # The wall's top (height 1) falls 1 unit beyond its far face; the sun's
    # 0.27 degrees widen that edge by under 0.01.
    dark = inner & (x < -0.07) & (x > -0.93)
    bright = (x > 0.07) | (x < -1.1) | (np.abs(z) > 2.3)
    st.check(np.all(seen[dark] == 0) and np.all(seen[bright] == 1),
             "%s: dark behind the wall to where its top's shadow reaches, lit elsewhere "
             "(%d dark, %d lit wrong)" % (kind, int(np.sum(seen[dark] != 0)),
                                         int(np.sum(seen[bright] != 1))))

# The sun's position (vtkSolarPosition) against the U.S. Naval Observatory's
# 2026 equinoxes and solstices (day of year, hour UT, declination): a mean
# year's series, within half a degree where the declination moves fastest.
for name, day, hour, declination, tolerance in [
        ("March equinox", 79, 14 + 46 / 60, 0.0, 0.5), ("June solstice", 172, 8.4, 23.436, 0.03),
        ("September equinox", 266, 5 / 60, 0.0, 0.5),
        ("December solstice", 355, 20 + 50 / 60, -23.436, 0.03)]:
    found = vtkSolarPosition.GetDeclination(day, hour)
    print("%s 2026: declination %.3f, published %.3f" % (name, found, declination))
    st.check(abs(found - declination) < tolerance, "%s: the sun's declination within %.2f degrees "
             "(%.3f)" % (name, tolerance, found - declination))
towards = [0.0, 0.0, 0.0]
vtkSolarPosition.GetDirection(52.0, 172, 12.0, towards)
elevation = math.degrees(math.asin(towards[2]))
noon = 90.0 - 52.0 + vtkSolarPosition.GetDeclination(172, 12.0)
st.check(abs(elevation - noon) < 1e-9 and abs(towards[0]) < 1e-12 and towards[1] < 0,
         "at 52 degrees north the solstice's noon sun stands due south at 90 - 52 + declination "
         "(%.3f)" % elevation)


def patch(x, y, size=0.2):
    """A small horizontal square (normal +z) centred at (x, y, 0)."""
    square = vtkPlaneSource()
    square.SetOrigin(x - size / 2, y - size / 2, 0.0)
    square.SetPoint1(x + size / 2, y - size / 2, 0.0)
    square.SetPoint2(x - size / 2, y + size / 2, 0.0)
    return square


def sun_run(receiver, casters=(), latitude=0.0, day=80, directions=()):
    f = vtkLightVisibilityFilter()
    f.SetInputConnection(receiver.GetOutputPort())
    for caster in casters:
        f.AddCasterConnection(caster.GetOutputPort())
    f.SunHoursOn()
    f.SetSunLatitude(latitude)
    f.SetSunDayOfYear(day)
    for direction in directions:
        f.AddSunDirection(*direction)
    f.SetSamples(16)
    f.Update()
    return f.GetOutput()


# A bare horizontal plane at the equator on the equinox: 12 hours of sun,
# all of the day's daylight (steps of a quarter hour).
out = sun_run(patch(0.0, 0.0))
hours, fraction = array(out, "SunHours"), array(out, "SunFraction")
st.check(hours is not None and np.all(np.abs(hours - 12.0) <= 0.25) and np.all(fraction == 1.0),
         "the equator on the equinox: 12 hours of sun on a bare plane (%s)"
         % (None if hours is None else hours[:1],))
st.check(out.GetPointData().GetArray("LightVisibility") is None,
         "the sun alone: no LightVisibility")

# An east-west wall 10 high at 52 degrees north on the December solstice,
# whose sun stays south: the ground just north of it has none, the ground
# south of it has the whole day, 2 acos(-tan(latitude) tan(declination)) / 15
# hours long.
wall = vtkCubeSource()
wall.SetBounds(-5.0, 5.0, -0.1, 0.1, 0.0, 10.0)
south, north = patch(0.0, -3.0), patch(0.0, 1.0)
both = vtkAppendPolyData()
both.AddInputConnection(south.GetOutputPort())
both.AddInputConnection(north.GetOutputPort())
out = sun_run(both, casters=[wall], latitude=52.0, day=355)
hours, fraction = array(out, "SunHours"), array(out, "SunFraction")
declination = math.radians(vtkSolarPosition.GetDeclination(355, 12.0))
day = 2.0 * math.degrees(math.acos(-math.tan(math.radians(52.0)) * math.tan(declination))) / 15.0
print("52 N, 21 December: %.2f hours of daylight; south of the wall %s, north %s"
      % (day, hours[:4], hours[4:]))
st.check(np.all(np.abs(hours[:4] - day) <= 0.25) and np.all(fraction[:4] == 1.0),
         "south of the wall: the whole day's %.2f hours of sun" % day)
st.check(np.all(hours[4:] == 0.0) and np.all(fraction[4:] == 0.0),
         "north of the wall: no sun all day")

# Given directions and their hours instead of a day's: the wall hides the
# one from the north for the ground north of it, not the one overhead.
out = sun_run(north, casters=[wall],
              directions=[(0.0, -1.0, 0.2, 2.0), (0.0, 0.0, 1.0, 3.0)])
st.check(np.allclose(array(out, "SunHours"), 3.0) and np.allclose(array(out, "SunFraction"), 0.6),
         "given sun directions: the wall hides 2 of 5 hours (%s)" % array(out, "SunHours"))

# `softshadows visibility`: the ball scene's faces in the world, written as
# VTP, against the same closed form on the ground; with the sun at the
# equator on the equinox, 12 hours on the ground beside the ball's path.
scene = st.ball_scene(height=1.5, light_radius=0.4)
scene["actors"][0]["params"]["resolution"] = 60
with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "ball.json")
    written = os.path.join(folder, "ball.vtp")
    with open(path, "w") as stream:
        json.dump(scene, stream)
    st.run(["visibility", path, "--samples", "256", "--output", written, "--sun-latitude", "0",
            "--quiet"])
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(written)
    reader.Update()
    out = reader.GetOutput()
points = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
on_ground = np.abs(points[:, 1]) < 1e-6
light = scene["lights"][0]
expected = st.ball_light_visibility(points[on_ground], scene["actors"][1]["position"],
                               light["position"], light["radius"])
seen = array(out, "LightVisibility").reshape(-1)[on_ground]
error = np.abs(seen - expected)[expected < 0.98]
rmse = float(np.sqrt(np.mean(error ** 2)))
print("softshadows visibility: %d ground points, %d in shadow, RMSE %.4f there"
      % (on_ground.sum(), len(error), rmse))
st.check(len(error) > 100 and rmse < 0.015 and error.max() < 0.08,
         "softshadows visibility follows the closed form on the ground (RMSE %.4f)" % rmse)
# Against the renderer's truth (`softshadows truth`, the same scene and 256
# rays): each ground point where the camera sees it, at its nearest pixel.
scene["size"] = [480, 360]
truth, _, measured = st.truth(scene)
row, column, inside = st.camera_pixels(scene["camera"], scene["size"], points[on_ground])
row, column = row[inside], column[inside]
compared = measured[row, column]
difference = (seen[inside] - truth[row, column])[compared]
rmse = float(np.sqrt(np.mean(difference ** 2)))
print("against softshadows truth: %d ground points compared, RMSE %.4f, largest %.3f"
      % (len(difference), rmse, np.abs(difference).max()))
st.check(len(difference) > 1000 and rmse < 0.01 and np.abs(difference).max() < 0.1,
         "the visibility agrees with softshadows truth where the camera sees the ground "
         "(RMSE %.4f)" % rmse)

hours = array(out, "SunHours")[on_ground]
# The equinox's sun crosses the sky from east (+x) to west in the plane
# square to north (-z): the ball's shadow sweeps along x, within |z| < 0.5.
away = np.abs(points[on_ground][:, 2]) > 1.0
st.check(np.all(np.abs(hours[away] - 12.0) <= 0.25),
         "softshadows visibility --sun-latitude 0: 12 hours on the open ground (%s)"
         % np.unique(hours[away])[:4])
# A translucent ball receives but casts nothing, as in the renderer.
scene["actors"][1]["opacity"] = 0.5
with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "ball.json")
    written = os.path.join(folder, "ball.vtp")
    with open(path, "w") as stream:
        json.dump(scene, stream)
    st.run(["visibility", path, "--samples", "4", "--output", written, "--quiet"])
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(written)
    reader.Update()
    glass = reader.GetOutput()
ground = np.abs(vtk_to_numpy(glass.GetPoints().GetData())[:, 1]) < 1e-6
st.check(glass.GetNumberOfPoints() == out.GetNumberOfPoints() and
         np.all(array(glass, "LightVisibility").reshape(-1)[ground] == 1),
         "softshadows visibility: a translucent ball is on the mesh but shadows nothing")
demo = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Examples", "Scenes",
                    "demo.json")
bad = st.run(["visibility", demo, "--sun-day", "80"], check=False)
far = st.run(["visibility", demo, "--sun-latitude", "1e999"], check=False)
st.check(far.returncode == 2 and far.stderr.count("\n") == 1,
         "--sun-latitude 1e999: one line, exit 2 (%r)" % far.stderr)
st.check(bad.returncode == 2 and bad.stderr.count("\n") == 1 and "--sun-latitude" in bad.stderr,
         "--sun-day without --sun-latitude: one line, exit 2 (%r)" % bad.stderr)

# Bad input: one clear error each, no output arrays.
errors = []


def guarded(f):
    f.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
    f.GetExecutive().AddObserver(vtkCommand.ErrorEvent,
                                 lambda caller, event: errors.append(event))
    return f


none = guarded(vtkLightVisibilityFilter())
none.SetInputConnection(floor.GetOutputPort())
none.Update()
st.check(len(errors) >= 1 and none.GetOutput().GetPointData().GetArray("LightVisibility") is None,
         "no lights: an error and no arrays")
errors.clear()
broken = vtkPolyData()
broken.DeepCopy(floor.GetOutput())
broken.GetPoints().SetPoint(5, float("nan"), 0.0, 0.0)
nan = guarded(vtkLightVisibilityFilter())
nan.SetInputData(broken)
nan.SetLights(lights(small))
nan.Update()
st.check(len(errors) >= 1 and nan.GetOutput().GetPointData().GetArray("LightVisibility") is None,
         "a NaN receiver point: an error and no arrays")
errors.clear()
skew = guarded(vtkLightVisibilityFilter())
skew.SetInputConnection(floor.GetOutputPort())
skew.SunHoursOn()
skew.SetSunNorth(0.0, 0.0, 2.0)
skew.Update()
st.check(len(errors) >= 1 and skew.GetOutput().GetPointData().GetArray("SunHours") is None,
         "north along up: an error and no arrays")

# Values past what rays can carry: each an error, never Embree's abort.
for label, change in [
        ("a NaN sun radius", lambda f: (f.SunHoursOn(), f.SetSunRadius(float("nan")))),
        ("a NaN sun latitude", lambda f: (f.SunHoursOn(), f.SetSunLatitude(float("nan")))),
        ("a light at NaN", lambda f: f.SetLights(lights(positional((float("nan"), 2, 0), 0.1)))),
        ("a receiver point beyond float range",
         lambda f: f.SetInputData(far))]:
    errors.clear()
    far = vtkPolyData()
    far.DeepCopy(floor.GetOutput())
    far.GetPoints().SetPoint(3, 1e39, 0.0, 0.0)
    f = guarded(vtkLightVisibilityFilter())
    f.SetInputConnection(floor.GetOutputPort())
    f.SetLights(lights(small))
    change(f)
    f.Update()
    st.check(len(errors) >= 1 and f.GetOutput().GetPointData().GetArray("LightVisibility") is None,
             "%s: an error and no arrays" % label)

# Where the sun never rises (80 degrees north in December) the arrays are
# there, all zero.
polar = sun_run(patch(0.0, 0.0), latitude=80.0, day=355)
st.check(array(polar, "SunHours") is not None and np.all(array(polar, "SunHours") == 0)
         and np.all(array(polar, "SunFraction") == 0), "polar night: SunHours and SunFraction 0")

# A receiver that does not cast (translucent, as in VTK's shadows): the
# ball and ground as one receiver leave the ground lit.
together = vtkAppendPolyData()
together.AddInputConnection(floor.GetOutputPort())
together.AddInputConnection(sphere.GetOutputPort())
clear = vtkLightVisibilityFilter()
clear.SetInputConnection(together.GetOutputPort())
clear.SetLights(lights(small))
clear.SetSamples(4)
clear.ReceiverCastsOff()
clear.Update()
ground_points = floor.GetOutput().GetNumberOfPoints()
st.check(np.all(array(clear.GetOutput(), "LightVisibility")[:ground_points] == 1),
         "ReceiverCasts off: the receiver shadows nothing, itself included")

# TwoSided: a ball whose normals point inwards (as VTK's isosurfaces of
# fields negative inside) reads 0 everywhere one-sided, and with two sides
# exactly what the outward ball reads.
inward = vtkReverseSense()
inward.SetInputConnection(sphere.GetOutputPort())
inward.ReverseCellsOn()
inward.ReverseNormalsOn()
readings = []
for source, two_sided in [(sphere, False), (inward, False), (inward, True)]:
    f = vtkLightVisibilityFilter()
    f.SetInputConnection(source.GetOutputPort())
    f.SetLights(lights(small))
    f.SetSamples(16)
    f.SetTwoSided(two_sided)
    f.Update()
    readings.append(array(f.GetOutput(), "LightVisibility").reshape(-1))
# (Except at the terminator, where the light's centre is below a point's
# tangent plane but part of its sphere above: the side facing the centre
# is the inner one there.)
ball_points = vtk_to_numpy(sphere.GetOutput().GetPoints().GetData()).astype(float)
outward = vtk_to_numpy(sphere.GetOutput().GetPointData().GetNormals())
towards = np.asarray(small.GetPosition()) - ball_points
facing = np.sum(outward * towards, axis=1) / np.linalg.norm(towards, axis=1)
away_from_terminator = np.abs(facing) > 0.1
st.check(readings[0].max() == 1.0 and readings[1].max() == 0.0 and
         np.array_equal(readings[2][away_from_terminator], readings[0][away_from_terminator]),
         "TwoSided: an inward ball reads 0 one-sided, the outward ball's values with two sides "
         "(%d of %d points compared)" % (away_from_terminator.sum(), len(facing)))

# Resizing a light casts again: the size lives in its information.
resized = vtkLightVisibilityFilter()
resized.SetInputConnection(floor.GetOutputPort())
resized.AddCasterConnection(sphere.GetOutputPort())
resized.SetLights(lights(small))
resized.SetSamples(16)
resized.Update()
before = np.array(array(resized.GetOutput(), "LightVisibility"))
vtkShadowLightSize.SetRadius(0.6, small)
resized.Update()
after = array(resized.GetOutput(), "LightVisibility")
vtkShadowLightSize.SetRadius(0.15, small)
st.check(np.sum((after > 0.02) & (after < 0.98)) > 2 * np.sum((before > 0.02) & (before < 0.98)),
         "resizing a light updates the filter's output")

# Progress reaches the end.
progress = []
f = vtkLightVisibilityFilter()
f.SetInputConnection(floor.GetOutputPort())
f.SetLights(lights(small))
f.SetSamples(4)
f.AddObserver(vtkCommand.ProgressEvent,
              lambda caller, event: progress.append(caller.GetProgress()))
f.Update()
st.check(len(progress) > 10 and progress[-1] == 1.0,
         "progress is reported in bands up to 1 (%d events)" % len(progress))
print("ok")
