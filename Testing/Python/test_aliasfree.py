# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The `aliasfree` technique (Sintorn, Eisemann & Assarsson), measured
against the ray-cast truth: hard shadows that match an exact hard shadow at
any map size, with no bias at all; soft shadows near the truth of a
spherical light on a ball, a fence, a knot and a self-shadowing blob, for
every number of light samples, under spot, point and directional lights,
and inside a room and an L-shaped one under point lights; penumbrae that widen as the ball rises;
light shapes and their scaling; penumbrae restricted to the silhouettes as
computed everywhere; temporal jitter converging while nothing moves; bent
normals smoothing a coarse sphere's terminator; bad
cases (a light inside a caster, a frame over its memory limit, a 2048x2048
window, a million-triangle caster, no lights, odd meshes) drawn with clear
errors or right images."""
import copy
import json
import os
import tempfile
import time

import numpy as np

import shadowtest as st

SIZE = (320, 240)


def fence_scene(light_radius=0.3):
    scene = st.ball_scene(light_radius=light_radius, technique="aliasfree", size=SIZE)
    scene["lights"] = [{"type": "spot", "position": [0.5, 4.0, -4.0], "focal_point": [0, 0, 0.5],
                        "cone_angle": 40, "radius": light_radius}]
    scene["camera"] = {"position": [0.0, 4.5, 5.0], "focal_point": [0.0, 0.3, 0.2],
                       "view_up": [0.0, 1.0, 0.0], "view_angle": 35.0}
    scene["actors"][1] = {"source": "fence", "params": {"pickets": 9, "height": 1.2},
                          "position": [0.0, 0.0, -1.0]}
    return scene


def knot_scene(light_radius=0.3):
    scene = st.ball_scene(light_radius=light_radius, technique="aliasfree", size=SIZE)
    scene["actors"][1] = {"source": "knot", "params": {"ring_radius": 0.6, "tube_radius": 0.12},
                          "position": [0.0, 1.1, 0.0], "orientation": [20, 0, 0]}
    return scene


def quality_scene(name):
    path = os.path.join(os.path.dirname(__file__), "..", "..", "Examples", "Scenes", "quality",
                        name + ".json")
    with open(path) as f:
        scene = json.load(f)
    scene["size"] = list(SIZE)
    scene["shadows"] = {"technique": "aliasfree"}
    return scene


def blob_scene(light_radius=0.3):
    scene = quality_scene("blob")
    scene["lights"][0]["radius"] = light_radius
    return scene


def scenes(light_radius):
    ball = st.ball_scene(height=1.0, light_radius=light_radius, technique="aliasfree", size=SIZE)
    return {"ball": ball, "fence": fence_scene(light_radius), "knot": knot_scene(light_radius),
            "blob": blob_scene(light_radius)}


def with_map(scene, map_size, params=None):
    scene = copy.deepcopy(scene)
    scene["shadows"]["map_size"] = map_size
    if params:
        scene["shadows"]["aliasfree"] = params
    return scene


# 1. Hard: against the exact hard shadow (radius 0, ray cast), mismatching
# pixels below 0.2% at 256^2 and 1024^2 maps, where `hard` aliases.
for name, scene in scenes(0.0).items():
    truth, _, mask = st.truth(scene, samples=16)
    lit = truth > 0.5
    for map_size in (256, 1024):
        scene = with_map(scene, map_size)
        mismatch = {}
        for technique in ("aliasfree:hard", "hard"):
            visibility, _ = st.shadow_only(scene, technique)
            mismatch[technique] = float(((visibility > 0.5) != lit)[mask].mean())
        print("%s, %d^2: mismatching pixels: aliasfree:hard %.4f%%, hard %.4f%%"
              % (name, map_size, 100 * mismatch["aliasfree:hard"], 100 * mismatch["hard"]))
        st.check(mismatch["aliasfree:hard"] < 0.002 and
                 mismatch["aliasfree:hard"] < mismatch["hard"],
                 "%s, %d^2 map: alias-free hard shadows match the exact one (%.4f%% of pixels "
                 "differ, hard %.4f%%)" % (name, map_size, 100 * mismatch["aliasfree:hard"],
                                          100 * mismatch["hard"]))

# A point light: its six cube faces each list their own samples.
scene = st.ball_scene(height=1.0, light_radius=0.0, technique="aliasfree:hard", size=SIZE,
                      light_type="point")
truth, _, mask = st.truth(scene, samples=16)
visibility, _ = st.shadow_only(scene)
mismatch = float(((visibility > 0.5) != (truth > 0.5))[mask].mean())
st.check(mismatch < 0.002, "point light: alias-free hard shadows match the exact one (%.4f%% of "
         "pixels differ)" % (100 * mismatch))

# No bias at all: the shadow-map biases change nothing the camera sees.
for variant, radius in (("hard", 0.0), ("soft", 0.4)):
    scene = st.ball_scene(height=1.0, light_radius=radius, technique="aliasfree:" + variant,
                          size=SIZE)
    default, _ = st.shadow_only(scene)
    scene["shadows"]["aliasfree"] = {"slope_scaled_bias": 0.0, "constant_bias": 0.0,
                                     "normal_bias": 0.0}
    unbiased, _ = st.shadow_only(scene)
    st.check(np.array_equal(default, unbiased),
             "%s: no bias parameter plays a part (the image with every bias 0 is the same)"
             % variant)

# 2. Soft: RMSE against the truth of a spherical light below 0.015 with 256
# light samples, and under half of hard's, on each scene.
for name, scene in scenes(0.3).items():
    if name == "ball":
        scene = st.ball_scene(height=1.0, light_radius=0.4, technique="aliasfree", size=SIZE)
    truth, _, mask = st.truth(scene, samples=256)
    errors = {t: st.rmse(st.shadow_only(scene, t)[0], truth, mask) for t in ("aliasfree", "hard")}
    print("%s: RMSE against the truth: aliasfree %.4f, hard %.4f (%.2f)"
          % (name, errors["aliasfree"], errors["hard"], errors["aliasfree"] / errors["hard"]))
    st.check(errors["aliasfree"] < 0.015 and errors["aliasfree"] < 0.5 * errors["hard"],
             "%s: soft shadows within 0.015 of the truth and under half hard's error "
             "(%.4f, hard %.4f)" % (name, errors["aliasfree"], errors["hard"]))

# The closed form of the ball's ground visibility, under a spot light, a
# point light (six cube faces) and a directional light of 5 degrees.
for light_type in ("spot", "point", "directional"):
    scene = st.ball_scene(height=1.0, light_radius=0.4, technique="aliasfree", size=SIZE,
                          light_type="point" if light_type == "point" else "spot")
    if light_type == "directional":
        scene["lights"] = [{"type": "directional", "direction": [-0.3, -1.0, -0.2],
                            "radius": 5.0}]
    visibility, _ = st.shadow_only(scene)
    exact, visible = st.ball_visibility(scene)
    error = st.rmse(visibility, exact, visible)
    st.check(error < 0.015, "%s light: the ground's visibility as the closed form gives it "
             "(RMSE %.4f)" % (light_type, error))

# Inside a room, a point light: no wall pixel dark that the truth lights.
# Walls far from a small caster lie almost in the planes of some of its
# triangles, where the planes through a wall point and the triangle's edges
# nearly coincide; oriented one by one, by rounding, they once hid the
# whole light from isolated wall pixels.
scene = quality_scene("room")
truth, _, mask = st.truth(scene, samples=64)
visibility, _ = st.shadow_only(scene)
specks = int(((truth > 0.9) & (visibility < 0.1))[mask].sum())
error = st.rmse(visibility, truth, mask)
st.check(specks == 0 and error < 0.015, "room, point light: no pixel in shadow that the truth "
         "lights (%d), RMSE %.4f" % (specks, error))

# Inside an L-shaped room (closed, not convex), a point light in one arm:
# the inner corner's shadow across the other. A closed caster hides a
# sample only from its outer side, and every blocked segment from a sample
# inside to the light re-enters the room through a face it sees from that
# side: soft near the truth, hard matching the exact shadow.
L_ROOM = [(-3, -3), (3, -3), (3, 0), (0, 0), (0, 3), (-3, 3)]
with tempfile.TemporaryDirectory() as folder:
    obj = os.path.join(folder, "lroom.obj")
    with open(obj, "w") as f:
        for y in (-1.5, 2.5):
            f.writelines("v %g %g %g\n" % (x, y, z) for x, z in L_ROOM)
        n = len(L_ROOM)
        f.write("f %s\n" % " ".join(str(i + 1) for i in reversed(range(n))))
        f.write("f %s\n" % " ".join(str(n + i + 1) for i in range(n)))
        for i in range(n):
            j = (i + 1) % n
            f.write("f %d %d %d %d\n" % (i + 1, j + 1, n + j + 1, n + i + 1))
    scene = {"name": "lroom", "size": list(SIZE),
             "camera": {"position": [-2.5, 1.8, -2.5], "focal_point": [-1.0, -1.0, 1.5],
                        "view_angle": 70},
             "lights": [{"type": "point", "position": [2.0, 0.5, -2.0], "radius": 0.2}],
             "actors": [{"file": obj, "color": [0.9, 0.9, 0.9]}],
             "shadows": {"technique": "aliasfree"}}
    truth, _, mask = st.truth(scene, samples=64)
    error = st.rmse(st.shadow_only(scene)[0], truth, mask)
    scene["lights"][0]["radius"] = 0.0
    exact, _, mask = st.truth(scene, samples=1)
    hard, _ = st.shadow_only(scene, "aliasfree:hard")
    mismatch = float(((hard > 0.5) != (exact > 0.5))[mask].mean())
st.check(error < 0.015 and mismatch < 0.002 and (exact < 0.5)[mask].mean() > 0.1,
         "inside an L-shaped room: soft RMSE %.4f, hard %.3f%% of pixels off the exact shadow"
         % (error, 100 * mismatch))

# Every number of light samples, on the ball.
scene = st.ball_scene(height=1.0, light_radius=0.4, technique="aliasfree", size=SIZE)
truth, _, mask = st.truth(scene, samples=1024)
errors = {}
for count in (128, 256, 512, 1024):
    errors[count] = st.rmse(st.shadow_only(with_map(scene, 1024, {"light_samples": count}))[0],
                            truth, mask)
print("RMSE by light samples: %s" % {k: round(v, 4) for k, v in errors.items()})
st.check(max(errors.values()) < 0.015 and errors[1024] <= errors[128],
         "128 to 1024 light samples all within 0.015 of the truth, 1024 no worse than 128 (%s)"
         % {k: round(v, 4) for k, v in errors.items()})

# Penumbra work restricted to the silhouette edges' influence regions, or
# done everywhere: the same shadows (the fence: borders and thin slats).
for name, scene in (("ball", st.ball_scene(height=1.0, light_radius=0.4, technique="aliasfree",
                                           size=SIZE)), ("fence", fence_scene())):
    restricted, _ = st.shadow_only(scene)
    everywhere, _ = st.shadow_only(with_map(scene, 1024, {"restrict_to_silhouettes": False}))
    differ = float((np.abs(restricted - everywhere) > 1.5 / 255.0).mean())
    st.check(differ < 0.0005, "%s: penumbrae restricted to the silhouettes as computed "
             "everywhere (%.3f%% of pixels differ)" % (name, 100 * differ))

# Temporal jitter: while nothing moves, frames with 64 turned light samples
# average to nearly what 1024 give in one frame; a moved light starts again.
def jitter_frames(count, samples, move_at=None, x=0.0):
    """The ball's shadow-only image after `count` still frames (the light
    nudged to x + 0.01 before frame `move_at`), through the Python API."""
    from vtksoftshadows import vtkAliasFreeShadowPass

    window, light, shadows = st.api_ball(vtkAliasFreeShadowPass, light_radius=0.5, light_x=x,
                                         ball_resolution=32)
    shadows.SetNumberOfLightSamples(samples)
    shadows.SetMapSize(512)
    for frame in range(count):
        if frame == move_at:
            light.SetPosition(x + 0.01, 5, 0)
        window.Render()
    return st.grab_red(window) / 255.0


reference = jitter_frames(1, 1024)
one = jitter_frames(1, 64)
sixteen = jitter_frames(16, 64)
moved = jitter_frames(16, 64, move_at=15)
errors = [float(np.sqrt(np.mean((image - reference) ** 2))) for image in (one, sixteen)]
st.check(errors[1] < 0.6 * errors[0], "jitter: 16 still frames of 64 light samples nearer 1024 "
         "samples than one frame (RMSE %.4f, one frame %.4f)" % (errors[1], errors[0]))
st.check(np.array_equal(moved, jitter_frames(1, 64, x=0.01)),
         "jitter: a light that moved starts the average again (the frame after the move is a "
         "first frame)")

# 3. The penumbra widens as the ball rises.
widths = st.penumbra_widths("aliasfree")
st.check(widths[0] < widths[1] < widths[2], "the penumbra widens as the ball rises: %s"
         % np.round(widths, 3).tolist())

# 4. Light shapes: a sphere scaled by 2 is the sphere of twice the radius;
# a disc facing the ground casts nearly the sphere's shadow; a rectangle's
# is soft too, and not the disc's.
scene = st.ball_scene(height=1.0, light_radius=0.4, technique="aliasfree", size=SIZE)
sphere, _ = st.shadow_only(scene)
mask = st.quality_mask(scene)
doubled = copy.deepcopy(scene)
doubled["lights"][0]["radius"] = 0.8
scaled = with_map(scene, 1024, {"light_scale": [2.0, 2.0, 2.0]})
difference = st.rmse(st.shadow_only(doubled)[0], st.shadow_only(scaled)[0], mask)
st.check(difference < 0.01, "a sphere scaled by 2 shadows as one of twice the radius (RMSE %.4f)"
         % difference)
disc, _ = st.shadow_only(with_map(scene, 1024, {"light_shape": 1}))
rectangle, _ = st.shadow_only(with_map(scene, 1024, {"light_shape": 2}))
st.check(st.rmse(disc, sphere, mask) < 0.02, "a disc facing the ground casts nearly the sphere's "
         "shadow (RMSE %.4f)" % st.rmse(disc, sphere, mask))
soft = mask & (rectangle > 0.05) & (rectangle < 0.95)
st.check(soft.sum() > 500 and st.rmse(rectangle, disc, mask) > 0.002,
         "a square light: a penumbra (%d pixels) unlike the disc's (RMSE %.4f)"
         % (soft.sum(), st.rmse(rectangle, disc, mask)))
wide = with_map(scene, 1024, {"light_scale": [3.0, 1.0, 1.0]})
st.check(st.penumbra_width(wide, st.shadow_only(wide)[0]) >
         1.5 * st.penumbra_width(scene, sphere),
         "an ellipsoid three times as long along x widens the penumbra along x")

# 5. Bent normals (section 6): a ten-sided sphere lit from the side. Exact
# shadows blacken the triangles that face away from the light while Phong's
# normals still light their lit neighbours up to the shared edge: a jump
# from dark to lit along the terminator. Bent, shading fades to nearly black
# before it; the lit side keeps Phong; the shadow itself does not change;
# on a finely tessellated sphere the shading hardly changes.
def bend_scene(variant, bent, light_type, resolution=10):
    light = {"type": light_type, "position": [6.0, 0.6, 0.0], "radius": 0.3}
    if light_type == "spot":
        light.update({"focal_point": [0.0, 0.6, 0.0], "cone_angle": 20})
    return {"name": "bend", "size": list(SIZE),
            "camera": {"position": [0.0, 0.6, 4.0], "focal_point": [0.0, 0.6, 0.0],
                       "view_angle": 30},
            "lights": [light],
            "actors": [{"source": "sphere", "params": {"radius": 0.8, "resolution": resolution},
                        "position": [0.0, 0.6, 0.0]}],
            "shadows": {"technique": "aliasfree:" + variant,
                        "aliasfree": {"bent_normals": bent}}}


def rendered(scene):
    """The frame's brightest channel, in [0, 1]."""
    with tempfile.TemporaryDirectory() as folder:
        scene_file = os.path.join(folder, "scene.json")
        with open(scene_file, "w") as f:
            json.dump(scene, f)
        output = os.path.join(folder, "out.png")
        st.run(["render", scene_file, "--output", output])
        return st.read_png(output)[:, :, :3].max(axis=2) / 255.0


