"""The `silhouette` technique (Valient & Bujnak): anti-aliased hard shadows
where geometry puts them, closer to an exact hard shadow than `hard` at the
same map size; soft penumbrae from the light's radius that widen with the
occluder's height and stay hard at contact, close to the ray-cast truth (on
other scenes: test_quality.py); and meshes the topology aware mesh cannot
fully describe (open sheets, non-manifold edges, degenerate faces, lines and
points) drawn without an error."""
import copy
import json
import os
import tempfile

import numpy as np

import shadowtest as st

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "..", "Examples", "Scenes", "quality")

# The hard variant's shadow where geometry says: away from its edge every
# ground pixel is in the ball's shadow exactly when the segment to the light
# passes through the ball.
scene = st.ball_scene(height=1.0, light_radius=0.0, technique="silhouette:hard", map_size=512)
visibility, _ = st.shadow_only(scene)
visible, shadowed, edge = st.expected_hard_shadow(scene)
away = visible & (edge > 1.5)
wrong = float(((visibility < 0.5) != shadowed)[away].mean())
st.check(shadowed[away].sum() > 500 and wrong < 0.001,
         "silhouette:hard: the ball's shadow where geometry says (%.3f%% of %d pixels wrong)"
         % (100 * wrong, away.sum()))

# Anti-aliasing against an exact hard shadow (ray casting, one ray a pixel),
# at a 512^2 map: a curved occluder and thin slats, RMSE and mismatch at
# most half of `hard`'s.
with open(os.path.join(SCENES, "grate.json")) as f:
    grate = json.load(f)
grate["lights"][0]["radius"] = 0.0
grate["size"] = [480, 360]  # the quality scenes' own size
grate["shadows"] = {"technique": "hard", "map_size": 512}
ball = st.ball_scene(height=1.0, light_radius=0.0, size=(320, 240), map_size=512)
for name, scene in (("ball", ball), ("grate", grate)):
    truth, _, mask = st.truth(scene, samples=1)
    figures = {}
    for technique in ("hard", "silhouette:hard"):
        visibility, _ = st.shadow_only(scene, technique)
        figures[technique] = (st.rmse(visibility, truth, mask),
                              float((np.abs(visibility - truth) > 0.5)[mask].mean()))
        print("%s, exact hard shadow: %-16s RMSE %.4f, mismatch %.3f%%"
              % (name, technique, figures[technique][0], 100 * figures[technique][1]))
    (rmse, mismatch), (hard_rmse, hard_mismatch) = figures["silhouette:hard"], figures["hard"]
    st.check(rmse <= 0.5 * hard_rmse and mismatch <= 0.5 * hard_mismatch,
             "%s: silhouette:hard at most half of hard's error against the exact shadow (RMSE "
             "%.4f vs %.4f, mismatch %.3f%% vs %.3f%%)"
             % (name, rmse, hard_rmse, 100 * mismatch, 100 * hard_mismatch))

# Soft: the penumbra widens as the ball rises, and against the ray-cast
# truth the error is well under hard's.
radius = 0.4
widths = []
for height in (0.75, 1.5, 2.25):
    scene = st.ball_scene(height=height, light_radius=radius, technique="silhouette")
    visibility, _ = st.shadow_only(scene)
    widths.append(st.penumbra_width(scene, visibility))
    truth, _, mask = st.truth(scene)
    errors = {t: st.rmse(st.shadow_only(scene, t)[0], truth, mask) for t in ("hard", "silhouette")}
    print("height %.2f: penumbra %.3f; RMSE silhouette %.4f, hard %.4f"
          % (height, widths[-1], errors["silhouette"], errors["hard"]))
    st.check(errors["silhouette"] < 0.4 * errors["hard"],
             "height %.2f: silhouette under 0.4 of hard's error against the truth (%.4f, %.4f)"
             % (height, errors["silhouette"], errors["hard"]))
st.check(widths[0] < widths[1] < widths[2], "silhouette penumbra widens as the ball rises: %s"
         % np.round(widths, 3).tolist())

# Where the occluder touches the receiver the edge stays hard; farther out
# it softens.
scene = st.post_scene(light_radius=radius, technique="silhouette")
visibility, _ = st.shadow_only(scene)
at_base = st.edge_width_pixels(scene, visibility, -0.2)
far_out = st.edge_width_pixels(scene, visibility, -1.4)
print("post: edge %.1f px at the base, %.1f px far out" % (at_base, far_out))
st.check(at_base <= 2.0, "at contact the edge is hard: %.1f px wide" % at_base)
st.check(far_out > at_base + 2.0, "away from contact it softens: %.1f px" % far_out)

