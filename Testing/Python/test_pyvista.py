# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The PyVista integration (vtksoftshadows.pyvista): the ball scene drawn by
a PyVista plotter under a pyvista.Light spot light of radius 0.3, its shadow
where geometry puts it and soft; after disable_soft_shadows() the very
picture of a plotter that never enabled them; techniques and parameters
refused by name; and PyVista's other passes (SSAO, depth of field, eye dome
lighting, blurring, FXAA, SSAA, its own shadows) combined or refused with a
clear error, never drawn wrong in silence.

Needs PyVista (Debian 13's python3-pyvista and later): without it, it says so
and exits with 77, which CTest counts as skipped."""
import sys
import warnings

import numpy as np

try:
    import pyvista as pv
except ImportError:
    print("SKIP: PyVista is not installed (python3-pyvista, Debian 13 and later)")
    sys.exit(77)

from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
from vtksoftshadows import vtkShadowTechniqueCatalog, vtkSoftShadowPass
from vtksoftshadows.pyvista import (SoftShadowsCompatibilityError, disable_soft_shadows,
                                    enable_soft_shadows, get_soft_shadow_pass,
                                    light_visibility)

import shadowtest as st

pv.OFF_SCREEN = True
SIZE = (320, 240)
RADIUS = 0.3
SCENE = st.ball_scene(height=1.0, light_radius=RADIUS, size=SIZE)
VISIBLE, HIDDEN, EDGE = st.expected_hard_shadow(SCENE)  # bottom row first
GROUND = st.interior(VISIBLE, 2)  # away from the ball's outline and the floor's edge
UMBRA = GROUND & HIDDEN & (EDGE > 6)
LIT = GROUND & ~HIDDEN & (EDGE > 20)
RADIUS_KEY = vtkSoftShadowPass.RADIUS()

# VTK's errors and warnings, to be checked for.
messages = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(messages)


taken = [0]


def take_messages():
    """What VTK said since the last call."""
    text = messages.GetOutput()
    new, taken[0] = text[taken[0]:], len(text)
    return new


def scene(lighting="none", shape=(1, 1), poly=False):
    """The ball scene of shadowtest.ball_scene() in a PyVista plotter, in
    every subplot; returns (plotter, its spot lights). With `poly`, the
    meshes are vtkActors with vtkPolyDataMapper rather than add_mesh()'s
    vtkDataSetMapper."""
    pl = pv.Plotter(off_screen=True, window_size=[SIZE[0] * shape[1], SIZE[1] * shape[0]],
                    lighting=lighting, shape=shape)
    pl.disable_anti_aliasing()  # the theme's MSAA, unless a check asks for it
    lights = []
    for row in range(shape[0]):
        for column in range(shape[1]):
            pl.subplot(row, column)
            floor = pv.Plane(center=(0, 0, 0), direction=(0, 1, 0), i_size=6, j_size=6,
                             i_resolution=8, j_resolution=8)
            ball = pv.Sphere(radius=st.BALL_RADIUS, center=(0, 1, 0), theta_resolution=64,
                             phi_resolution=32)
            for mesh, color in ((floor, (1.0, 1.0, 1.0)), (ball, (0.9, 0.3, 0.25))):
                if poly:
                    mapper = vtkPolyDataMapper()
                    mapper.SetInputData(mesh)
                    actor = vtkActor()
                    actor.SetMapper(mapper)
                    actor.GetProperty().SetColor(*color)
                    pl.add_actor(actor)
                else:
                    pl.add_mesh(mesh, color=color)  # floats: PyVista reads int tuples as 0-255
            if lighting == "none":
                light = pv.Light(position=tuple(st.LIGHT), focal_point=(0, 0, 0), positional=True,
                                 cone_angle=45, light_type="scene light")
                pl.add_light(light, only_active=True)  # one light a subplot
                lights.append(light)
            pl.camera_position = [tuple(st.CAMERA["position"]), tuple(st.CAMERA["focal_point"]),
                                  tuple(st.CAMERA["view_up"])]
            pl.camera.view_angle = st.CAMERA["view_angle"]
    return pl, lights


def grab(pl, twice=False, column=0):
    """The plotter's picture (of subplot `column`) after a render, float RGB,
    bottom row first. (Before show(), PyVista renders only in its first
    screenshot; depth of field needs two frames off screen, as PyVista's
    show() knows.)"""
    pl.screenshot(return_img=True)
    pl.render()
    if twice:
        pl.render()
    image = np.asarray(pl.screenshot(return_img=True))[::-1, :, :3].astype(float)
    return image[:, column * SIZE[0]:(column + 1) * SIZE[0]]


def visibility(shadowed, plain):
    """Shadowed over plain brightness of the ground: the light's visibility
    (the floor is lit by the spot light alone)."""
    return shadowed.sum(axis=2) / np.maximum(plain.sum(axis=2), 1.0)


def check_shadow(name, v, umbra_at_most=0.15, lit_at_least=0.9):
    umbra = float(np.median(v[UMBRA]))
    lit = float(np.percentile(v[LIT], 5))
    st.check(umbra < umbra_at_most and lit > lit_at_least,
             "%s: the ball's umbra is dark (median %.3f) and open ground lit (5th percentile %.3f)"
             % (name, umbra, lit))


def penumbra(v):
    return int(((v > 0.1) & (v < 0.9) & GROUND).sum())


def chain(renderer):
    """Class names of every pass the renderer draws through."""
    names, stack, seen = [], [renderer.GetPass()], set()
    while stack:
        current = stack.pop()
        if current is None or current.__this__ in seen:
            continue
        seen.add(current.__this__)
        names.append(current.GetClassName())
        if hasattr(current, "GetDelegatePass"):
            stack.append(current.GetDelegatePass())
        if hasattr(current, "GetPasses") and current.GetPasses() is not None:
            passes = current.GetPasses()
            stack.extend(passes.GetItemAsObject(i) for i in range(passes.GetNumberOfItems()))
    return names


def refused(error, words, call):
    """Whether call() raises `error` with each of `words` in its message."""
    try:
        call()
    except error as raised:
        text = str(raised)
        return all(w in text for w in words), text
    return False, "(nothing raised)"


print("PyVista %s, VTK %s" % (pv.__version__, ".".join(map(str, pv.vtk_version_info))))

# The reference: the same scene in a plotter that never enables soft shadows.
reference, _ = scene()
plain = grab(reference)
st.check(GROUND.sum() > 10000 and UMBRA.sum() > 300 and LIT.sum() > 2000,
         "the scene's ground, umbra and lit ground cover %d, %d and %d pixels"
         % (GROUND.sum(), UMBRA.sum(), LIT.sum()))
st.check(float(np.median(plain.sum(axis=2)[GROUND])) > 150,
         "without shadows the spot light lights the floor")

# Soft shadows: where the ball hides the light, with a penumbra.
pl, (light,) = scene()
before = grab(pl)
st.check(np.array_equal(before, plain), "two plotters of the scene draw the same picture")
contact = enable_soft_shadows(pl, "contact", light_radius=RADIUS, map_size=512)
st.check(contact.IsA("vtkContactHardeningShadowPass") and contact.GetMapSize() == 512,
         "enable_soft_shadows returns the contact pass, map_size set")
st.check(vtkSoftShadowPass.GetRadius(light) == RADIUS,
         "the pyvista.Light without a size gets light_radius")
st.check(get_soft_shadow_pass(pl) is contact, "get_soft_shadow_pass() is that pass")
soft = visibility(grab(pl), plain)
st.check(contact.GetNumberOfShadowedLights() == 1, "one shadowed light")
check_shadow("contact", soft)

# A second call replaces the first: a hard shadow of the light without size.
hard_pass = enable_soft_shadows(pl, "hard")
st.check(hard_pass.IsA("vtkHardShadowPass")
         and "vtkContactHardeningShadowPass" not in chain(pl.renderer),
         "enabling again puts the new pass in the old one's place: %s" % chain(pl.renderer))
st.check(not light.GetInformation().Has(RADIUS_KEY),
         "without light_radius the size the first call gave is taken back")
hard = visibility(grab(pl), plain)
check_shadow("hard", hard)
st.check(penumbra(soft) > 2 * penumbra(hard),
         "contact is soft: %d penumbra pixels, hard %d" % (penumbra(soft), penumbra(hard)))

# Off: the picture of a plotter that never had them, the light as it was.
disable_soft_shadows(pl)
st.check(pl.renderer.GetPass() is None and get_soft_shadow_pass(pl) is None,
         "after disable the renderer draws without a pass again, as PyVista set it")
after = grab(pl)
st.check(np.array_equal(after, plain), "after disable the picture is the never-enabled one "
         "(largest difference %g)" % np.abs(after - plain).max())
disable_soft_shadows(pl)
st.check(pl.renderer.GetPass() is None and get_soft_shadow_pass(pl) is None
         and np.array_equal(grab(pl), plain), "disable when not enabled changes nothing")

# On and off again and again (the toggling of pyvista#8685): each time the
# same pictures.
for cycle in range(3):
    enable_soft_shadows(pl, "contact", light_radius=RADIUS, map_size=512)
    again = visibility(grab(pl), plain)
    disable_soft_shadows(pl)
    st.check(np.abs(again - soft).max() < 1e-6 and np.array_equal(grab(pl), plain),
             "cycle %d: the same shadowed picture, then the plain one" % cycle)

# Techniques, variants and parameters: refused by name, nothing changed.
catalog = vtkShadowTechniqueCatalog
cases = [
    (ValueError, ["nope", "contact", "aliasfree"], lambda: enable_soft_shadows(pl, "nope")),
    (ValueError, ["enable_shadows"], lambda: enable_soft_shadows(pl, "vtk")),
    (ValueError, ["nope", "multipass"], lambda: enable_soft_shadows(pl, "contact:nope")),
    (ValueError, ["no variants"], lambda: enable_soft_shadows(pl, "smoothies:soft")),
    (ValueError, ["foo", "pass_limit"], lambda: enable_soft_shadows(pl, "contact", foo=1)),
    (ValueError, ["pcf_radius", "contact"],
     lambda: enable_soft_shadows(pl, "contact", pcf_radius=2)),
    (ValueError, ["contact.dp", "from 0 to 16"],
     lambda: enable_soft_shadows(pl, "contact", dp=100)),
    (ValueError, ["pass_limit", "whole"], lambda: enable_soft_shadows(pl, "contact:multipass",
                                                                     pass_limit=2.5)),
    (ValueError, ["dilation"], lambda: enable_soft_shadows(pl, "contact", dilation="yes")),
    (ValueError, ["light_scale"],
     lambda: enable_soft_shadows(pl, "aliasfree", light_scale=(1, 2))),
    (ValueError, ["map_size"], lambda: enable_soft_shadows(pl, "hard", map_size=8)),
    (ValueError, ["light_radius"], lambda: enable_soft_shadows(pl, "hard", light_radius=-1)),
    (ValueError, ["light_radius"],
     lambda: enable_soft_shadows(pl, "hard", light_radius=float("nan"))),
]
for error, words, call in cases:
    ok, text = refused(error, words, call)
    st.check(ok, "refused, naming %s: %s" % (words, text))
st.check(pl.renderer.GetPass() is None and not light.GetInformation().Has(RADIUS_KEY)
         and get_soft_shadow_pass(pl) is None, "refusals leave the plotter as it was")
q, _ = scene(poly=True)  # aliasfree reads vtkPolyDataMapper actors (below)
aliasfree = enable_soft_shadows(q, "aliasfree:hard", light_samples=64, light_scale=(1, 2, 1),
                                fit_to_view_samples=False, map_size=256)
t = catalog.FindTechnique("aliasfree")
read = [0.0, 0.0, 0.0]
catalog.GetParameter(aliasfree, t, catalog.FindParameter(t, "light_scale"), read)
st.check(aliasfree.GetNumberOfLightSamples() == 64 and read == [1.0, 2.0, 1.0]
         and not aliasfree.GetFitToViewSamples() and aliasfree.GetMapSize() == 256,
         "parameters reach the pass through the catalog (light_samples, light_scale, a boolean)")
disable_soft_shadows(q)
q.close()

# PyVista's other passes. Each: the picture with the pass alone, then with
# contact's soft shadows too (dark where the ball hides the light, against
# that picture, and as soft as without the pass: far more penumbra pixels
# than hard's under the same pass), then without them again: the first
# picture.
effects = [
    ("SSAO", lambda p: p.enable_ssao()),
    ("eye dome lighting", lambda p: p.enable_eye_dome_lighting()),
    ("blurring", lambda p: p.add_blurring()),
    ("FXAA", lambda p: p.enable_anti_aliasing("fxaa")),
    ("MSAA", lambda p: p.enable_anti_aliasing("msaa")),
]
for name, turn_on in effects:
    p, _ = scene()
    turn_on(p)
    alone = grab(p)
    enable_soft_shadows(p, "hard")
    v_hard = visibility(grab(p), alone)
    enable_soft_shadows(p, "contact", light_radius=RADIUS, map_size=512)
    v = visibility(grab(p), alone)
    check_shadow("contact with %s" % name, v, umbra_at_most=0.2, lit_at_least=0.85)
    st.check(penumbra(v) > 1.5 * penumbra(v_hard) and penumbra(v) > 0.5 * penumbra(soft),
             "contact with %s stays soft: %d penumbra pixels, hard %d, contact alone %d"
             % (name, penumbra(v), penumbra(v_hard), penumbra(soft)))
    if name == "FXAA":
        st.check("vtkOpenGLFXAAPass" in chain(p.renderer),
                 "FXAA, which VTK skips while the renderer has a pass, is a vtkOpenGLFXAAPass "
                 "in the chain: %s" % chain(p.renderer))
    disable_soft_shadows(p)
    back = grab(p)
    st.check(np.array_equal(back, alone), "%s: after disable the picture of %s alone "
             "(largest difference %g)" % (name, name, np.abs(back - alone).max()))
    p.close()

# Depth of field and SSAA draw the scene larger than the viewport: the
# screen-space techniques are refused (they would fall back to hard shadows),
# the light-space ones combine.
for name, turn_on, twice in (("depth of field", lambda p: p.enable_depth_of_field(), True),
                             ("SSAA", lambda p: p.enable_anti_aliasing("ssaa"), False)):
    p, (spot,) = scene()
    turn_on(p)
    alone = grab(p, twice)
    ok, text = refused(SoftShadowsCompatibilityError, [name, "contact"],
                       lambda: enable_soft_shadows(p, "contact", light_radius=RADIUS))
    st.check(ok and not spot.GetInformation().Has(RADIUS_KEY) and get_soft_shadow_pass(p) is None,
             "%s with contact: refused, nothing changed: %s" % (name, text))
    enable_soft_shadows(p, "hard", map_size=1024)
    check_shadow("hard with %s" % name, visibility(grab(p, twice), alone), 0.2, 0.85)
    disable_soft_shadows(p)
    st.check(np.array_equal(grab(p, twice), alone),
             "%s: after disable the picture of %s alone" % (name, name))
    p.close()

# Enabled first, then PyVista's pass on and off: PyVista resets the renderer's
# pass to None when its last pass goes; the shadows stay.
p, _ = scene()
enable_soft_shadows(p, "contact", light_radius=RADIUS, map_size=512)
p.enable_ssao()
check_shadow("SSAO after contact", visibility(grab(p), plain), 0.35, 0.8)
p.disable_ssao()
check_shadow("contact after SSAO is turned off again", visibility(grab(p), plain))
p.close()

# SSAA turned on after a screen-space technique: the shadows go, with a word.
p, _ = scene()
enable_soft_shadows(p, "contact", light_radius=RADIUS)
grab(p)
p.enable_anti_aliasing("ssaa")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    grab(p)
said = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
st.check(get_soft_shadow_pass(p) is None and any("SSAA" in s and "turned off" in s for s in said),
         "SSAA after contact: the soft shadows are turned off with a warning: %s" % said)
p.close()

# PyVista's own shadows: refused either way round.
p, _ = scene()
p.enable_shadows()
ok, text = refused(SoftShadowsCompatibilityError, ["enable_shadows", "disable_shadows"],
                   lambda: enable_soft_shadows(p, "hard"))
st.check(ok, "with PyVista's shadows on: refused: %s" % text)
p.disable_shadows()
enable_soft_shadows(p, "hard")
check_shadow("hard after PyVista's shadows were turned off", visibility(grab(p), plain), 0.2)
p.close()
p, _ = scene()
enable_soft_shadows(p, "hard")
grab(p)
p.enable_shadows()
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    grab(p)
said = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
st.check(get_soft_shadow_pass(p) is None and any("enable_shadows" in s for s in said),
         "PyVista's shadows after soft ones: these are turned off, with a warning: %s" % said)
p.close()

# A subplot away from the window's corner with eye dome lighting, which draws
# the scene into a buffer of its own at its corner: screen-space techniques
# refused, light-space ones combined.
p, _ = scene(shape=(1, 2))
p.subplot(0, 1)
p.enable_eye_dome_lighting()
alone = grab(p, column=1)
ok, text = refused(SoftShadowsCompatibilityError, ["subplot", "vtkEDLShading"],
                   lambda: enable_soft_shadows(p, "contact", light_radius=RADIUS))
st.check(ok, "contact with eye dome lighting in the right subplot: refused: %s" % text)
enable_soft_shadows(p, "hard")
check_shadow("hard with eye dome lighting in the right subplot",
             visibility(grab(p, column=1), alone), 0.2, 0.85)
p.subplot(0, 0)
st.check(get_soft_shadow_pass(p) is None, "the other subplot's renderer is untouched")
p.close()

# silhouette, smoothies and aliasfree read the casters' polydata: add_mesh()
# actors (vtkDataSetMapper) cast their soft shadows as vtkPolyDataMapper
# actors do.
p, _ = scene()
plain = grab(p)
enable_soft_shadows(p, "hard")
v_hard = visibility(grab(p), plain)
for technique in ("silhouette", "smoothies", "aliasfree"):
    enable_soft_shadows(p, technique, light_radius=RADIUS)
    v = visibility(grab(p, twice=True), plain)
    check_shadow("%s with add_mesh() actors" % technique, v)
    st.check(penumbra(v) > 1.5 * penumbra(v_hard), "%s there is soft: %d penumbra pixels, "
             "hard %d" % (technique, penumbra(v), penumbra(v_hard)))
p.close()

# A pass set by hand outside PyVista's: refused, not silently replaced.
p, _ = scene()
mine = vtkRenderStepsPass()
p.renderer.SetPass(mine)
ok, text = refused(SoftShadowsCompatibilityError, ["SetPass"],
                   lambda: enable_soft_shadows(p, "hard"))
st.check(ok and p.renderer.GetPass() is mine, "a hand-set pass: refused, kept: %s" % text)
p.close()

# PyVista's light kit: one headlight and four directional camera lights; the
# camera lights cast shadows (their size in degrees), the headlight none.
p, _ = scene(lighting="light kit")
kit = enable_soft_shadows(p, "hard", light_radius=2.0)
grab(p)
lights = [p.renderer.GetLights().GetItemAsObject(i)
          for i in range(p.renderer.GetLights().GetNumberOfItems())]
heads = [light for light in lights if light.LightTypeIsHeadlight()]
sized = [light for light in lights if light.GetInformation().Has(RADIUS_KEY)]
st.check(len(lights) == 5 and len(heads) == 1 and len(sized) == 4
         and kit.GetNumberOfShadowedLights() == 4,
         "light kit: %d lights, %d headlight, %d sized, %d shadowed"
         % (len(lights), len(heads), len(sized), kit.GetNumberOfShadowedLights()))
disable_soft_shadows(p)
st.check(not any(light.GetInformation().Has(RADIUS_KEY) for light in lights),
         "light kit: the sizes are taken back")
p.close()

# Plotter components (PyVista 0.48 and later): plotter.enable_soft_shadows().
p, (spot,) = scene()
if hasattr(pv, "register_plotter_component"):
    made = p.enable_soft_shadows("hard", map_size=512)
    st.check(made.IsA("vtkHardShadowPass") and p.soft_shadows.shadow_pass is made,
             "plotter.enable_soft_shadows() and plotter.soft_shadows.shadow_pass")
    check_shadow("hard through the plotter component", visibility(grab(p), plain), 0.2)
    p.disable_soft_shadows()
    st.check(not p.soft_shadows.enabled and np.array_equal(grab(p), plain),
             "plotter.disable_soft_shadows(): the plain picture")
    p.enable_soft_shadows("contact", light_radius=RADIUS)
    grab(p)
    p.close()
    st.check(get_soft_shadow_pass(p) is None and not spot.GetInformation().Has(RADIUS_KEY),
             "closing the plotter turns them off (the component's close hook)")
else:
    print("PyVista %s has no plotter components (0.48 and later): plotter.enable_soft_shadows "
          "not checked" % pv.__version__)
    enable_soft_shadows(p, "contact", light_radius=RADIUS)
    grab(p)
    p.close()
    disable_soft_shadows(p)
    st.check(get_soft_shadow_pass(p) is None,
             "closing a plotter with soft shadows on, then disabling: none left")

# Shadows as data on PyVista meshes (light_visibility): the ball's shadow on
# the plane under the plotter's sized spot light, umbra under the ball and
# lit beyond; with the sun at the equator on the equinox, 12 hours on the
# open plane; mistakes refused with the filter's reason.
floor = pv.Plane(i_size=6, j_size=6, i_resolution=60, j_resolution=60, direction=(0, 1, 0))
ball = pv.Sphere(radius=0.5, center=(0, 1, 0), theta_resolution=48, phi_resolution=24)
lamp = pv.Light(position=(0, 5, 0), focal_point=(0, 0, 0), positional=True, cone_angle=45)
vtkSoftShadowPass.SetRadius(0.3, lamp)
seen = light_visibility(floor, [lamp], casters=[ball], samples=16,
                        sun={"latitude": 0.0, "day": 80, "up": (0, 1, 0), "north": (0, 0, -1)})
values = seen.point_data["LightVisibility"]
distance = np.linalg.norm(seen.points[:, [0, 2]], axis=1)
st.check(isinstance(seen, pv.PolyData) and values[distance < 0.1].max() == 0.0 and
         values[distance > 1.5].min() == 1.0,
         "light_visibility: umbra under the ball, lit beyond (%s)" % type(seen).__name__)
flipped = light_visibility(ball.compute_normals(flip_normals=True), [lamp], samples=16,
                           two_sided=True)
st.check(flipped.point_data["LightVisibility"].max() == 1.0,
         "light_visibility(two_sided=True): a ball with inward normals is lit on top")
open_ground = np.abs(seen.points[:, 2]) > 1.0
st.check(np.all(np.abs(seen.point_data["SunHours"][open_ground] - 12.0) <= 0.25),
         "light_visibility: 12 hours of sun on the open plane at the equator")
for bad, expected in [({"sun": {"latitude": 0.0, "north": (0, 0, 1)}}, "parallel"),
                      ({"sun": {"lattitude": 0.0}}, "unknown sun key"), ({}, "no lights")]:
    try:
        light_visibility(floor, **bad)
        refused_with = None
    except (RuntimeError, ValueError) as error:
        refused_with = str(error)
    st.check(refused_with is not None and expected in refused_with,
             "light_visibility(%s): refused (%s)" % (bad, refused_with))

reference.close()
text = take_messages()
st.check("ERROR" not in text, "no error from VTK:\n%s" % text[-2000:])
print("ok")