for variant, light_type in (("hard", "spot"), ("soft", "point")):
    jumps, tops, shadows = {}, {}, {}
    for bent in (False, True):
        scene = bend_scene(variant, bent, light_type)
        image = rendered(scene)
        shadows[bent], geometry = st.shadow_only(scene)
        dark = geometry & (image < 2.5 / 255.0)
        beside_dark = np.zeros_like(dark)
        for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
            beside_dark |= np.roll(np.roll(dark, dy, axis=0), dx, axis=1)
        tops[bent] = image[geometry].max()
        # Lit pixels next to black ones, away from the outline: the terminator.
        jumps[bent] = image[st.interior(geometry, 2) & ~dark & beside_dark].max() / tops[bent]
    st.check(jumps[False] > 0.12 and jumps[True] < 0.08 and abs(tops[True] - tops[False]) < 0.01
             and np.array_equal(shadows[True], shadows[False]),
             "%s, %s light, bent normals: the terminator's jump from black %.3f of the brightest "
             "(%.3f unbent), the brightest %.3f (%.3f), the shadow the same"
             % (variant, light_type, jumps[True], jumps[False], tops[True], tops[False]))
fine = [rendered(bend_scene("soft", bent, "spot", resolution=64)) for bent in (False, True)]
change = float(np.abs(fine[1] - fine[0]).mean())
st.check(change < 0.005, "a 64-sided sphere's shading hardly bent (mean change %.4f)" % change)

