# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Every kind of actor VTK draws looks as VTK draws it under every technique,
plus its shadow: the compatibility matrix.

Each case puts one actor (a mapper and render mode a VTK user draws with)
above a floor under a spot light, and is drawn by plain VTK and by each
technique. Then, against plain VTK's picture:
- drawn and lit: the actor's pixels that plain VTK lights keep their
  brightness (nothing lies between them and the light; only the actor's own
  terminator may move a little);
- casting: the floor darkens where the actor's shadow falls;
- receiving: with a plate high above (out of view) between it and the
  light, the actor's lit pixels go dark; what VTK draws unlit (lines without
  normals, image slices, text) stays as it is;
- no stray darkness: most of the floor stays as plain VTK draws it;
- no error from VTK, and a warning only where a mapper cannot be shadowed
  (volumes), naming it.
Every failure is listed before the test fails.
"""
import sys

import numpy as np
import shadowtest as st
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import (VTK_STRING, vtkCommand, vtkFloatArray, vtkOutputWindow,
                                      vtkPoints, vtkUnsignedCharArray)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkMolecule, vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkDomainsChemistryOpenGL2 import vtkOpenGLMoleculeMapper
from vtkmodules.vtkFiltersCore import vtkElevationFilter, vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import (vtkCubeSource, vtkLineSource, vtkPlaneSource,
                                          vtkSphereSource, vtkTexturedSphereSource)
from vtkmodules.vtkImagingSources import vtkImageGridSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingAnnotation import vtkAxesActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkAssembly, vtkColorTransferFunction,
                                         vtkGlyph3DMapper,
                                         vtkImageSlice, vtkImageSliceMapper, vtkLight,
                                         vtkLightActor,
                                         vtkPolyDataMapper, vtkRenderWindow, vtkRenderer,
                                         vtkTextActor, vtkTexture, vtkVolume,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingFreeType  # noqa: F401
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLSphereMapper, vtkOpenGLStickMapper
from vtksoftshadows import (vtkContactHardeningShadowPass, vtkHardShadowPass,
                            vtkOmnidirectionalShadowPass, vtkReferenceShadowPass,
                            vtkSoftShadowPass)

SIZE = (160, 120)


def mapper_for(source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    return mapper


def actor_for(mapper, color=(0.9, 0.5, 0.3)):
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def ball(resolution=24):
    sphere = vtkSphereSource()
    sphere.SetCenter(0.0, 0.9, 0.0)
    sphere.SetRadius(0.45)
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    return sphere


def grid_plate():
    """A plate facing the light, with point normals."""
    plate = vtkPlaneSource()
    plate.SetOrigin(-0.6, 0.8, 0.6)
    plate.SetPoint1(0.6, 0.8, 0.6)
    plate.SetPoint2(-0.6, 0.8, -0.6)
    plate.SetResolution(8, 8)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(plate.GetOutputPort())
    return normals


def three_points():
    points = vtkPoints()
    for x in (-0.5, 0.0, 0.5):
        points.InsertNextPoint(x, 0.9, 0.0)
    vertices = vtkCellArray()
    for i in range(3):
        vertices.InsertNextCell(1)
        vertices.InsertCellPoint(i)
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetVerts(vertices)
    return data


def grid_image(size, spacing, line, fill):
    """A size x size grey image: lines `spacing` pixels apart on a fill."""
    grid = vtkImageGridSource()
    grid.SetDataExtent(0, size - 1, 0, size - 1, 0, 0)
    grid.SetGridSpacing(spacing, spacing, 0)
    grid.SetLineValue(line)
    grid.SetFillValue(fill)
    grid.SetDataScalarTypeToUnsignedChar()
    return grid


def case_surface():
    return [actor_for(mapper_for(ball()))]


def case_representation(setup):
    actor = actor_for(mapper_for(grid_plate()))
    setup(actor.GetProperty())
    return [actor]


def case_edges():
    actor = actor_for(mapper_for(ball()))
    actor.GetProperty().EdgeVisibilityOn()
    return [actor]


def case_polylines():
    line = vtkLineSource()
    line.SetPoint1(-0.7, 0.9, 0.0)
    line.SetPoint2(0.7, 0.9, 0.0)
    actor = actor_for(mapper_for(line))
    actor.GetProperty().SetLineWidth(3)
    return [actor]


def case_sphere_imposters():
    mapper = vtkOpenGLSphereMapper()
    mapper.SetInputData(three_points())
    mapper.SetRadius(0.22)
    return [actor_for(mapper)]


def case_stick_imposters():
    """Three sticks, along x, z and x: vtkOpenGLStickMapper ray-casts them in
    the fragment shader (molecules' bonds without the molecule mapper). It
    reads colours from scalars, which it needs."""
    data = three_points()
    colors = vtkUnsignedCharArray()
    colors.SetNumberOfComponents(3)
    orientation = vtkFloatArray()
    orientation.SetName("orientation")
    orientation.SetNumberOfComponents(3)
    scale = vtkFloatArray()
    scale.SetName("scale")
    scale.SetNumberOfComponents(3)  # length, radius, unused
    for direction in ((1, 0, 0), (0, 0, 1), (1, 0, 0)):
        orientation.InsertNextTuple3(*direction)
        scale.InsertNextTuple3(0.45, 0.1, 0.0)
        colors.InsertNextTuple3(230, 128, 77)
    data.GetPointData().SetScalars(colors)
    data.GetPointData().AddArray(orientation)
    data.GetPointData().AddArray(scale)
    mapper = vtkOpenGLStickMapper()
    mapper.SetInputData(data)
    mapper.SetOrientationArray("orientation")
    mapper.SetScaleArray("scale")
    return [actor_for(mapper)]


def case_assembly():
    """Two balls as parts of a moved vtkAssembly: its parts take its keys."""
    assembly = vtkAssembly()
    for x in (-0.45, 0.45):
        sphere = vtkSphereSource()
        sphere.SetCenter(x, 0.0, 0.0)
        sphere.SetRadius(0.3)
        assembly.AddPart(actor_for(mapper_for(sphere)))
    assembly.SetPosition(0.0, 0.9, 0.0)
    return [assembly]


def case_axes():
    """vtkAxesActor draws its shafts and tips without handing on its keys."""
    axes = vtkAxesActor()
    axes.SetTotalLength(0.9, 0.9, 0.9)
    axes.SetShaftTypeToCylinder()
    axes.SetCylinderRadius(0.06)
    axes.SetConeRadius(0.3)
    axes.AxisLabelsOff()
    axes.SetPosition(-0.3, 0.6, 0.0)
    return [axes]


def case_molecule():
    molecule = vtkMolecule()
    atoms = [molecule.AppendAtom(z, x, 0.9, 0.0) for z, x in ((8, -0.6), (6, 0.0), (8, 0.6))]
    molecule.AppendBond(atoms[0], atoms[1], 2)
    molecule.AppendBond(atoms[1], atoms[2], 2)
    mapper = vtkOpenGLMoleculeMapper()
    mapper.SetInputData(molecule)
    mapper.UseBallAndStickSettings()
    return [actor_for(mapper)]


def case_composite():
    blocks = vtkMultiBlockDataSet()
    for i, x in enumerate((-0.45, 0.45)):
        sphere = vtkSphereSource()
        sphere.SetCenter(x, 0.9, 0.0)
        sphere.SetRadius(0.3)
        sphere.Update()
        blocks.SetBlock(i, sphere.GetOutput())
    mapper = st.composite_mapper()
    mapper.SetInputDataObject(blocks)
    return [actor_for(mapper)]


def case_glyphs():
    cube = vtkCubeSource()
    cube.SetXLength(0.3)
    cube.SetYLength(0.3)
    cube.SetZLength(0.3)
    mapper = vtkGlyph3DMapper()
    mapper.SetInputData(three_points())
    mapper.SetSourceConnection(cube.GetOutputPort())
    mapper.ScalingOff()
    return [actor_for(mapper)]


def case_textured():
    sphere = vtkTexturedSphereSource()
    sphere.SetRadius(0.45)
    sphere.SetThetaResolution(24)
    sphere.SetPhiResolution(24)
    grid = grid_image(64, 8, 80, 255)
    texture = vtkTexture()
    texture.SetInputConnection(grid.GetOutputPort())
    actor = actor_for(mapper_for(sphere), (1.0, 1.0, 1.0))
    actor.SetTexture(texture)
    actor.SetPosition(0.0, 0.9, 0.0)
    return [actor]


def case_scalars():
    sphere = ball()
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(sphere.GetOutputPort())
    elevation.SetLowPoint(0, 0.45, 0)
    elevation.SetHighPoint(0, 1.35, 0)
    mapper = mapper_for(elevation)
    mapper.SetScalarRange(0.0, 1.0)
    return [actor_for(mapper)]


def case_pbr():
    actor = actor_for(mapper_for(ball(32)))
    actor.GetProperty().SetInterpolationToPBR()
    actor.GetProperty().SetMetallic(0.2)
    actor.GetProperty().SetRoughness(0.5)
    return [actor]


def case_translucent():
    actors = []
    for x, color in ((-0.3, (1.0, 0.2, 0.2)), (0.3, (0.2, 1.0, 0.2))):
        sphere = vtkSphereSource()
        sphere.SetCenter(x, 0.9, 0.0 if x < 0 else 0.2)
        sphere.SetRadius(0.45)
        sphere.SetThetaResolution(32)
        sphere.SetPhiResolution(32)
        actor = actor_for(mapper_for(sphere), color)
        actor.GetProperty().SetOpacity(0.5)
        actors.append(actor)
    return actors


def case_text():
    text = vtkTextActor()
    text.SetInput("Shadows")
    text.GetTextProperty().SetFontSize(24)
    text.GetTextProperty().SetColor(1.0, 1.0, 0.6)
    text.SetPosition(20, 80)
    return [text]


def case_image_slice():
    grid = grid_image(32, 4, 60, 230)
    grid.SetDataSpacing(0.03, 0.03, 1.0)
    grid.SetDataOrigin(-0.47, 0.5, 0.0)
    mapper = vtkImageSliceMapper()
    mapper.SetInputConnection(grid.GetOutputPort())
    image = vtkImageSlice()
    image.SetMapper(mapper)
    image.GetProperty().SetColorWindow(255)
    image.GetProperty().SetColorLevel(127.5)
    return [image]


def case_volume():
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    mapper = vtkOpenGLGPUVolumeRayCastMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(60, 0.0)
    opacity.AddPoint(260, 0.4)
    colors = vtkColorTransferFunction()
    colors.AddRGBPoint(60, 0.2, 0.4, 1.0)
    colors.AddRGBPoint(260, 1.0, 0.9, 0.5)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.GetProperty().SetScalarOpacity(opacity)
    volume.GetProperty().SetColor(colors)
    volume.SetScale(0.03)
    volume.SetPosition(0.0, 0.9, 0.0)
    return [volume]


def case_light_actor():
    """The scene's light drawn as a cone and frustum (see render())."""
    return ["light actor"]


def shade():
    """A plate high above, between the actors and the light, out of view."""
    plate = vtkPlaneSource()
    plate.SetOrigin(-0.3, 3.0, 1.1)
    plate.SetPoint1(0.9, 3.0, 1.1)
    plate.SetPoint2(-0.3, 3.0, -0.1)
    return actor_for(mapper_for(plate))


# Translucent actors are drawn and receive shadows but cast none, as in VTK.
TRANSLUCENT = {"casts": False}
PEELED = {"casts": False, "peeling": True}

CASES = [
    ("surface", case_surface),
    ("wireframe", lambda: case_representation(lambda p: p.SetRepresentationToWireframe())),
    ("points", lambda: case_representation(
        lambda p: (p.SetRepresentationToPoints(), p.SetPointSize(4)))),
    ("edges", case_edges),
    # VTK lights lines only with normals: these are drawn unlit, shadow or not.
    ("polylines", case_polylines, {"receives": False}),
    ("lines as tubes", lambda: case_representation(
        lambda p: (p.SetRepresentationToWireframe(), p.RenderLinesAsTubesOn(),
                   p.SetLineWidth(4)))),
    ("points as spheres", lambda: case_representation(
        lambda p: (p.SetRepresentationToPoints(), p.RenderPointsAsSpheresOn(),
                   p.SetPointSize(6)))),
    ("sphere imposters", case_sphere_imposters),
    ("stick imposters", case_stick_imposters),
    ("molecule (sphere and stick imposters)", case_molecule),
    ("composite", case_composite),
    ("assembly", case_assembly),
    ("axes actor", case_axes),
    ("glyphs", case_glyphs),
    ("textured", case_textured),
    ("scalar colours", case_scalars),
    ("PBR", case_pbr),
    ("translucent", case_translucent, TRANSLUCENT),
    ("translucent, depth peeling", case_translucent, PEELED),
    # Drawn as plain VTK draws them; whether they cast is not asked here.
    ("text (2D)", case_text, {"casts": None, "receives": False}),
    ("image slice", case_image_slice, {"casts": None, "receives": False}),
    ("volume", case_volume,
     {"casts": None, "receives": False, "warns": "vtkOpenGLGPUVolumeRayCastMapper"}),
    # A picture of the light: drawn as plain VTK draws it, and casting nothing.
    # The same, in a viewport off the window's corner beside another renderer.
    ("surface, in a viewport", case_surface, {"viewport": (0.25, 0.1, 1.0, 0.95)}),
    ("light actor", case_light_actor,
     {"casts": False, "receives": None, "unlit": True,
      "view": ((5.0, 3.5, 6.0), (0.3, 2.0, 0.5))}),
]


def technique(name):
    if name == "hard":
        return vtkHardShadowPass()
    if name == "contact":
        return vtkContactHardeningShadowPass()
    if name == "omni":
        return vtkOmnidirectionalShadowPass()
    if name == "reference":
        reference = vtkReferenceShadowPass()
        reference.SetNumberOfSamples(16)
        return reference
    raise ValueError(name)


TECHNIQUES = ["hard", "contact", "omni", "reference"]


def render(props, name=None, peeling=False, view=None, viewport=None):
    """RGB image (rows bottom first) of the floor, `props` and the light;
    with `viewport`, in a renderer over that part of the window, beside a
    second, empty renderer over the rest."""
    renderer = vtkRenderer()
    if viewport:
        renderer.SetViewport(*viewport)
    renderer.SetUseDepthPeeling(peeling)
    renderer.AutomaticLightCreationOff()
    renderer.SetBackground(0.0, 0.0, 0.4)
    floor = vtkPlaneSource()
    floor.SetOrigin(-3, 0, 3)
    floor.SetPoint1(3, 0, 3)
    floor.SetPoint2(-3, 0, -3)
    renderer.AddActor(actor_for(mapper_for(floor), (0.8, 0.8, 0.8)))
    for prop in props:
        if prop != "light actor":
            renderer.AddViewProp(prop)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(0.6, 5.0, 1.0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    light.SetConeAngle(40.0)
    vtkSoftShadowPass.SetRadius(0.1, light)
    renderer.AddLight(light)
    if "light actor" in props:
        picture = vtkLightActor()
        picture.SetLight(light)
        picture.SetClippingRange(0.5, 4.0)  # the frustum ends above the floor, in view
        renderer.AddViewProp(picture)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*(view[0] if view else (0.0, 3.2, 3.6)))
    camera.SetFocalPoint(*(view[1] if view else (0.0, 0.5, 0.0)))
    renderer.ResetCameraClippingRange()
    if name:
        shadows = technique(name)
        shadows.SetMapSize(512)
        renderer.SetPass(shadows)
    window = vtkRenderWindow()
    window.SetSize(*SIZE)
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    if viewport:
        other = vtkRenderer()
        other.SetBackground(0.3, 0.0, 0.0)
        other.SetViewport(0.0, 0.0, viewport[0], 1.0)
        window.AddRenderer(other)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    result = image.reshape(SIZE[1], SIZE[0], -1)[:, :, :3].astype(float)
    window.Finalize()
    return result


def brightness(image):
    return image.mean(axis=2)


# Any error VTK reports (a shader that does not compile, say) fails the test:
# a technique must not quietly draw something else.
errors = []


@calldata_type(VTK_STRING)
def on_error(caller, event, text):
    errors.append(text)


vtkOutputWindow.GetInstance().AddObserver(vtkCommand.ErrorEvent, on_error)
# Warnings only where a mapper cannot be shadowed: one, naming it.
warnings = []


@calldata_type(VTK_STRING)
def on_warning(caller, event, text):
    warnings.append(text)


vtkOutputWindow.GetInstance().AddObserver(vtkCommand.WarningEvent, on_warning)

failures = []
floors = {}
for case, build, *options in CASES:
    options = options[0] if options else {}
    peeling = options.get("peeling", False)
    view = options.get("view")
    viewport = options.get("viewport")
    # The floor alone, once for each camera and viewport the cases use.
    key = (view, viewport)
    if key not in floors:
        floors[key] = brightness(render([], view=view, viewport=viewport))
    floor_only = floors[key]
    plain = brightness(render(build(), peeling=peeling, view=view, viewport=viewport))
    actor = np.abs(plain - floor_only) > 3.0
    floor = ~actor & (floor_only > 10.0)
    lit_actor = actor & (plain > 40.0)
    for name in TECHNIQUES:
        shaded = brightness(render(build(), name, peeling, view, viewport))
        label = "%s, %s" % (case, name)
        if options.get("unlit"):
            # Drawn as plain VTK draws it, pixel for pixel (its lines are black).
            changed = np.mean(np.abs(shaded[actor] - plain[actor]) > 10.0)
            if actor.sum() < 20 or changed > 0.01:
                failures.append("%s: %d pixels, %.1f%% of them not as plain VTK draws them"
                                % (label, actor.sum(), 100 * changed))
            print("%-40s %-9s %.1f%% of %d pixels changed" % (case, name, 100 * changed,
                                                            actor.sum()))
            continue
        if lit_actor.sum() < 20:
            failures.append("%s: plain VTK lights too little of the actor to judge" % label)
            continue
        # Drawn and lit as plain VTK draws it.
        difference = np.abs(shaded[lit_actor] - plain[lit_actor])
        darkened = np.mean(shaded[lit_actor] < 0.75 * plain[lit_actor])
        if np.median(difference) > 4.0 or darkened > 0.1:
            failures.append("%s: actor not lit as plain VTK (median difference %.1f, "
                            "%.0f%% of its lit pixels darker by a quarter)"
                            % (label, np.median(difference), 100 * darkened))
        # Casts a shadow on the floor, and leaves the rest of it alone.
        shadow = floor & (shaded < 0.75 * floor_only)
        if options.get("casts", True) is True and shadow.sum() < 15:
            failures.append("%s: no shadow on the floor (%d pixels)" % (label, shadow.sum()))
        if shadow.sum() > 0.3 * floor.sum():
            failures.append("%s: %.0f%% of the floor darkened" % (label, 100.0 * shadow.mean()))
        expected = options.get("warns")
        named = [w for w in warnings if expected and expected in w]
        if len(named) != (1 if expected else 0) or len(warnings) != len(named):
            failures.append("%s: %d warning(s), expected %s: %s" % (
                label, len(warnings), "one naming " + expected if expected else "none",
                " | ".join(w.strip()[-200:] for w in warnings)))
        warnings.clear()
        if errors:
            failures.append("%s: VTK reported %d error(s), the first: %s"
                            % (label, len(errors), errors[0].strip()[:300]))
            errors.clear()
        # Receives: under the plate, lit pixels go dark (VTK's light has no
        # ambient part here), unlit ones stay.
        receives = options.get("receives", True)
        if receives is not None:
            under = brightness(render(build() + [shade()], name, peeling, view, viewport))
            warnings.clear()  # the same as above, from a new pass
            kept = np.median(under[lit_actor] / plain[lit_actor])
            if (receives and kept > 0.3) or (not receives and kept < 0.9):
                failures.append("%s: under a plate, its lit pixels keep %.0f%% of their "
                                "brightness (expected %s)" % (label, 100 * kept,
                                                              "dark" if receives else "as is"))
            if errors:
                failures.append("%s, under a plate: VTK reported %d error(s), the first: %s"
                                % (label, len(errors), errors[0].strip()[:300]))
                errors.clear()
        print("%-40s %-9s actor median diff %4.1f, %3.0f%% darkened; floor shadow %4d px; "
              "under a plate %s" % (case, name, np.median(difference), 100 * darkened,
                                    shadow.sum(), "-" if receives is None else "%.2f" % kept))

if failures:
    print("\n".join("FAIL: " + f for f in failures))
    sys.exit(1)
print("ok: %d cases x %d techniques look as plain VTK draws them, plus their shadows"
      % (len(CASES), len(TECHNIQUES)))
