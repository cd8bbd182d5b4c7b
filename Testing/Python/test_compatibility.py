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
import os
import sys
import time

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
from vtkmodules.vtkFiltersCore import vtkElevationFilter, vtkPolyDataNormals, vtkReverseSense
from vtkmodules.vtkFiltersSources import (vtkConeSource, vtkCubeSource, vtkLineSource, vtkPlaneSource,
                                          vtkSphereSource, vtkTexturedSphereSource)
from vtkmodules.vtkImagingSources import vtkImageGridSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingAnnotation import vtkAxesActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkAssembly, vtkColorTransferFunction,
                                         vtkCompositeDataDisplayAttributes,
                                         vtkGlyph3DMapper,
                                         vtkImageSlice, vtkImageSliceMapper, vtkLight,
                                         vtkLightActor,
                                         vtkPolyDataMapper, vtkRenderWindow, vtkRenderer,
                                         vtkTextActor, vtkTexture, vtkVolume,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingFreeType  # noqa: F401
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLSphereMapper, vtkOpenGLStickMapper
from vtksoftshadows import vtkShadowTechniqueCatalog, vtkSoftShadowPass

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


def grid_plate(resolution=8):
    """A plate facing the light, with point normals."""
    plate = vtkPlaneSource()
    plate.SetOrigin(-0.6, 0.8, 0.6)
    plate.SetPoint1(0.6, 0.8, 0.6)
    plate.SetPoint2(-0.6, 0.8, -0.6)
    plate.SetResolution(resolution, resolution)
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


def case_representation(setup, resolution=8):
    actor = actor_for(mapper_for(grid_plate(resolution)))
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
    # vtkAxesActor places its parts by its user transform only (not by SetPosition).
    place = vtkTransform()
    place.Translate(-0.3, 0.6, 0.0)
    axes.SetUserTransform(place)
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


def small_cube():
    """A glyph source: a cube 0.3 wide."""
    cube = vtkCubeSource()
    cube.SetXLength(0.3)
    cube.SetYLength(0.3)
    cube.SetZLength(0.3)
    return cube


def case_glyphs():
    cube = small_cube()
    mapper = vtkGlyph3DMapper()
    mapper.SetInputData(three_points())
    mapper.SetSourceConnection(cube.GetOutputPort())
    mapper.ScalingOff()
    return [actor_for(mapper)]


def case_oriented_glyphs():
    """Cones pointing three ways, each scaled by its own value: every
    instance at its own transform."""
    data = three_points()
    directions = vtkFloatArray()
    directions.SetName("direction")
    directions.SetNumberOfComponents(3)
    sizes = vtkFloatArray()
    sizes.SetName("size")
    for direction, size in (((1, 0, 0), 0.3), ((0, 0, 1), 0.5), ((1, 1, 0), 0.4)):
        directions.InsertNextTuple3(*direction)
        sizes.InsertNextValue(size)
    data.GetPointData().AddArray(directions)
    data.GetPointData().AddArray(sizes)
    cone = vtkConeSource()
    cone.SetResolution(12)
    cone.SetRadius(0.3)
    mapper = vtkGlyph3DMapper()
    mapper.SetInputData(data)
    mapper.SetSourceConnection(cone.GetOutputPort())
    mapper.SetOrientationArray("direction")
    mapper.SetOrientationModeToDirection()
    mapper.SetScaleArray("size")
    mapper.SetScaleModeToScaleByMagnitude()
    mapper.SetScaleFactor(1.5)
    return [actor_for(mapper)]


def case_indexed_glyphs():
    """A cube, a sphere and a cube again, picked per point by an index array."""
    data = three_points()
    index = vtkFloatArray()
    index.SetName("which")
    for i in (0, 1, 0):
        index.InsertNextValue(i)
    data.GetPointData().AddArray(index)
    cube = small_cube()
    sphere = vtkSphereSource()
    sphere.SetRadius(0.22)
    mapper = vtkGlyph3DMapper()
    mapper.SetInputData(data)
    mapper.SetSourceConnection(0, cube.GetOutputPort())
    mapper.SetSourceConnection(1, sphere.GetOutputPort())
    mapper.SourceIndexingOn()
    mapper.SetSourceIndexArray("which")
    mapper.ScalingOff()
    return [actor_for(mapper)]


