# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Screen-space techniques in a renderer that does not start at the window's
corner: the same scene drawn in a whole window and in the right half of one
twice as wide (an odd size, so reduced buffers round up) must give the same
visibility, for `contact` at full and half resolution and for `reference`.
And tiny or empty viewports, for every pass: drawn, or refused with an
error, never a crash."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory)

from vtksoftshadows import (vtkContactHardeningShadowPass, vtkHardShadowPass,
                            vtkOmnidirectionalShadowPass, vtkReferenceShadowPass,
                            vtkSoftShadowPass)

import shadowtest as st

WIDTH, HEIGHT = 241, 181


def actor(source, position=(0.0, 0.0, 0.0)):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    a = vtkActor()
    a.SetMapper(mapper)
    a.SetPosition(*position)
    return a


def renderer(make_pass, viewport):
    floor = vtkPlaneSource()
    floor.SetOrigin(-3, 0, -3)
    floor.SetPoint1(-3, 0, 3)
    floor.SetPoint2(3, 0, -3)
    ball = vtkSphereSource()
    ball.SetRadius(0.5)
    ball.SetThetaResolution(48)
    ball.SetPhiResolution(24)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(1, 5, 0.5)
    light.SetFocalPoint(0, 0, 0)
    light.SetConeAngle(40)
    vtkSoftShadowPass.SetRadius(0.3, light)
    r = vtkRenderer()
    r.AddActor(actor(floor))
    r.AddActor(actor(ball, (0, 1, 0)))
    r.AutomaticLightCreationOff()
    r.AddLight(light)
    r.SetViewport(*viewport)
    r.SetBackground(0.5, 0.5, 0.5)  # apart from the umbra's 0 and the lit 1
    camera = r.GetActiveCamera()
    camera.SetPosition(0, 5, 7)
    camera.SetFocalPoint(0, 0.5, 0)
    shadow_pass = make_pass()
    shadow_pass.SetShadowOnlyLight(0)
    r.SetPass(shadow_pass)
    return r


def grey(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[:, :, 0].astype(float)


def contact(divisor):
    def make():
        p = vtkContactHardeningShadowPass()
        p.SetResolutionDivisor(divisor)
        return p
    return make


def reference():
    p = vtkReferenceShadowPass()
    p.SetNumberOfSamples(16)
    return p


for label, make_pass in (("contact, divisor 1", contact(1)), ("contact, divisor 2", contact(2)),
                         ("reference", reference)):
    whole = vtkRenderWindow()
    whole.SetOffScreenRendering(1)
    whole.SetSize(WIDTH, HEIGHT)
    whole.AddRenderer(renderer(make_pass, (0, 0, 1, 1)))
    whole.Render()
    expected = grey(whole)

    halves = vtkRenderWindow()
    halves.SetOffScreenRendering(1)
    halves.SetSize(2 * WIDTH, HEIGHT)
    left = vtkRenderer()
    left.SetViewport(0, 0, 0.5, 1)
    halves.AddRenderer(left)
    halves.AddRenderer(renderer(make_pass, (0.5, 0, 1, 1)))
    halves.Render()
    got = grey(halves)[:, WIDTH:]

    differ = int((np.abs(got - expected) > 8).sum())
    shadowed = int((expected < 100).sum())
    print("%s: %d of %d pixels differ, %d in shadow" % (label, differ, expected.size, shadowed))
    st.check(shadowed > 1000, "%s: the ball casts a shadow (%d pixels)" % (label, shadowed))
    st.check(differ == 0, "%s: the right-hand renderer sees the same visibility" % label)


# Tiny and empty viewports: one pixel, three, a sliver that rounds to nothing.
for make_pass in (vtkHardShadowPass, contact(2), vtkOmnidirectionalShadowPass, reference):
    for size, viewport, empty in (((1, 1), (0, 0, 1, 1), False), ((3, 3), (0, 0, 1, 1), False),
                                  ((64, 64), (0.5, 0, 0.5, 1), True)):
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(*size)
        r = renderer(make_pass, viewport)
        errors = []
        r.GetPass().AddObserver("ErrorEvent", lambda obj, event: errors.append(event))
        window.AddRenderer(r)
        window.Render()
        name = r.GetPass().GetClassName()
        st.check(bool(errors) == empty, "%s in a %dx%d viewport: %s" % (
            name, size[0] if not empty else 0, size[1],
            "refused with an error" if empty else "drawn without error"))
