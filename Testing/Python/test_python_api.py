# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A Python user's path: import the passes from `vtksoftshadows`, set one on
a renderer, and see a shadow where the ball hides the light; and the
techniques' catalog, which makes passes by name and sets their parameters."""
import math
import sys

from vtkmodules.vtkCommonCore import vtkCommand, vtkUnsignedCharArray
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkRenderWindow, vtkRenderer)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory)

from vtksoftshadows import (vtkContactHardeningShadowPass, vtkFenceSource, vtkHardShadowPass,
                            vtkOmnidirectionalShadowPass, vtkReferenceShadowPass,
                            vtkShadowLightSize, vtkShadowTechniqueCatalog, vtkSoftShadowPass)

import shadowtest as st


def actor(source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    a = vtkActor()
    a.SetMapper(mapper)
    return a


renderer = vtkRenderer()
plane = vtkPlaneSource()
plane.SetOrigin(-3, 0, -3)
plane.SetPoint1(3, 0, -3)
plane.SetPoint2(-3, 0, 3)
renderer.AddActor(actor(plane))
ball = vtkSphereSource()
ball.SetCenter(0, 1, 0)
ball.SetRadius(0.5)
renderer.AddActor(actor(ball))

light = vtkLight()
light.SetLightTypeToSceneLight()
light.SetPositional(True)
light.SetPosition(0, 5, 0)
light.SetFocalPoint(0, 0, 0)
light.SetConeAngle(45)
vtkSoftShadowPass.SetRadius(0.3, light)
st.check(abs(vtkSoftShadowPass.GetRadius(light) - 0.3) < 1e-12, "radius stored on the light")
# The pass's light size is vtkShadowLightSize's: one key, one rule.
st.check(vtkShadowLightSize.GetRadius(light) == vtkSoftShadowPass.GetRadius(light)
         and vtkShadowLightSize.RADIUS() is vtkSoftShadowPass.RADIUS(), "one light-size key")
vtkSoftShadowPass.SetRadius(-1.0, light)
st.check(vtkShadowLightSize.GetRadius(light) == 0.3, "a negative radius is refused")
st.check(not vtkShadowLightSize.IsPointLight(light), "a 45-degree cone is a spot light")
renderer.AddLight(light)

camera = renderer.GetActiveCamera()
camera.SetPosition(0, 6, 6)
camera.SetFocalPoint(0, 0, 0)
renderer.ResetCameraClippingRange()

window = vtkRenderWindow()
window.SetOffScreenRendering(True)
window.SetSize(200, 150)
window.AddRenderer(renderer)


def visibility_at(x, y, z):
    renderer.SetWorldPoint(x, y, z, 1.0)
    renderer.WorldToDisplay()
    dx, dy, _ = renderer.GetDisplayPoint()
    px, py = int(round(dx)), int(round(dy))
    rgb = vtkUnsignedCharArray()
    window.GetPixelData(px, py, px, py, 0, rgb, 0)
    return rgb.GetValue(0) / 255.0


for pass_type in (vtkHardShadowPass, vtkReferenceShadowPass, vtkContactHardeningShadowPass,
                  vtkOmnidirectionalShadowPass):
    shadow_pass = pass_type()
    shadow_pass.SetMapSize(512)
    shadow_pass.SetShadowOnlyLight(0)
    if pass_type is vtkReferenceShadowPass:
        shadow_pass.SetNumberOfSamples(16)
    renderer.SetPass(shadow_pass)
    window.Render()
    name = pass_type.__name__
    st.check(shadow_pass.GetNumberOfShadowedLights() == 1, name + ": one shadowed light")
    st.check(visibility_at(0.0, 0.0, 0.0) < 0.05, name + ": ground under the ball is in umbra")
    st.check(visibility_at(2.0, 0.0, 1.0) > 0.95, name + ": open ground is lit")

# One contact pass switched between variants (each keeps only the buffers it
# needs): the same umbra and lit ground every time.
contact = vtkContactHardeningShadowPass()
contact.SetMapSize(512)
contact.SetShadowOnlyLight(0)
renderer.SetPass(contact)
for variant in ("Gaussian", "MultiPass", "PCF", "Gaussian"):
    getattr(contact, "SetVariantTo" + variant)()
    window.Render()
    st.check(visibility_at(0.0, 0.0, 0.0) < 0.05, "contact " + variant + ": umbra under the ball")
    st.check(visibility_at(2.0, 0.0, 1.0) > 0.95, "contact " + variant + ": open ground is lit")

fence = vtkFenceSource()
fence.Update()
st.check(fence.GetOutput().GetNumberOfPolys() > 0, "vtkFenceSource makes triangles")

# The catalog: every technique and variant makes its pass, each parameter's
# default lies in its range and reads back what is set; a value out of range,
# or a pass of another class, is refused with an error and changes nothing.
catalog = vtkShadowTechniqueCatalog
names = [catalog.GetTechniqueName(t) for t in range(catalog.GetNumberOfTechniques())]
st.check(names == ["hard", "reference", "contact", "omni", "silhouette", "smoothies", "aliasfree"],
         "the catalog's techniques: %s" % names)
st.check(catalog.FindTechnique("nope") == -1 and catalog.GetTechniqueName(99) is None,
         "unknown techniques are -1 and have no name")
hard_pass = catalog.NewPass(catalog.FindTechnique("hard"), 0)
hard_errors = []
hard_pass.AddObserver(vtkCommand.ErrorEvent, lambda *args: hard_errors.append(args))
for t, name in enumerate(names):
    for v in range(max(1, catalog.GetNumberOfVariants(t))):
        made = catalog.NewPass(t, v)
        st.check(made is not None and made.IsA("vtkSoftShadowPass"),
                 "%s variant %d: a pass (%s)" % (name, v, made and made.GetClassName()))
    made = catalog.NewPass(t, -1)
    errors = []
    made.AddObserver(vtkCommand.ErrorEvent, lambda *args: errors.append(args))
    for p in range(catalog.GetNumberOfParameters(t)):
        key = "%s.%s" % (name, catalog.GetParameterKey(t, p))
        size = catalog.GetParameterSize(t, p)
        low, high = catalog.GetParameterMinimum(t, p), catalog.GetParameterMaximum(t, p)
        default = [0.0, 0.0, 0.0]
        st.check(catalog.GetParameter(made, t, p, default)
                 and all(low <= x <= high for x in default[:size]),
                 "%s: default %s in [%g, %g]" % (key, default[:size], low, high))
        # The catalog's bounds are the class's own: it keeps either end.
        top = [high if math.isfinite(high) else 1.0] * 3
        st.check(catalog.SetParameter(made, t, p, top) and catalog.GetParameter(made, t, p, default)
                 and default[:size] == top[:size], "%s: set to its maximum, read back" % key)
        wanted = [low if math.isfinite(low) else -1.0] * 3
        st.check(catalog.SetParameter(made, t, p, wanted) and catalog.GetParameter(made, t, p, default)
                 and default[:size] == wanted[:size], "%s: set to its minimum, read back" % key)
        del errors[:]
        refused = [math.nan] * 3
        if math.isfinite(high):
            refused = [high + 1.0] * 3
        st.check(not catalog.SetParameter(made, t, p, refused) and len(errors) == 1
                 and catalog.GetParameter(made, t, p, default) and default[:size] == wanted[:size],
                 "%s: %g refused with one error, the value kept" % (key, refused[0]))
contact_index = catalog.FindTechnique("contact")
dp = catalog.FindParameter(contact_index, "dp")
st.check(not catalog.SetParameter(hard_pass, contact_index, dp, [1.0, 0.0, 0.0])
         and len(hard_errors) == 1 and not catalog.GetParameter(hard_pass, contact_index, dp, [0.0] * 3),
         "contact.dp is not a parameter of a hard pass: one error")

# What is allowed: whole numbers for integers, 0 or 1 for booleans, finite.
samples = catalog.FindParameter(catalog.FindTechnique("reference"), "samples")
dilation = catalog.FindParameter(contact_index, "dilation")
bias = catalog.FindParameter(contact_index, "slope_scaled_bias")
reference_index = catalog.FindTechnique("reference")
st.check(catalog.IsAllowed(reference_index, samples, [16.0, 0, 0])
         and not catalog.IsAllowed(reference_index, samples, [16.5, 0, 0])
         and catalog.IsAllowed(contact_index, dilation, [1.0, 0, 0])
         and not catalog.IsAllowed(contact_index, dilation, [0.5, 0, 0])
         and catalog.IsAllowed(contact_index, bias, [-3.0, 0, 0])
         and not catalog.IsAllowed(contact_index, bias, [math.inf, 0, 0])
         and not catalog.IsAllowed(contact_index, bias, [math.nan, 0, 0]),
         "IsAllowed: 16.5 samples, a boolean 0.5 and an infinite or NaN bias are refused")

# SPECs, parsed by the library for every front end: name[:variant].
ids = [7, 7]
st.check(catalog.ParseSpec("contact:multipass", ids)
         and ids == [contact_index, catalog.FindVariant(contact_index, "multipass")]
         and catalog.GetSpecProblem("contact:multipass") == "",
         "ParseSpec('contact:multipass'): %s" % ids)
st.check(catalog.ParseSpec("smoothies", ids) and ids == [catalog.FindTechnique("smoothies"), -1],
         "ParseSpec('smoothies'): no variant named, %s" % ids)
for spec, words in (("raytraced", ["unknown technique 'raytraced'", "aliasfree"]),
                    ("contact:nope", ["unknown variant 'nope'", "multipass"]),
                    ("smoothies:soft", ["has none"]), ("", ["unknown technique ''"])):
    problem = catalog.GetSpecProblem(spec)
    st.check(not catalog.ParseSpec(spec, ids) and all(w in problem for w in words),
             "SPEC %r refused: %s" % (spec, problem))
made = catalog.NewPass("aliasfree:hard")
st.check(made is not None and made.IsA("vtkAliasFreeShadowPass") and made.GetVariant() == made.Hard,
         "NewPass('aliasfree:hard') makes the hard variant")
st.check(catalog.NewPass("contact:nope") is None, "NewPass of a bad SPEC is None")

# map_size, the biases...: every technique's, the framework's own.
for t, name in enumerate(names):
    shared = [catalog.GetParameterKey(t, p) for p in range(catalog.GetNumberOfParameters(t))
              if catalog.IsParameterShared(t, p)]
    st.check(shared[0] == "map_size" and "normal_bias" in shared and "pcf_radius" not in shared,
             "%s's shared parameters: %s" % (name, shared))
aliasfree_index = catalog.FindTechnique("aliasfree")
st.check(catalog.FindParameter(aliasfree_index, "seed") >= 0, "aliasfree has a seed parameter")

# What the pass says of itself: screen-space receivers, and its own timings.
uses = {name: catalog.NewPass(t, 0).GetUsesScreenSpace() for t, name in enumerate(names)}
st.check(uses == {"hard": False, "reference": True, "contact": True, "omni": False,
                  "silhouette": False, "smoothies": False, "aliasfree": True},
         "GetUsesScreenSpace: %s" % uses)
fresh = catalog.NewPass(catalog.FindTechnique("hard"), 0)
st.check(fresh.GetTechniqueCPUTime() < 0 and fresh.GetTechniqueGPUTime() < 0,
         "hard times no work of its own")