def two_balls(hidden=None):
    """Two balls as two blocks of a composite dataset; the second drawn
    (`hidden` None), hidden by the display attributes ("block"), translucent
    by them ("translucent") or left out of the dataset ("left out")."""
    blocks = vtkMultiBlockDataSet()
    spheres = []
    for i, x in enumerate((-0.45, 0.45)):
        sphere = vtkSphereSource()
        sphere.SetCenter(x, 0.9, 0.0)
        sphere.SetRadius(0.3)
        sphere.Update()
        spheres.append(sphere.GetOutput())
    blocks.SetBlock(0, spheres[0])
    if hidden != "left out":
        blocks.SetBlock(1, spheres[1])
    mapper = st.composite_mapper()
    mapper.SetInputDataObject(blocks)
    if hidden in ("block", "translucent"):
        attributes = vtkCompositeDataDisplayAttributes()
        if hidden == "block":
            attributes.SetBlockVisibility(spheres[1], False)
        else:
            attributes.SetBlockOpacity(spheres[1], 0.5)
        mapper.SetCompositeDataDisplayAttributes(attributes)
    return [actor_for(mapper)]


def case_hidden_actor(hide=True):
    """A ball, and a second one switched off."""
    actors = case_surface()
    if hide:
        sphere = vtkSphereSource()
        sphere.SetCenter(0.7, 1.0, 0.3)
        sphere.SetRadius(0.3)
        hidden = actor_for(mapper_for(sphere))
        hidden.VisibilityOff()
        actors.append(hidden)
    return actors


def case_hidden_part(hide=True):
    """An assembly of two balls whose second part is switched off."""
    assembly = vtkAssembly()
    for i, x in enumerate((-0.45, 0.45)):
        sphere = vtkSphereSource()
        sphere.SetCenter(x, 0.0, 0.0)
        sphere.SetRadius(0.3)
        part = actor_for(mapper_for(sphere))
        if i == 1:
            if not hide:
                continue
            part.VisibilityOff()
        assembly.AddPart(part)
    assembly.SetPosition(0.0, 0.9, 0.0)
    return [assembly]


def case_shared_mapper():
    """Two actors drawing one mapper's polydata, placed apart: one cached
    mesh, two placements."""
    mapper = mapper_for(ball())
    actors = [actor_for(mapper), actor_for(mapper)]
    actors[0].SetPosition(-0.5, 0.0, 0.0)
    actors[1].SetPosition(0.5, 0.0, -0.2)
    actors[1].SetScale(0.7)
    return actors


def case_mirrored():
    """A closed mesh placed by a mirroring matrix: its faces wind inwards in
    its own coordinates and outwards in the world (VTK lights the faces that
    wind towards the camera; the normals stay as they are)."""
    sphere = ball()
    reverse = vtkReverseSense()
    reverse.SetInputConnection(sphere.GetOutputPort())
    reverse.ReverseCellsOn()
    reverse.ReverseNormalsOff()
    actor = actor_for(mapper_for(reverse))
    actor.SetScale(-1.0, 1.0, 1.0)
    return [actor]


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
HOLLOW = {"hollow": "plate"}
PEELED = {"casts": False, "peeling": True}

