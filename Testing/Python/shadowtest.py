# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Helpers for the numeric shadow tests: scenes whose shadows geometry can
predict, the `softshadows` program, and camera rays matching vtkCamera's.

Images are handled bottom row first, as vtkImageData stores them.
"""

import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

SOFTSHADOWS = os.environ.get("SOFTSHADOWS_EXE", "softshadows")
# Sanitizer builds check this interpreter for memory errors but not leaks
# (CPython leaves objects behind at exit by design); the program it runs is
# checked for leaks too.
PROGRAM_ENV = None
if "SOFTSHADOWS_PROGRAM_ASAN_OPTIONS" in os.environ:
    PROGRAM_ENV = dict(os.environ, ASAN_OPTIONS=os.environ["SOFTSHADOWS_PROGRAM_ASAN_OPTIONS"])

# The ball scene: ground 6 x 6 on y = 0, a ball of radius 0.5 at (0, h, 0),
# a spot light above at LIGHT, camera looking down at 45 degrees.
GROUND_HALF = 3.0
BALL_RADIUS = 0.5
LIGHT = np.array([0.0, 5.0, 0.0])
CAMERA = {"position": [0.0, 6.0, 6.0], "focal_point": [0.0, 0.0, 0.0],
          "view_up": [0.0, 1.0, 0.0], "view_angle": 40.0}


def vtk_version():
    """The VTK release the tests run on, as (major, minor): where releases
    differ in what they can read or draw, the tests say so with it."""
    from vtkmodules.vtkCommonCore import vtkVersion
    return vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()


def composite_mapper():
    """A new mapper of VTK's for composite polydata: vtkCompositePolyDataMapper2
    until VTK 9.3 moved that work into vtkCompositePolyDataMapper (9.5 removed
    the former)."""
    if vtk_version() >= (9, 3):
        from vtkmodules.vtkRenderingCore import vtkCompositePolyDataMapper
        return vtkCompositePolyDataMapper()
    from vtkmodules.vtkRenderingOpenGL2 import vtkCompositePolyDataMapper2
    return vtkCompositePolyDataMapper2()


def ball_scene(height=1.0, light_radius=0.0, technique="hard", params=None,
               size=(240, 180), map_size=1024, light_type="spot"):
    shadows = {"technique": technique, "map_size": map_size}
    if params:
        shadows[technique.split(":")[0]] = params
    return {
        "name": "ball",
        "size": list(size),
        "camera": CAMERA,
        "lights": [{"type": "spot", "position": LIGHT.tolist(),
                    "focal_point": [0, 0, 0], "cone_angle": 45,
                    "radius": light_radius} if light_type == "spot" else
                   {"type": "point", "position": LIGHT.tolist(), "radius": light_radius}],
        "actors": [
            {"source": "plane",
             "params": {"size": [2 * GROUND_HALF, 2 * GROUND_HALF], "resolution": 8}},
            {"source": "sphere", "params": {"radius": BALL_RADIUS, "resolution": 64},
             "position": [0.0, height, 0.0], "color": [0.9, 0.3, 0.25]},
        ],
        "shadows": shadows,
    }


def run(args, check=True):
    """Runs softshadows; returns the CompletedProcess."""
    result = subprocess.run([SOFTSHADOWS] + list(args), capture_output=True, text=True,
                            env=PROGRAM_ENV)
    if check and result.returncode != 0:
        raise AssertionError("softshadows %s failed (%d):\n%s%s" % (
            " ".join(args), result.returncode, result.stdout, result.stderr))
    return result


def read_png(path):
    """Returns an array [rows, columns, components], bottom row first."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    return vtk_to_numpy(scalars).reshape(h, w, scalars.GetNumberOfComponents())


def shadow_only(scene, technique=None, light=0):
    """Renders `scene` with --shadow-only; returns (visibility in [0,1],
    geometry mask), both [rows, columns]."""
    with tempfile.TemporaryDirectory() as folder:
        scene_file = os.path.join(folder, "scene.json")
        with open(scene_file, "w") as f:
            json.dump(scene, f)
        output = os.path.join(folder, "out.png")
        args = ["render", scene_file, "--shadow-only", "--output", output,
                "--light", str(light)]
        if technique:
            args += ["--technique", technique]
        run(args)
        pixels = read_png(output)
    assert pixels.shape[2] == 2, "shadow-only output must be grey+alpha"
    return pixels[:, :, 0] / 255.0, pixels[:, :, 1] == 255


