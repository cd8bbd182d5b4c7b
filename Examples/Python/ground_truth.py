# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""How close a technique is to physics: a ball over a floor under a spot
light of radius 0.3, the light's visibility drawn by vtkReferenceShadowPass
(the average of 256 shadow maps from points over the light) and by
vtkHardShadowPass, each against vtkRayCastLightVisibility, which ray-casts
the visible share of the light's sphere at every pixel (Embree, no shadow
map). Prints each pass's RMSE over the pixels quality is measured on and
writes the three visibility images side by side (truth, reference, hard).

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/ground_truth.py [OUTPUT.png]
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter

from vtksoftshadows import vtkHardShadowPass, vtkRayCastLightVisibility, vtkReferenceShadowPass

import example_scene as ex

SIZE = (320, 240)
output = sys.argv[1] if len(sys.argv) > 1 else "ground_truth.png"

ball = vtkSphereSource()
ball.SetRadius(0.5)
ball.SetThetaResolution(64)
ball.SetPhiResolution(32)
renderer = vtkRenderer()
renderer.AddActor(ex.floor())
renderer.AddActor(ex.actor(ball, position=(0.0, 1.0, 0.0)))
renderer.AutomaticLightCreationOff()
renderer.AddLight(ex.spot_light((1.0, 5.0, 0.5), 0.3))
camera = renderer.GetActiveCamera()
camera.SetPosition(0.0, 5.0, 7.0)
camera.SetFocalPoint(0.0, 0.5, 0.0)
renderer.ResetCameraClippingRange()
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(*SIZE)
window.AddRenderer(renderer)

# The truth, and the pixels it is measured on (lit from the front, inside
# the spot cone, away from silhouettes).
truth = vtkRayCastLightVisibility()
truth.SetRenderer(renderer)
truth.SetSize(*SIZE)
truth.Update()
points = truth.GetOutput().GetPointData()
visible = vtk_to_numpy(points.GetArray("Visibility")).reshape(SIZE[1], SIZE[0])
mask = vtk_to_numpy(points.GetArray("QualityMask")).reshape(SIZE[1], SIZE[0]) > 0

images = [visible]
for name, shadows in (("reference", vtkReferenceShadowPass()), ("hard", vtkHardShadowPass())):
    shadows.SetShadowOnlyLight(0)  # each pixel's colour is light 0's visibility
    renderer.SetPass(shadows)
    window.Render()
    capture = vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    capture.Update()
    pixels = vtk_to_numpy(capture.GetOutput().GetPointData().GetScalars())
    drawn = pixels[:, 0].reshape(SIZE[1], SIZE[0]) / 255.0
    rmse = float(np.sqrt(np.mean((drawn[mask] - visible[mask]) ** 2)))
    print("%-9s RMSE against the ray-cast truth: %.4f (%d pixels)" % (name, rmse, mask.sum()))
    images.append(drawn)

side_by_side = (np.clip(np.hstack(images), 0.0, 1.0) * 255).astype(np.uint8)
image = vtkImageData()
image.SetDimensions(side_by_side.shape[1], side_by_side.shape[0], 1)
image.GetPointData().SetScalars(numpy_to_vtk(side_by_side.ravel(), deep=True))
writer = vtkPNGWriter()
writer.SetFileName(output)
writer.SetInputData(image)
writer.Write()
print(os.path.abspath(output))
sys.exit(writer.GetErrorCode())
