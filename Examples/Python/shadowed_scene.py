"""A ball above a floor, lit by a spot light of radius 0.3, drawn with
shadows by setting a vtkHardShadowPass on the renderer. Writes a PNG.

    PYTHONPATH=build/lib/python3/dist-packages \
      xvfb-run -a /usr/bin/python3 Examples/Python/shadowed_scene.py shadowed.png
"""
import sys

from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

from vtksoftshadows import vtkHardShadowPass, vtkSoftShadowPass


def main(output):
    # A 6 x 6 floor on y = 0, facing up.
    floor = vtkPlaneSource()
    floor.SetOrigin(-3.0, 0.0, -3.0)
    floor.SetPoint1(-3.0, 0.0, 3.0)
    floor.SetPoint2(3.0, 0.0, -3.0)
    floor_mapper = vtkPolyDataMapper()
    floor_mapper.SetInputConnection(floor.GetOutputPort())
    floor_actor = vtkActor()
    floor_actor.SetMapper(floor_mapper)

    # A ball floating above it.
    ball = vtkSphereSource()
    ball.SetRadius(0.5)
    ball.SetThetaResolution(48)
    ball.SetPhiResolution(24)
    ball_mapper = vtkPolyDataMapper()
    ball_mapper.SetInputConnection(ball.GetOutputPort())
    ball_actor = vtkActor()
    ball_actor.SetMapper(ball_mapper)
    ball_actor.SetPosition(0.0, 1.0, 0.0)
    ball_actor.GetProperty().SetColor(0.9, 0.3, 0.25)

    # Shadows come from scene lights: a spot light (cone < 90 degrees) above
    # the ball. Its radius sets the penumbra width of the soft techniques.
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(1.0, 5.0, 0.5)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    light.SetConeAngle(40.0)
    vtkSoftShadowPass.SetRadius(0.3, light)

    renderer = vtkRenderer()
    renderer.AddActor(floor_actor)
    renderer.AddActor(ball_actor)
    renderer.AutomaticLightCreationOff()
    renderer.AddLight(light)
    renderer.SetBackground(0.2, 0.2, 0.25)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 5.0, 7.0)
    camera.SetFocalPoint(0.0, 0.5, 0.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()

    # The pass draws the shadow maps and the scene: every ordinary actor
    # casts and receives shadows. Other techniques (vtkReferenceShadowPass...)
    # are set the same way.
    shadows = vtkHardShadowPass()
    renderer.SetPass(shadows)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(480, 360)
    window.AddRenderer(renderer)
    window.Render()

    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(output)
    writer.SetInputConnection(capture.GetOutputPort())
    writer.Write()
    return 0 if writer.GetErrorCode() == 0 else 1


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("Usage: shadowed_scene.py OUTPUT.png")
    sys.exit(main(sys.argv[1]))
