# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""More lights than a technique's receivers have texture units for: 40
lights (spot and point) over the ball. Every technique shadows as many as
fit, the brightest and then the nearest the focal point, draws the rest lit
but unshadowed, says so in one warning (again only when the number
changes) and logs no error; the picture is never blank."""
import math

import numpy as np
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkImagingSources import vtkImageCanvasSource2D
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderWindow, vtkRenderer, vtkTexture
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory)

from vtksoftshadows import (vtkAliasFreeShadowPass, vtkContactHardeningShadowPass,
                            vtkHardShadowPass, vtkOmnidirectionalShadowPass,
                            vtkReferenceShadowPass, vtkSilhouetteShadowPass,
                            vtkSmoothieShadowPass, vtkSoftShadowPass)

import shadowtest as st

LIGHTS = 40
UNSHADOWED = "lights are drawn without shadows"


def scene(pass_class, textured=False):
    """Ground and ball; light 0 a bright spot above the ball, light 1 a
    bright point light beside it, then 38 dim ones, spot and point in turn,
    each farther from the focal point than the one before."""
    renderer = vtkRenderer()
    st.add_ground_and_ball(renderer)
    if textured:
        canvas = vtkImageCanvasSource2D()
        canvas.SetExtent(0, 7, 0, 7, 0, 0)
        canvas.SetScalarTypeToUnsignedChar()
        canvas.SetNumberOfScalarComponents(3)
        canvas.SetDrawColor(255, 255, 255)
        canvas.FillBox(0, 7, 0, 7)
        texture = vtkTexture()
        texture.SetInputConnection(canvas.GetOutputPort())
        renderer.GetActors().GetLastActor().SetTexture(texture)
    lights = []
    for i in range(LIGHTS):
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPositional(True)
        if i == 0:
            light.SetPosition(0, 5, 0)
            light.SetConeAngle(45)
            light.SetIntensity(0.6)
        elif i == 1:
            light.SetPosition(1.5, 4, 0)
            light.SetConeAngle(180)
            light.SetIntensity(0.5)
        else:
            angle = 2.0 * math.pi * i / LIGHTS
            reach = 1.0 + 0.05 * i
            light.SetPosition(reach * math.cos(angle), 4, reach * math.sin(angle))
            light.SetConeAngle(45 if i % 2 == 0 else 180)
            light.SetIntensity(0.02)
        light.SetFocalPoint(0, 0, 0)
        renderer.AddLight(light)
        lights.append(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 6, 6)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCameraClippingRange()
    shadows = pass_class()
    shadows.SetMapSize(256)
    renderer.SetPass(shadows)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(64, 64)
    # Pixels all 0 or 255 below: no edge blended by multisampling, which
    # VTK 9.6 applies to such windows under Xvfb and 9.1 does not.
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    return window, renderer, lights, shadows


def pixel(renderer, x, y, z):
    renderer.SetWorldPoint(x, y, z, 1.0)
    renderer.WorldToDisplay()
    d = renderer.GetDisplayPoint()
    return int(round(d[1])), int(round(d[0]))  # row, column


def visibility_at(window, renderer, shadows, light, point):
    """Light `light`'s visibility at a ground point (mean of 3x3 pixels)."""
    shadows.SetShadowOnlyLight(light)
    window.Render()
    red = st.grab_red(window) / 255.0
    row, column = pixel(renderer, *point)
    return red[row - 1:row + 2, column - 1:column + 2].mean()


messages = vtkStringOutputWindow()
previous = vtkOutputWindow.GetInstance()
vtkOutputWindow.SetInstance(messages)


taken = [0]


def take_messages():
    """What VTK said since the last call."""
    text = messages.GetOutput()
    new, taken[0] = text[taken[0]:], len(text)
    return new


techniques = [("hard", vtkHardShadowPass), ("reference", vtkReferenceShadowPass),
              ("contact", vtkContactHardeningShadowPass), ("omni", vtkOmnidirectionalShadowPass),
              ("silhouette", vtkSilhouetteShadowPass), ("smoothies", vtkSmoothieShadowPass),
              ("aliasfree", vtkAliasFreeShadowPass)]
