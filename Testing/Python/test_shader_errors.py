# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""A receiver's shader that does not compile (here: an actor's own shader
replacement that clashes with the shadow term) is reported in one error
naming the technique and the first line of OpenGL's log, not VTK's numbered
source; that actor is drawn as VTK draws it, the others keep their shadows,
and the next frames say nothing more. SOFTSHADOWS_DEBUG_SHADERS adds the
source to that one error."""
import os

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow, vtkStringOutputWindow

from vtksoftshadows import vtkHardShadowPass, vtkOmnidirectionalShadowPass

import shadowtest as st

messages = vtkStringOutputWindow()
previous = vtkOutputWindow.GetInstance()
vtkOutputWindow.SetInstance(messages)


def broken_ball(pass_class):
    """The API ball scene (shaded, not shadow-only) whose ball's fragment
    shader defines the name of light 0's shadow factor away: the shadow
    term cannot compile there, VTK's own lighting can."""
    window, _, shadows = st.api_ball(pass_class)
    shadows.SetShadowOnlyLight(-1)
    renderer = window.GetRenderers().GetFirstRenderer()
    renderer.GetActors().GetLastActor().GetShaderProperty().AddFragmentShaderReplacement(
        "//VTK::Light::Dec", True, "#define vtkShadowFactor0 )\n//VTK::Light::Dec", False)
    return window, renderer, shadows


def red_at(window, renderer, point):
    """The red channel around a world point (3x3 pixels)."""
    red = st.grab_red(window)
    renderer.SetWorldPoint(*point, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return red[int(y) - 1:int(y) + 2, int(x) - 1:int(x) + 2].mean()


def observed(obj, event):
    """Adds an observer that keeps the message of each `event`."""
    seen = []

    @calldata_type(VTK_STRING)
    def keep(caller, name, text):
        seen.append(text)
    obj.AddObserver(event, keep)
    return seen


for name, pass_class in (("hard", vtkHardShadowPass), ("omni", vtkOmnidirectionalShadowPass)):
    window, renderer, shadows = broken_ball(pass_class)
    errors = observed(shadows, vtkCommand.ErrorEvent)
    before = len(messages.GetOutput())
    for _ in range(3):
        window.Render()
    said = messages.GetOutput()[before:]
    st.check(len(errors) == 1, "%s: one error over three frames (%d)" % (name, len(errors)))
    text = errors[0] if errors else ""
    first = text.strip().split("\n")[-1] if text else ""
    st.check(pass_class.__name__ in first and "does not compile" in first and "the receivers" in first
             and "error" in first.split("does not compile or link:")[-1],
             "%s: it names the technique, the receivers and OpenGL's first line: %r" % (name, first))
    st.check(text.count("\n") <= 3 and "#version" not in text and "#version" not in said,
             "%s: no shader source printed (%d lines)" % (name, text.count("\n")))

    # The ball drawn as VTK draws it; the ground, whose shader compiled, keeps
    # the ball's shadow.
    top = red_at(window, renderer, (0.0, 1.5, 0.0))  # the ball's top, lit
    under = red_at(window, renderer, (0.0, 0.0, 0.4))  # the ground in its shadow
    lit = red_at(window, renderer, (2.0, 0.0, 1.5))
    st.check(top > 100 and under < 0.5 * lit,
             "%s: the ball is drawn (red %.0f), the ground keeps its shadow (%.0f under it, %.0f "
             "in the light)" % (name, top, under, lit))
    shadows.ReleaseGraphicsResources(window)
    window.Finalize()

# The debug switch: the same error, with the numbered source and the log.
os.environ["SOFTSHADOWS_DEBUG_SHADERS"] = "1"
window, renderer, shadows = broken_ball(vtkHardShadowPass)
errors = observed(shadows, vtkCommand.ErrorEvent)
window.Render()
st.check(len(errors) == 1 and "1: #version" in errors[0] and errors[0].count("\n") > 50,
         "SOFTSHADOWS_DEBUG_SHADERS: the one error holds the source (%d lines)"
         % (errors[0].count("\n") if errors else 0))
del os.environ["SOFTSHADOWS_DEBUG_SHADERS"]
shadows.ReleaseGraphicsResources(window)
window.Finalize()

vtkOutputWindow.SetInstance(previous)
print("ok")