# 6. Bad cases. A spot light inside the ball: everything it lights outside
# the ball is in shadow.
scene = st.ball_scene(height=1.0, light_radius=0.1, technique="aliasfree", size=SIZE,
                      map_size=256)
scene["lights"][0]["position"] = [0.0, 1.0, 0.0]
visibility, _ = st.shadow_only(scene)
points, visible, _ = st.ground_points(scene)
near = visible & (np.hypot(points[:, :, 0], points[:, :, 2]) < 0.8)
st.check(near.sum() > 100 and visibility[near].max() < 0.05,
         "a light inside the ball: the ground under it in shadow (brightest %.3f)"
         % visibility[near].max())

# A frame over the memory limit: one clear error, drawn without shadows
# (written, and the command fails as on any error logged while rendering).
scene = st.ball_scene(height=1.0, light_radius=0.4, technique="aliasfree", size=SIZE,
                      params={"memory_limit": 2.0})
with tempfile.TemporaryDirectory() as folder:
    scene_file = os.path.join(folder, "scene.json")
    with open(scene_file, "w") as f:
        json.dump(scene, f)
    output = os.path.join(folder, "out.png")
    result = st.run(["render", scene_file, "--shadow-only", "--output", output], check=False)
    pixels = st.read_png(output)
    visibility = pixels[:, :, 0][pixels[:, :, 1] == 255] / 255.0