for name, pass_class in techniques:
    window, renderer, lights, shadows = scene(pass_class)
    for _ in range(3):
        window.Render()
    shadowed = shadows.GetNumberOfShadowedLights()
    unshadowed = shadows.GetNumberOfUnshadowedLights()
    capacity = (shadows.GetMaximumNumberOfShadowedLights(False),
                shadows.GetMaximumNumberOfShadowedLights(True))
    print("%-10s shadows %d of %d lights (at most %d spot or %d point lights)"
          % (name, shadowed, LIGHTS, capacity[0], capacity[1]))
    st.check(0 < shadowed < LIGHTS and shadowed + unshadowed == LIGHTS,
             "%s: %d shadowed and %d unshadowed of %d" % (name, shadowed, unshadowed, LIGHTS))
    st.check(capacity[1] <= shadowed <= capacity[0] or capacity[0] <= shadowed <= capacity[1],
             "%s: as many shadowed as fit (%d, capacity %s)" % (name, shadowed, capacity))

    # Lit where the lights reach: the ground and the ball, not a blank frame.
    red = st.grab_red(window)
    st.check(np.mean(red > 40) > 0.5, "%s: the picture is lit (%.0f%% of pixels)"
             % (name, 100 * np.mean(red > 40)))

    text = take_messages()
    st.check(text.count(UNSHADOWED) == 1 and str(unshadowed) + " of 40 " + UNSHADOWED in text,
             "%s: one warning over three frames naming the %d unshadowed lights" % (name, unshadowed))
    st.check("ERROR" not in text, "%s: no error%s" % (name, "" if "ERROR" not in text else
                                                      ":\n" + text))

    # The brightest lights (a spot and a point light) cast their shadows;
    # the farthest dim light is drawn unshadowed.
    for light, under, beside in ((0, (0, 0, 0), (2.0, 0, 1.5)), (1, (-0.5, 0, 0), (1.5, 0, 2.0))):
        dark = visibility_at(window, renderer, shadows, light, under)
        bright = visibility_at(window, renderer, shadows, light, beside)
        st.check(dark < 0.2 and bright > 0.9, "%s: light %d shadows the ground under the ball "
                 "(%.2f) and lights it beside (%.2f)" % (name, light, dark, bright))
    shadows.SetShadowOnlyLight(LIGHTS - 1)
    window.Render()
    red = st.grab_red(window)  # the background is black
    st.check(np.mean(red == 255) > 0.5 and np.all((red == 0) | (red == 255)),
             "%s: the farthest dim light is unshadowed (%.0f%% of pixels lit, %d partly)"
             % (name, 100 * np.mean(red == 255), np.sum((red > 0) & (red < 255))))
    shadows.SetShadowOnlyLight(-1)

    # Fewer lights, still too many: one more warning; then few enough: none.
    for light in lights[-5:]:
        light.SwitchOff()
    window.Render()
    window.Render()
    text = take_messages()
    st.check(text.count(UNSHADOWED) == (1 if shadows.GetNumberOfUnshadowedLights() else 0),
             "%s: one warning when the number of unshadowed lights changes" % name)
    for light in lights[3:]:
        light.SwitchOff()
    window.Render()
    text = take_messages()
    st.check(shadows.GetNumberOfShadowedLights() == 3 and UNSHADOWED not in text
             and "ERROR" not in text, "%s: three lights, all shadowed, no word" % name)
    shadows.ReleaseGraphicsResources(window)
    window.Finalize()

# A receiver with textures of its own beyond the reserve shadows the lights
# that fit beside them, says so, and raises the reserve for the next frames.
window, renderer, lights, shadows = scene(vtkHardShadowPass, textured=True)
shadows.SetReservedTextureUnits(0)
window.Render()
first = shadows.GetNumberOfShadowedLights()
window.Render()
text = take_messages()
st.check("leave room for the shadows of" in text and "ERROR" not in text,
         "a textured receiver beyond the reserve shadows the lights that fit:\n%s" % text)
st.check(shadows.GetNumberOfShadowedLights() == first - 1,
         "its texture comes off the next frames' budget (%d, then %d lights)"
         % (first, shadows.GetNumberOfShadowedLights()))
shadows.ReleaseGraphicsResources(window)
window.Finalize()

vtkOutputWindow.SetInstance(previous)
print("ok")