def camera_basis(camera):
    """A perspective vtkCamera with a vertical view angle as (eye, unit
    forward, right and up, tan of half the view angle)."""
    eye = np.array(camera["position"], float)
    forward = np.array(camera["focal_point"], float) - eye
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, np.array(camera["view_up"], float))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    return eye, forward, right, up, math.tan(math.radians(camera["view_angle"]) / 2.0)


def camera_rays(camera, size):
    """Unit ray directions through every pixel centre, [rows, columns, 3],
    for a perspective vtkCamera with a vertical view angle."""
    w, h = size
    _, forward, right, up, half = camera_basis(camera)
    x = ((np.arange(w) + 0.5) / w * 2.0 - 1.0) * half * w / h
    y = ((np.arange(h) + 0.5) / h * 2.0 - 1.0) * half
    rays = forward + x[None, :, None] * right + y[:, None, None] * up
    return rays / np.linalg.norm(rays, axis=2, keepdims=True)


def camera_pixels(camera, size, points):
    """The (row, column) of the pixel nearest each point's image, rows from
    the bottom (as camera_rays and read_png), and whether it is inside the
    picture; the inverse of camera_rays."""
    w, h = size
    eye, forward, right, up, half = camera_basis(camera)
    offsets = np.asarray(points, float) - eye
    depth = offsets @ forward
    column = np.rint(((offsets @ right) / depth / (half * w / h) + 1.0) / 2.0 * w - 0.5)
    row = np.rint(((offsets @ up) / depth / half + 1.0) / 2.0 * h - 0.5)
    inside = (depth > 0) & (column >= 0) & (column < w) & (row >= 0) & (row < h)
    return row.astype(int), column.astype(int), inside


def sphere_hit(origin, rays, center, radius):
    """Ray parameter of the first hit with a sphere, inf where missed."""
    oc = origin - center
    b = rays @ oc
    c = oc @ oc - radius * radius
    disc = b * b - c
    t = -b - np.sqrt(np.maximum(disc, 0.0))
    return np.where((disc > 0) & (t > 0), t, np.inf)


def ground_points(scene):
    """For the ball scene: world points of the visible ground, a mask of the
    pixels showing ground, and the world size of a pixel there."""
    size = scene["size"]
    camera = scene["camera"]
    eye = np.array(camera["position"], float)
    rays = camera_rays(camera, size)
    ball = np.array(scene["actors"][1]["position"], float)
    t_ground = np.where(rays[:, :, 1] < 0, -eye[1] / np.minimum(rays[:, :, 1], -1e-12), np.inf)
    points = eye + t_ground[:, :, None] * rays
    inside = (np.abs(points[:, :, 0]) <= GROUND_HALF) & (np.abs(points[:, :, 2]) <= GROUND_HALF)
    t_ball = sphere_hit(eye, rays, ball, BALL_RADIUS)
    visible = inside & (t_ground < t_ball)
    pixel = t_ground * 2.0 * math.tan(math.radians(camera["view_angle"]) / 2.0) / size[1]
    return points, visible, pixel


def segment_clearance(points, target, center, radius):
    """Distance by which the segments points->target miss the sphere
    (negative: they pass through it)."""
    d = target - points
    length2 = np.sum(d * d, axis=-1)
    s = np.clip(np.sum((center - points) * d, axis=-1) / length2, 0.0, 1.0)
    closest = points + s[..., None] * d
    return np.linalg.norm(closest - center, axis=-1) - radius


def expected_hard_shadow(scene):
    """Ground pixels, whether each is in the ball's hard shadow, and how many
    pixels each lies from the shadow's edge."""
    points, visible, pixel = ground_points(scene)
    ball = np.array(scene["actors"][1]["position"], float)
    clearance = segment_clearance(points, LIGHT, ball, BALL_RADIUS)
    # A clearance at the ball maps onto the ground scaled by the distances.
    scale = np.linalg.norm(points - LIGHT, axis=-1) / np.linalg.norm(ball - LIGHT)
    edge_pixels = np.abs(clearance) * scale / pixel
    return visible, clearance < 0, edge_pixels