last = result.stderr.strip().splitlines()[-1]
st.check(result.returncode == 1 and result.stderr.count("this frame needs") == 2 and
         last.startswith("softshadows: error:") and "this frame needs" in last and
         "MemoryLimit" in result.stderr and visibility.min() > 0.99,
         "over MemoryLimit: one error naming it, the frame unshadowed (%s)"
         % result.stderr.strip().splitlines()[-1][-160:])

# The casters count too: a ball and floor of 64,640 triangles (46 MiB of
# triangles and edges, CPU and GPU) under a limit its lists alone fit in
# (about 10 MiB at 96x96): refused, the error naming the triangles; under
# one that holds both, drawn with its shadow.
for limit, refused in [(40.0, True), (160.0, False)]:
    scene = st.ball_scene(height=1.0, light_radius=0.2, technique="aliasfree", size=(96, 96),
                          map_size=256, params={"memory_limit": limit})
    scene["actors"][1]["params"]["resolution"] = 256
    with tempfile.TemporaryDirectory() as folder:
        scene_file = os.path.join(folder, "scene.json")
        with open(scene_file, "w") as f:
            json.dump(scene, f)
        output = os.path.join(folder, "out.png")
        result = st.run(["render", scene_file, "--shadow-only", "--output", output],
                        check=False)
        pixels = st.read_png(output)
        visibility = pixels[:, :, 0][pixels[:, :, 1] == 255] / 255.0
    if refused:
        st.check(result.returncode == 1 and "64640 triangles" in result.stderr and
                 "triangles and their edges, over MemoryLimit" in result.stderr and
                 visibility.min() > 0.99,
                 "a 65k-triangle caster over MemoryLimit: refused, naming its triangles (%s)"
                 % result.stderr.strip().splitlines()[-1][-200:])
    else:
        st.check(result.returncode == 0 and visibility.min() < 0.05,
                 "the same caster under a limit that holds it: drawn, its shadow dark "
                 "(darkest %.3f)" % visibility.min())