CASES = [
    ("surface", case_surface),
    ("surface, under a point light", case_surface, {"point": True}),
    # A plate of 4 x 4 squares, whose shadow is solid; then drawn as lines,
    # whose shadows leave holes (this window resolves 4 x 4, not 8 x 8).
    ("plate", lambda: case_representation(lambda p: None, 4)),
    ("wireframe", lambda: case_representation(lambda p: p.SetRepresentationToWireframe(), 4),
     HOLLOW),
    ("points", lambda: case_representation(
        lambda p: (p.SetRepresentationToPoints(), p.SetPointSize(4))), HOLLOW),
    ("edges", case_edges),
    # VTK lights lines only with normals: these are drawn unlit, shadow or not.
    ("polylines", case_polylines, {"receives": False}),
    ("lines as tubes", lambda: case_representation(
        lambda p: (p.SetRepresentationToWireframe(), p.RenderLinesAsTubesOn(),
                   p.SetLineWidth(3)), 4), HOLLOW),
    ("points as spheres", lambda: case_representation(
        lambda p: (p.SetRepresentationToPoints(), p.RenderPointsAsSpheresOn(),
                   p.SetPointSize(6))), HOLLOW),
    ("sphere imposters", case_sphere_imposters),
    ("stick imposters", case_stick_imposters),
    ("molecule (sphere and stick imposters)", case_molecule),
    ("composite", two_balls),
    ("two actors, one mapper", case_shared_mapper),
    ("mirrored", case_mirrored),
    ("assembly", case_assembly),
    ("axes actor", case_axes),
    ("glyphs", case_glyphs),
    ("glyphs, oriented and scaled", case_oriented_glyphs),
    ("glyphs, indexed sources", case_indexed_glyphs),
    ("glyphs, under a point light", case_glyphs, {"point": True}),
    # What is switched off casts nothing: the picture is the scene's without it.
    ("hidden actor", case_hidden_actor, {"same_as": lambda: case_hidden_actor(False)}),
    ("hidden assembly part", case_hidden_part, {"same_as": lambda: case_hidden_part(False)}),
    ("hidden composite block", lambda: two_balls("block"),
     {"same_as": lambda: two_balls("left out")}),
    # A translucent block receives and casts nothing: the floor is as without it.
    ("translucent composite block", lambda: two_balls("translucent"),
     {"same_as": lambda: two_balls("left out")}),
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
    """A pass by the catalog's name, "technique" or "technique:variant"."""
    base, _, variant = name.partition(":")
    index = vtkShadowTechniqueCatalog.FindTechnique(base)
    shadows = vtkShadowTechniqueCatalog.NewPass(
        index, vtkShadowTechniqueCatalog.FindVariant(index, variant) if variant else -1)
    if base == "reference":
        shadows.SetNumberOfSamples(16)
    return shadows


# Every technique and variant; hard first: the others' shadows are compared
# with its, which VTK's own mappers draw.
TECHNIQUES = ["hard", "hard:sixpass", "reference", "contact:pcf", "contact:gaussian",
              "contact:multipass", "omni:poisson", "omni:pcf4", "omni:hard", "silhouette",
              "silhouette:hard", "smoothies", "aliasfree", "aliasfree:hard"]
# While working on one: COMPATIBILITY_ONLY="aliasfree,glyphs" keeps the
# techniques and cases whose names contain one of those words.
ONLY = [w for w in os.environ.get("COMPATIBILITY_ONLY", "").split(",") if w]


def render(props, name=None, options=None):
    """RGB image (rows bottom first) of the floor, `props` and the light, as
    the case's `options` say (a point light, depth peeling, another view;
    with `viewport`, in a renderer over that part of the window, beside a
    second, empty renderer over the rest)."""
    options = options or {}
    view, viewport = options.get("view"), options.get("viewport")
    renderer = vtkRenderer()
    if viewport:
        renderer.SetViewport(*viewport)
    renderer.SetUseDepthPeeling(options.get("peeling", False))
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
    # A point light (a cone of 90 degrees or more) is shadowed through cube maps.
    light.SetConeAngle(120.0 if options.get("point") else 40.0)
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
    window = WINDOW
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
    # The next picture's renderer takes this one's place: the pass and the
    # mappers let their resources go, as when an application swaps scenes.
    renderers = window.GetRenderers()
    for r in [renderers.GetItemAsObject(i) for i in range(renderers.GetNumberOfItems())]:
        r.ReleaseGraphicsResources(window)
        window.RemoveRenderer(r)
    return result


# One window for every picture: its context's shader cache spares most of
# the compiling a window of its own each would repeat.
WINDOW = vtkRenderWindow()
WINDOW.SetSize(*SIZE)
WINDOW.SetMultiSamples(0)


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

# COMPATIBILITY_ONLY's words pick cases, techniques or both; hard always runs.
case_words = [w for w in ONLY if any(w in case[0] for case in CASES)]
technique_words = [w for w in ONLY if any(w in t for t in TECHNIQUES)]
cases = [c for c in CASES if not case_words or any(w in c[0] for w in case_words)]
techniques = [t for t in TECHNIQUES
              if t == "hard" or not technique_words or any(w in t for w in technique_words)]

failures = []
renders = 0


def render_counted(props, name=None, options=None):
    global renders
    renders += 1
    return brightness(render(props, name, options))


def check_messages(label, expected=None):
    """No error; a warning only where a mapper cannot be shadowed, naming it."""
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


floors = {}      # the floor alone, per camera, viewport and light, plain or per technique
shadows = {}     # each case's floor shadow (a mask) under each technique
start = time.time()
for case, build, *options in cases:
    options = options[0] if options else {}
    # The floor alone, once for each camera, viewport and light the cases use.
    key = (options.get("view"), options.get("viewport"), options.get("point", False))
    look = {k: options[k] for k in ("view", "viewport", "point") if k in options}
    if key not in floors:
        floors[key] = render_counted([], options=look)
    floor_only = floors[key]
    plain = render_counted(build(), options=options)
    actor = np.abs(plain - floor_only) > 3.0
    floor = ~actor & (floor_only > 10.0)
    lit_actor = actor & (plain > 40.0)
    for name in techniques:
        shaded = render_counted(build(), name, options)
        label = "%s, %s" % (case, name)
        if options.get("unlit"):
            # Drawn as plain VTK draws it, pixel for pixel (its lines are black).
            changed = np.mean(np.abs(shaded[actor] - plain[actor]) > 10.0)
            if actor.sum() < 20 or changed > 0.01:
                failures.append("%s: %d pixels, %.1f%% of them not as plain VTK draws them"
                                % (label, actor.sum(), 100 * changed))
            check_messages(label)
            print("%-40s %-17s %.1f%% of %d pixels changed" % (case, name, 100 * changed,
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
        # Casts a shadow on the floor where hard's (VTK's mappers') falls, and
        # leaves the rest of it alone.
        shadow = floor & (shaded < 0.75 * floor_only)
        shadows[(case, name)] = shadow
        casts = options.get("casts", True)
        agreement = "-"
        if casts is True:
            hard = shadows[(case, "hard")]
            agreement = "%.2f" % ((shadow & hard).sum() / max(1, (shadow | hard).sum()))
            if shadow.sum() < 15:
                failures.append("%s: no shadow on the floor (%d pixels)" % (label, shadow.sum()))
            elif float(agreement) < 0.5:
                failures.append("%s: its shadow and hard's share %s of their pixels"
                                % (label, agreement))
        if shadow.sum() > 0.3 * floor.sum():
            failures.append("%s: %.0f%% of the floor darkened" % (label, 100.0 * shadow.mean()))
        # What is drawn as lines or points casts lines' and points' shadows,
        # never the solid surface's of its faces.
        solid = options.get("hollow")
        if solid and (solid, name) in shadows and shadow.sum() > 0.6 * shadows[(solid, name)].sum():
            failures.append("%s: %d shadow pixels, %.0f%% of the solid %s's: a surface that "
                            "is not drawn casts" % (label, shadow.sum(), 100.0 * shadow.sum()
                                                    / max(1, shadows[(solid, name)].sum()),
                                                    solid))
        # What casts nothing darkens nothing: not even an outline.
        if casts is False:
            if (key, name) not in floors:
                floors[(key, name)] = render_counted([], name, look)
            stray = floor & (shaded < floors[(key, name)] - 12.0)
            if stray.sum() > 4:
                failures.append("%s: casts nothing, yet %d floor pixels are darker than "
                                "under %s alone" % (label, stray.sum(), name))
        # Hidden actors and blocks: the floor is as in the scene without them.
        if "same_as" in options:
            alike = render_counted(options["same_as"](), name, options)
            apart = np.sum(floor & (np.abs(alike - shaded) > 12.0))
            if apart > 4:
                failures.append("%s: %d floor pixels differ from the scene without what "
                                "casts nothing"
                                % (label, apart))
        check_messages(label, options.get("warns"))
        # Receives: under the plate, lit pixels go dark (VTK's light has no
        # ambient part here), unlit ones stay.
        receives = options.get("receives", True)
        if receives is not None:
            under = render_counted(build() + [shade()], name, options)
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
        print("%-40s %-17s actor diff %4.1f, %3.0f%% darker; shadow %4d px, %s of hard's; "
              "under a plate %s" % (case, name, np.median(difference), 100 * darkened,
                                    shadow.sum(), agreement,
                                    "-" if receives is None else "%.2f" % kept))

print("%d cases x %d techniques, %d renders in %.0f s" % (len(cases), len(techniques), renders,
                                                       time.time() - start))
if failures:
    print("\n".join("FAIL: " + f for f in failures))
    sys.exit(1)
print("ok: every case under every technique looks as plain VTK draws it, plus its shadow")