def penumbra_width(scene, visibility, low=0.02, high=0.98):
    """World width of the penumbra on the ground line z = 0, x > 0: the
    x-extent of the samples whose visibility lies strictly between `low`
    and `high`. One sample a column: the visible ground pixel nearest z = 0."""
    points, visible, pixel = ground_points(scene)
    z = np.where(visible & (points[:, :, 0] > 0), np.abs(points[:, :, 2]), np.inf)
    rows = np.argmin(z, axis=0)
    columns = np.arange(z.shape[1])
    near = z[rows, columns] < pixel[rows, columns]
    x = points[rows, columns, 0][near]
    v = visibility[rows, columns][near]
    band = (v > low) & (v < high)
    if not band.any():
        return 0.0
    return float(x[band].max() - x[band].min())


HEIGHTS = (0.75, 1.5, 2.25)


def penumbra_widths(technique, light_radius=0.4):
    """penumbra_width() of the ball's shadow by `technique` with the ball at
    each of HEIGHTS, lowest first."""
    widths = []
    for height in HEIGHTS:
        scene = ball_scene(height=height, light_radius=light_radius, technique=technique)
        widths.append(penumbra_width(scene, shadow_only(scene)[0]))
    return widths


def check(condition, message):
    if not condition:
        print("FAIL: " + message)
        sys.exit(1)
    print("ok: " + message)


def surface_ids(scene):
    """Per pixel: 0 background, 1 ground, 2 ball (the ball scene)."""
    camera = scene["camera"]
    eye = np.array(camera["position"], float)
    rays = camera_rays(camera, scene["size"])
    points, ground, _ = ground_points(scene)
    ball = np.array(scene["actors"][1]["position"], float)
    ids = np.where(ground, 1, 0)
    ids[np.isfinite(sphere_hit(eye, rays, ball, BALL_RADIUS))] = 2
    return ids


def quality_mask(scene):
    """SPEC's pixels for measuring quality: geometry lit from the front
    (N.L >= 0.1), inside 0.9 of the spot cone, away from silhouettes."""
    camera = scene["camera"]
    eye = np.array(camera["position"], float)
    rays = camera_rays(camera, scene["size"])
    ids = surface_ids(scene)
    ball = np.array(scene["actors"][1]["position"], float)
    t_ball = sphere_hit(eye, rays, ball, BALL_RADIUS)
    points, _, _ = ground_points(scene)
    ball_points = eye + np.where(np.isfinite(t_ball), t_ball, 0.0)[:, :, None] * rays
    position = np.where((ids == 2)[:, :, None], ball_points, points)
    normal = np.where((ids == 2)[:, :, None], (ball_points - ball) / BALL_RADIUS,
                      np.array([0.0, 1.0, 0.0]))
    to_light = LIGHT - position
    to_light /= np.linalg.norm(to_light, axis=2, keepdims=True)
    n_dot_l = np.sum(normal * to_light, axis=2)
    axis = np.array([0.0, -1.0, 0.0])
    if scene["lights"][0]["type"] == "spot":
        cone = scene["lights"][0]["cone_angle"]
        inside = np.sum(-to_light * axis, axis=2) >= math.cos(math.radians(0.9 * cone))
    else:
        inside = np.ones_like(n_dot_l, dtype=bool)
    same = np.ones_like(ids, dtype=bool)
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        same &= np.roll(np.roll(ids, dy, axis=0), dx, axis=1) == ids
    return (ids > 0) & (n_dot_l >= 0.1) & inside & same


def rmse(a, b, mask):
    return float(np.sqrt(np.mean((a[mask] - b[mask]) ** 2)))


def post_scene(light_radius=0.4, technique="contact", size=(240, 180)):
    """A square post standing on the ground, lit from +x: its shadow runs
    along -x from the post's base, which it touches."""
    return {
        "name": "post",
        "size": list(size),
        "camera": CAMERA,
        "lights": [{"type": "spot", "position": [3.0, 5.0, 0.0], "focal_point": [0, 0, 0],
                    "cone_angle": 45, "radius": light_radius}],
        "actors": [
            {"source": "plane",
             "params": {"size": [2 * GROUND_HALF, 2 * GROUND_HALF], "resolution": 8}},
            {"source": "cube", "params": {"size": [0.3, 1.5, 0.3]},
             "position": [0.0, 0.75, 0.0]},
        ],
        "shadows": {"technique": technique, "map_size": 1024},
    }


def edge_width_pixels(scene, visibility, x0, low=0.02, high=0.98):
    """Width in pixels of the penumbra across the shadow's +z edge at x = x0:
    the z-extent of ground samples near x0 with visibility strictly between
    `low` and `high`, over the pixel size there. The post hides nothing at
    z > 0.15 from the camera."""
    points, visible, pixel = ground_points(scene)
    near = visible & (np.abs(points[:, :, 0] - x0) < pixel) & (points[:, :, 2] > 0.16) \
        & (points[:, :, 2] < 1.5)
    z = points[:, :, 2][near]
    v = visibility[near]
    band = (v > low) & (v < high)
    if not band.any():
        return 0.0
    return float((z[band].max() - z[band].min()) / np.median(pixel[near]))


