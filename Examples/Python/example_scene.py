# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""What the examples share: a floor, actors, a spot light with a radius, a
camera, and drawing the scene through a shadow pass into a PNG.

Every example runs as

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/EXAMPLE.py [OUTPUT.png] [--plain]

writing OUTPUT.png (default: the example's name) and printing its path;
--plain draws the same scene without the shadow pass, as VTK draws it, to
see what the shadows add.
"""
import os
import sys

from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

from vtksoftshadows import vtkSoftShadowPass


def actor(source, color=(0.8, 0.8, 0.8), position=(0.0, 0.0, 0.0)):
    """An actor drawing `source` (an algorithm or a vtkPolyData)."""
    mapper = vtkPolyDataMapper()
    if hasattr(source, "GetOutputPort"):
        mapper.SetInputConnection(source.GetOutputPort())
    else:
        mapper.SetInputData(source)
    a = vtkActor()
    a.SetMapper(mapper)
    a.GetProperty().SetColor(*color)
    a.SetPosition(*position)
    return a


def floor(size=6.0):
    """A size x size floor on y = 0, facing up."""
    plane = vtkPlaneSource()
    half = size / 2.0
    plane.SetOrigin(-half, 0.0, -half)
    plane.SetPoint1(-half, 0.0, half)
    plane.SetPoint2(half, 0.0, -half)
    return actor(plane)


def spot_light(position, radius, focal_point=(0.0, 0.0, 0.0), cone_angle=45.0):
    """A scene spot light whose size (`radius`, world units) sets the
    penumbrae of the soft techniques: vtkSoftShadowPass.SetRadius()."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(*position)
    light.SetFocalPoint(*focal_point)
    light.SetConeAngle(cone_angle)
    vtkSoftShadowPass.SetRadius(radius, light)
    return light


def render(name, actors, lights, shadows, camera_position=(0.0, 5.0, 7.0),
           focal_point=(0.0, 0.5, 0.0), size=(480, 360)):
    """Draws `actors` under `lights` through the pass `shadows` (or without
    it with --plain) into the PNG the command line names; returns 0 when it
    was written."""
    arguments = [a for a in sys.argv[1:] if a != "--plain"]
    output = arguments[0] if arguments else name + ".png"

    renderer = vtkRenderer()
    for a in actors:
        renderer.AddActor(a)
    # Shadows come from scene lights; VTK's automatic headlight casts none.
    renderer.AutomaticLightCreationOff()
    for light in lights:
        renderer.AddLight(light)
    renderer.SetBackground(0.2, 0.2, 0.25)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*camera_position)
    camera.SetFocalPoint(*focal_point)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()
    if "--plain" not in sys.argv:
        # The pass draws the light-space maps and the scene: every ordinary
        # actor casts and receives shadows.
        renderer.SetPass(shadows)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()

    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(output)
    writer.SetInputConnection(capture.GetOutputPort())
    writer.Write()
    if writer.GetErrorCode() != 0:
        print("cannot write " + output, file=sys.stderr)
        return 1
    print(os.path.abspath(output))
    return 0
