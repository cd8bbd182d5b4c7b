# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's Light Visibility filter in pvbatch (scripts/paraview.sh runs
it on one MPI rank, then on two). A ball over the ground under a spherical
light, on one rank: the ground's visibility against the closed form, with
the light given as parameters; the same light taken from a view (its
Radius handed over) gives the same values, and a larger Radius a wider
penumbra; the sun over a bare ground at the equator on the equinox gives
12 hours. On two ranks, the ball split between them and the ground on
rank 0 only, the values must be the one rank's.

    PVBATCH test_light_visibility.py PLUGIN FOLDER
        one rank: the checks, and the values saved into FOLDER
    mpirun -np 2 PVBATCH test_light_visibility.py PLUGIN FOLDER
        two ranks: the values against FOLDER's one-rank values
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import CreateView, GroupDatasets, LoadPlugin

import pvshadows
from pvshadows import check

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from shadowtest import ball_light_visibility  # noqa: E402

LoadPlugin(sys.argv[1], remote=True, ns=globals())
folder = sys.argv[2]
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
CENTER, LIGHT = pvshadows.VISIBILITY_BALL, pvshadows.VISIBILITY_LIGHT
FOCAL_POINT = pvshadows.VISIBILITY_FOCAL_POINT
ground, ball = pvshadows.visibility_scene()
values = pvshadows.visibility_values
if ranks > 1:
    low, high = pvshadows.process_ids_range(ball)
    check((low, high) == (0, ranks - 1),
          "%d ranks: the ball's pieces lie on ranks %d to %d" % (ranks, low, high))


# The light as parameters.
given = LightVisibility(Input=ground, Casters=[ball], LightsFrom="Parameters",  # noqa: F821
                        LightType="Point", LightPosition=LIGHT, LightFocalPoint=FOCAL_POINT,
                        LightRadius=0.3, Samples=256)
points, visibility = values(given)
saved = os.path.join(folder, "light-visibility-1ranks.npz")
if ranks == 1:
    expected = ball_light_visibility(points, CENTER, LIGHT, 0.3)
    shadow = expected < 0.98
    error = np.abs(visibility - expected)[shadow]
    rmse = float(np.sqrt(np.mean(error ** 2)))
    check(shadow.sum() > 100 and rmse < 0.015 and error.max() < 0.08,
          "Light Visibility with the light as parameters follows the closed form over %d points "
          "in shadow (RMSE %.4f, largest %.3f)" % (shadow.sum(), rmse, error.max()))
    check(np.all(visibility[expected > 0.999] > 0.99), "points the ball cannot hide see the light")
    np.savez(saved, points=points, visibility=visibility)
else:
    pvshadows.check_visibility_as_saved(points, visibility, saved,
                                        "%d ranks compute what one does" % ranks)
    check((visibility < 0.5).sum() > 50, "%d ranks: the ball's shadow is on the ground (%d points "
          "below half)" % (ranks, (visibility < 0.5).sum()))


# The ground and the ball as one multiblock input: merged into one surface
# that shadows itself, the ground's values those of the ball as a caster.
both = GroupDatasets(Input=[ground, ball])
merged = LightVisibility(Input=both, LightType="Point", LightPosition=LIGHT,  # noqa: F821
                         LightFocalPoint=FOCAL_POINT, LightRadius=0.3, Samples=256)
merged_points, merged_visibility = values(merged)
on_ground = merged_points[:, 1] == 0.0
order = {tuple(p): k for k, p in enumerate(points.tolist())}
same = [order.get(tuple(p)) for p in merged_points[on_ground].tolist()]
check(None not in same and on_ground.sum() == len(points)
      and np.array_equal(merged_visibility[on_ground], visibility[same]),
      "%d rank(s): a multiblock of the ground and the ball, merged, gives the ground the values "
      "the ball gives it as a caster" % ranks)


def penumbra(v):
    return int(((v > 0.02) & (v < 0.98)).sum())


def lights_from_view():
    """The same light taken from a view: ParaView's light, its Radius
    handed over; then made larger."""
    view = CreateView("ShadowRenderView")
    light = pvshadows.visibility_light(view)
    taken = LightVisibility(Input=ground, Casters=[ball], LightsFrom="Lights",  # noqa: F821
                            Lights=list(view.AdditionalLights), Samples=256)
    _, from_view = values(taken)
    check(np.array_equal(from_view, visibility),
          "the view's light gives the parameters' values (largest difference %.2g)"
          % np.abs(from_view - visibility).max())
    # Two changes between updates: ParaView marks the filter dirty on the
    # first only, and the Radius, the second, must still reach it.
    light.Intensity = 0.5
    light.Radius = 0.6
    _, wider = values(taken)
    check(penumbra(wider) > 1.5 * penumbra(from_view),
          "the view's light made larger widens the penumbra: %d points against %d"
          % (penumbra(wider), penumbra(from_view)))


def light_types():
    """A spot light lights only its cone; a directional light of the sun's
    size from straight up puts the ball's shadow under the ball."""
    spot = LightVisibility(Input=ground, Casters=[ball], LightType="Spot",  # noqa: F821
                           LightPosition=LIGHT, LightFocalPoint=FOCAL_POINT, LightConeAngle=20,
                           Samples=16)
    points, irradiance = values(spot, "Irradiance")
    axis = np.array(FOCAL_POINT) - np.array(LIGHT)
    to_point = points - np.array(LIGHT)
    angle = np.degrees(np.arccos(to_point @ axis / np.linalg.norm(to_point, axis=1)
                                 / np.linalg.norm(axis)))
    check(np.all(irradiance[angle > 20.5] == 0) and (irradiance[angle < 19.5] > 0).mean() > 0.8,
          "a spot light of 20 degrees: no irradiance outside its cone, some on %.0f%% of the "
          "points inside" % (100 * (irradiance[angle < 19.5] > 0).mean()))
    sun = LightVisibility(Input=ground, Casters=[ball], LightType="Directional",  # noqa: F821
                          LightPosition=[0, 1, 0], LightFocalPoint=[0, 0, 0], LightRadius=0.27,
                          Samples=16)
    points, visibility = values(sun)
    under = np.hypot(points[:, 0] - CENTER[0], points[:, 2] - CENTER[2])
    check(np.all(visibility[under < 0.45] == 0) and np.all(visibility[under > 0.55] == 1),
          "a directional light from straight up: dark under the ball, lit beyond it")


def sun_hours():
    """The sun at the equator on the equinox over a bare ground whose up is +y."""
    sun = LightVisibility(Input=ground, LightsFrom="None (sun only)", SunHours=1,  # noqa: F821
                          SunLatitude=0.0, SunDayOfYear=80, SunUp=[0, 1, 0],
                          SunNorth=[0, 0, -1], Samples=16)
    _, hours = values(sun, "SunHours")
    check(hours is not None and abs(hours.mean() - 12.0) < 0.3 and hours.std() < 1e-6,
          "the sun at the equator on the equinox: %.2f hours on every point of a bare ground"
          % (-1 if hours is None else hours.mean()))


if ranks == 1:
    lights_from_view()
    light_types()
    sun_hours()
pvshadows.finish()