def ray_box(origin, rays, lo, hi):
    """Slab test: entry and exit ray parameters of an axis-aligned box
    (entry > exit where missed)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        inverse = 1.0 / rays
        t0 = (np.asarray(lo) - origin) * inverse
        t1 = (np.asarray(hi) - origin) * inverse
    near = np.nanmax(np.minimum(t0, t1), axis=-1)
    far = np.nanmin(np.maximum(t0, t1), axis=-1)
    return near, far


def segment_hits_box(points, target, lo, hi):
    """Whether the segments points -> target pass through a box."""
    d = target - points
    near, far = ray_box(points, d, lo, hi)
    return (near <= far) & (far > 0.0) & (near < 1.0)


# The room: a closed 8^3 box around a point light at the origin, one occluder
# towards each of the six walls.
ROOM_HALF = 4.0
ROOM_BOXES = [((1.6, 0, 0), (0.9, 0.3, 0.3)), ((-1.6, 0, 0), (0.3, 0.9, 0.9)),
              ((0, 1.6, 0), (0.3, 0.9, 0.3)), ((0, 0, 1.6), (0.9, 0.9, 0.3)),
              ((0, 0, -1.6), (0.3, 0.3, 0.9))]
ROOM_BALL = ((0.0, -1.6, 0.0), 0.4)
BOX_HALF = 0.3


def room_scene(camera, light_radius=0.0, technique="hard", size=(240, 180)):
    actors = [{"source": "cube", "params": {"size": [2 * ROOM_HALF] * 3}, "color": [0.9] * 3}]
    for position, color in ROOM_BOXES:
        actors.append({"source": "cube", "params": {"size": [2 * BOX_HALF] * 3},
                       "position": list(position), "color": list(color)})
    actors.append({"source": "sphere", "params": {"radius": ROOM_BALL[1]},
                   "position": list(ROOM_BALL[0]), "color": [0.9, 0.6, 0.2]})
    return {"name": "room", "size": list(size), "camera": camera,
            "lights": [{"type": "point", "position": [0.0, 0.0, 0.0], "radius": light_radius}],
            "actors": actors, "shadows": {"technique": technique, "map_size": 512}}


def room_expected(scene):
    """Per pixel: whether it shows a wall, the wall point, and whether the
    point light is hidden from it."""
    camera = scene["camera"]
    eye = np.array(camera["position"], float)
    rays = camera_rays(camera, scene["size"])
    _, t_wall = ray_box(eye, rays, [-ROOM_HALF] * 3, [ROOM_HALF] * 3)
    t_first = t_wall.copy()
    for position, _ in ROOM_BOXES:
        p = np.array(position)
        near, far = ray_box(eye, rays, p - BOX_HALF, p + BOX_HALF)
        t_first = np.where((near <= far) & (near > 0), np.minimum(t_first, near), t_first)
    t_first = np.minimum(t_first, sphere_hit(eye, rays, np.array(ROOM_BALL[0]), ROOM_BALL[1]))
    wall = t_wall <= t_first
    points = eye + t_wall[:, :, None] * rays
    light = np.zeros(3)
    hidden = segment_clearance(points, light, np.array(ROOM_BALL[0]), ROOM_BALL[1]) < 0
    for position, _ in ROOM_BOXES:
        p = np.array(position)
        hidden |= segment_hits_box(points, light, p - BOX_HALF, p + BOX_HALF)
    return wall, points, hidden


def interior(mask, margin):
    """Pixels whose (2 margin + 1)^2 neighbourhood lies entirely in mask."""
    result = mask.copy()
    for dy in range(-margin, margin + 1):
        for dx in range(-margin, margin + 1):
            result &= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
    return result


def truth(scene, light=0, samples=256):
    """The ray-cast ground truth (`softshadows truth`): (visibility in
    [0,1], geometry, SPEC's quality mask), each [rows, columns]."""
    with tempfile.TemporaryDirectory() as folder:
        scene_file = os.path.join(folder, "scene.json")
        with open(scene_file, "w") as f:
            json.dump(scene, f)
        output = os.path.join(folder, "truth.png")
        mask = os.path.join(folder, "mask.png")
        run(["truth", scene_file, "--output", output, "--mask", mask, "--light", str(light),
             "--samples", str(samples)])
        pixels = read_png(output)
        measured = read_png(mask)[:, :, 0] == 255
    return pixels[:, :, 0] / 255.0, pixels[:, :, 1] == 255, measured


def disc_overlap(r1, r2, d):
    """Area where two discs of radii r1, r2 with centres d apart overlap."""
    r1, r2, d = np.broadcast_arrays(np.asarray(r1, float), np.asarray(r2, float),
                                    np.asarray(d, float))
    small = np.minimum(r1, r2)
    area = np.where(d <= np.abs(r1 - r2), math.pi * small * small, 0.0)
    lens = (d < r1 + r2) & (d > np.abs(r1 - r2))
    with np.errstate(invalid="ignore", divide="ignore"):
        a1 = np.arccos(np.clip((d * d + r1 * r1 - r2 * r2) / (2 * d * r1), -1, 1))
        a2 = np.arccos(np.clip((d * d + r2 * r2 - r1 * r1) / (2 * d * r2), -1, 1))
        k = np.sqrt(np.maximum((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2), 0))
        lens_area = r1 * r1 * a1 + r2 * r2 * a2 - 0.5 * k
    return np.where(lens, lens_area, area)


def past_ball(points, center, to_light, alpha, ball_radius=BALL_RADIUS):
    """What each of `points` sees of a light of angular radius `alpha`
    towards the unit directions `to_light`, past a ball: 1 - the share of the
    light's disc the ball's disc covers (angular radii; the small-angle plane
    of directions)."""
    to_ball = np.asarray(center, float) - points
    ball_distance = np.linalg.norm(to_ball, axis=-1)
    beta = np.arcsin(ball_radius / ball_distance)
    cosine = np.sum(to_light * to_ball, axis=-1) / ball_distance
    gamma = np.arccos(np.clip(cosine, -1.0, 1.0))
    covered = disc_overlap(alpha, beta, gamma) / (math.pi * alpha * alpha)
    return 1.0 - np.clip(covered, 0.0, 1.0)


def ball_light_visibility(points, center, light_position, light_radius, ball_radius=BALL_RADIUS):
    """past_ball() for a spherical light of `light_radius` at `light_position`."""
    to_light = np.asarray(light_position, float) - points
    distance = np.linalg.norm(to_light, axis=-1)
    return past_ball(points, center, to_light / distance[..., None],
                     np.arcsin(light_radius / distance), ball_radius)


def ball_visibility(scene):
    """Closed form of the ball scene's ground visibility (past_ball()).
    Spot and point lights: a sphere of `radius`; directional: a cone of
    that many degrees around `direction`."""
    points, visible, _ = ground_points(scene)
    ball = scene["actors"][1]["position"]
    light = scene["lights"][0]
    if light["type"] != "directional":
        return ball_light_visibility(points, ball, light["position"], light["radius"]), visible
    to_light = -np.array(light["direction"], float)
    to_light = np.broadcast_to(to_light / np.linalg.norm(to_light), points.shape)
    alpha = np.full(points.shape[:2], math.radians(light["radius"]))
    return past_ball(points, ball, to_light, alpha), visible


# Meshes a silhouette-based technique's topology can describe only in part,
# each floating over the ground under the light: an open sheet (its border
# edges always on the silhouette), three fins on one edge (non-manifold) and
# a sheet with zero-area faces.
ODD_MESHES = {
    "sheet": "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\nf 1 2 3\nf 1 3 4\n",
    "fins": "v -0.5 0 0\nv 0.5 0 0\nv 0 0.4 0\nv 0 -0.3 0.4\nv 0 -0.3 -0.4\n"
            "f 1 2 3\nf 2 1 4\nf 1 2 5\n",
    "degenerate": "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\nv 0 0 0\n"
                  "f 1 2 3\nf 1 3 4\nf 1 5 3\nf 5 5 2\n",
}


def check_odd_meshes(technique):
    """Each of ODD_MESHES drawn by `technique` without an error; the two
    sheets shadow the ground beneath them and not beside them."""
    with tempfile.TemporaryDirectory() as folder:
        for name, text in ODD_MESHES.items():
            path = os.path.join(folder, name + ".obj")
            with open(path, "w") as f:
                f.write(text)
            scene = ball_scene(height=1.0, light_radius=0.1, technique=technique)
            scene["actors"][1] = {"file": path, "position": [0.0, 1.0, 0.0]}
            scene_file = os.path.join(folder, name + ".json")
            with open(scene_file, "w") as f:
                json.dump(scene, f)
            output = os.path.join(folder, name + ".png")
            result = run(["render", scene_file, "--shadow-only", "--output", output])
            check("ERR" not in result.stderr and "rror" not in result.stderr,
                  "%s, %s: drawn without an error%s" % (technique, name, (
                      ": " + result.stderr[:300]) if result.stderr else ""))
            if name in ("sheet", "degenerate"):
                visibility = read_png(output)[:, :, 0] / 255.0
                points, visible, _ = ground_points(scene)
                # The sheet at y = 1 under the light at y = 5 shadows |x|, |z| < 0.625.
                under = visible & (np.abs(points[:, :, 0]) < 0.4) & (np.abs(points[:, :, 2]) < 0.4)
                beside = visible & (np.maximum(np.abs(points[:, :, 0]),
                                               np.abs(points[:, :, 2])) > 1.0)
                check(visibility[under].max() < 0.1 and visibility[beside].min() > 0.9,
                      "%s, %s: shadowed beneath (brightest %.2f), lit beside (darkest %.2f)"
                      % (technique, name, visibility[under].max(), visibility[beside].min()))


def add_ground_and_ball(renderer, ball_resolution=None, casters=()):
    """The ground (6 x 6 at y = 0) and the ball (radius 0.5 at (0, 1, 0)) as
    actors of `renderer`, then `casters` (more polydata or sources)."""
    from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

    def add(data):
        mapper = vtkPolyDataMapper()
        if hasattr(data, "GetOutputPort"):
            mapper.SetInputConnection(data.GetOutputPort())
        else:
            mapper.SetInputData(data)
        a = vtkActor()
        a.SetMapper(mapper)
        renderer.AddActor(a)

    plane = vtkPlaneSource()
    plane.SetOrigin(-3, 0, -3)
    plane.SetPoint1(3, 0, -3)
    plane.SetPoint2(-3, 0, 3)
    add(plane)
    ball = vtkSphereSource()
    ball.SetCenter(0, 1, 0)
    ball.SetRadius(0.5)
    if ball_resolution:
        ball.SetThetaResolution(ball_resolution)
        ball.SetPhiResolution(ball_resolution)
    add(ball)
    for data in casters:
        add(data)


def spot_light(x=0.0, radius=0.3):
    """A spot light at (x, 5, 0) aimed at the origin, 45 degrees, of `radius`."""
    from vtkmodules.vtkRenderingCore import vtkLight
    from vtksoftshadows import vtkSoftShadowPass

    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(x, 5, 0)
    light.SetFocalPoint(0, 0, 0)
    light.SetConeAngle(45)
    vtkSoftShadowPass.SetRadius(radius, light)
    return light


def api_ball(pass_class, light_radius=0.3, light_x=0.0, ball_resolution=None, casters=()):
    """The ball over the ground through the Python API, drawn shadow-only by
    a `pass_class` pass into a 200 x 150 off-screen window, under a spot
    light at (light_x, 5, 0); `casters`: more polydata among the casters.
    Returns (window, light, pass)."""
    from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory)

    renderer = vtkRenderer()
    add_ground_and_ball(renderer, ball_resolution, casters)
    light = spot_light(light_x, light_radius)
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 6, 6)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCameraClippingRange()
    shadows = pass_class()
    shadows.SetShadowOnlyLight(0)
    renderer.SetPass(shadows)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(200, 150)
    window.AddRenderer(renderer)
    return window, light, shadows


def grab_red(window):
    """The window's red channel as drawn (no new frame), bottom row first."""
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()
    grab.Update()
    width, height = window.GetSize()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, 0].reshape(height, width)


def render_line_casters(pass_class, with_lines):
    """The ball over the ground through the Python API (api_ball), with
    (`with_lines`) a polyline and a polyvertex beside the ball among the
    casters: casters without faces, which scene files refuse. Returns (the
    red channel, bottom row first; the pass's errors and warnings; the
    pass)."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    casters = []
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
            casters.append(data)
    window, _, shadows = api_ball(pass_class, casters=casters)
    errors = []
    shadows.AddObserver(vtkCommand.ErrorEvent, lambda *args: errors.append(args))
    shadows.AddObserver(vtkCommand.WarningEvent, lambda *args: errors.append(args))
    window.Render()
    return grab_red(window), errors, shadows