# A light so large that it reaches the surfaces it lights: one clear error,
# at once, drawn without shadows (before, minutes a frame: every triangle's
# influence region covered the map).
scene = st.ball_scene(height=1.0, light_radius=1.0e6, technique="aliasfree", size=SIZE)
with tempfile.TemporaryDirectory() as folder:
    scene_file = os.path.join(folder, "scene.json")
    with open(scene_file, "w") as f:
        json.dump(scene, f)
    output = os.path.join(folder, "out.png")
    start = time.monotonic()
    result = st.run(["render", scene_file, "--shadow-only", "--output", output], check=False)
    seconds = time.monotonic() - start
    pixels = st.read_png(output)
    visibility = pixels[:, :, 0][pixels[:, :, 1] == 255] / 255.0
last = result.stderr.strip().splitlines()[-1]
st.check(result.returncode == 1 and result.stderr.count("reaches a surface it lights") == 2 and
         last.startswith("softshadows: error:") and visibility.min() > 0.99 and seconds < 60,
         "a light of radius 1e6: one error in %.1f s, the frame unshadowed (%s)"
         % (seconds, last[-160:]))

# The view samples of a 2048x2048 window, and a caster of a million
# triangles: right hard shadows, no error.
for name, size, resolution in (("2048x2048 window", (2048, 2048), 64),
                               ("1,004,400-triangle ball", SIZE, 710)):
    scene = st.ball_scene(height=1.0, technique="aliasfree:hard", size=size)
    scene["actors"][1]["params"]["resolution"] = resolution
    visibility, _ = st.shadow_only(scene)
    visible, shadowed, edge = st.expected_hard_shadow(scene)
    away = visible & (edge > 1.5)
    wrong = float(((visibility > 0.5) == shadowed)[away].mean())
    st.check(wrong < 0.002, "%s: the hard shadow where the ball casts it (%.4f%% of ground "
             "pixels wrong)" % (name, 100 * wrong))

# No light at all (the renderer's own light): drawn, no error.
scene = st.ball_scene(height=1.0, light_radius=0.4, technique="aliasfree", size=SIZE)
scene["lights"] = []
with tempfile.TemporaryDirectory() as folder:
    scene_file = os.path.join(folder, "scene.json")
    with open(scene_file, "w") as f:
        json.dump(scene, f)
    result = st.run(["render", scene_file, "--output", os.path.join(folder, "out.png")])
st.check("rror" not in result.stderr, "no lights: drawn without an error")

# Meshes open, non-manifold or with zero-area faces: right shadows, no error.
st.check_odd_meshes("aliasfree")
st.check_odd_meshes("aliasfree:hard")