# Meshes a topology aware mesh describes only in part, each floating over
# the ground under the light: an open sheet (its border edges always on the
# silhouette), three fins on one edge (non-manifold) and a sheet with
# zero-area faces. No error; the sheets shadow the ground beneath them.
MESHES = {
    "sheet": "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\nf 1 2 3\nf 1 3 4\n",
    "fins": "v -0.5 0 0\nv 0.5 0 0\nv 0 0.4 0\nv 0 -0.3 0.4\nv 0 -0.3 -0.4\n"
            "f 1 2 3\nf 2 1 4\nf 1 2 5\n",
    "degenerate": "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\nv 0 0 0\n"
                  "f 1 2 3\nf 1 3 4\nf 1 5 3\nf 5 5 2\n",
}
with tempfile.TemporaryDirectory() as folder:
    for name, text in MESHES.items():
        path = os.path.join(folder, name + ".obj")
        with open(path, "w") as f:
            f.write(text)
        scene = st.ball_scene(height=1.0, light_radius=0.1, technique="silhouette")
        scene["actors"][1] = {"file": path, "position": [0.0, 1.0, 0.0]}
        scene_file = os.path.join(folder, name + ".json")
        with open(scene_file, "w") as f:
            json.dump(scene, f)
        output = os.path.join(folder, name + ".png")
        result = st.run(["render", scene_file, "--shadow-only", "--output", output])
        st.check("ERR" not in result.stderr and "rror" not in result.stderr,
                 "%s: drawn without an error%s" % (name, (": " + result.stderr[:300])
                                                   if result.stderr else ""))
        if name in ("sheet", "degenerate"):
            pixels = st.read_png(output)
            visibility = pixels[:, :, 0] / 255.0
            points, visible, _ = st.ground_points(scene)
            # The sheet at y = 1 under the light at y = 5 shadows |x|, |z| < 0.625.
            under = visible & (np.abs(points[:, :, 0]) < 0.4) & (np.abs(points[:, :, 2]) < 0.4)
            beside = visible & (np.maximum(np.abs(points[:, :, 0]), np.abs(points[:, :, 2])) > 1.0)
            st.check(visibility[under].max() < 0.1 and visibility[beside].min() > 0.9,
                     "%s: shadowed beneath (brightest %.2f), lit beside (darkest %.2f)"
                     % (name, visibility[under].max(), visibility[beside].min()))

# Casters without faces (scene files refuse them; the API does not): lines
# and points beside the ball cast their depth-map shadow only, with no error,
# and the ball's shadow is unchanged.
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory)
from vtksoftshadows import vtkSilhouetteShadowPass


def add(renderer, data):
    mapper = vtkPolyDataMapper()
    if hasattr(data, "GetOutputPort"):
        mapper.SetInputConnection(data.GetOutputPort())
    else:
        mapper.SetInputData(data)
    a = vtkActor()
    a.SetMapper(mapper)
    renderer.AddActor(a)


def render(with_lines):
    renderer = vtkRenderer()
    plane = vtkPlaneSource()
    plane.SetOrigin(-3, 0, -3)
    plane.SetPoint1(3, 0, -3)
    plane.SetPoint2(-3, 0, 3)
    add(renderer, plane)
    ball = vtkSphereSource()
    ball.SetCenter(0, 1, 0)
    ball.SetRadius(0.5)
    add(renderer, ball)
    if with_lines:
        for kind in ("lines", "points"):
            points = vtkPoints()
            cells = vtkCellArray()
            for i in range(5):
                points.InsertNextPoint(1.5, 0.5 + 0.2 * i, -1.0 + 0.5 * i)
            cells.InsertNextCell(5, list(range(5)))
            data = vtkPolyData()
            data.SetPoints(points)
            data.SetLines(cells) if kind == "lines" else data.SetVerts(cells)
            add(renderer, data)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(0, 5, 0)
    light.SetFocalPoint(0, 0, 0)
    light.SetConeAngle(45)
    vtkSilhouetteShadowPass.SetRadius(0.3, light)
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 6, 6)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCameraClippingRange()
    shadows = vtkSilhouetteShadowPass()
    shadows.SetShadowOnlyLight(0)
    renderer.SetPass(shadows)
    errors = []
    shadows.AddObserver(vtkCommand.ErrorEvent, lambda *args: errors.append(args))
    shadows.AddObserver(vtkCommand.WarningEvent, lambda *args: errors.append(args))
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(200, 150)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, 0].reshape(150, 200)
    return image, errors, shadows


plain, _, _ = render(False)
image, errors, shadows = render(True)
st.check(not errors, "lines and points among the casters: no error or warning (%d)" % len(errors))
st.check(shadows.GetTopologyAwareMeshBytes() > 0,
         "the ball's topology aware mesh is on the GPU: %d bytes" % shadows.GetTopologyAwareMeshBytes())
ball_shadow = plain < 20
st.check(ball_shadow.sum() > 100 and (image[ball_shadow] < 20).all(),
         "the ball's shadow is unchanged by the line and point casters (%d pixels)"
         % ball_shadow.sum())
