# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Model files (glTF, GLB, OBJ + MTL) through VTK's importers, on models
Debian's assimp-testmodels ships: named as the scene (staged on a floor, lit
when they have no light), named by a scene's actor (`import`, placed), their
materials, cameras and KHR_lights_punctual lights used, and broken ones
refused in one line."""
import json
import math
import os
import shutil
import tempfile

import numpy as np

import shadowtest as st

MODELS = "/usr/share/assimp/models"
SPIDER = os.path.join(MODELS, "OBJ", "spider.obj")
BOX = os.path.join(MODELS, "glTF2", "BoxTextured-glTF", "BoxTextured.gltf")
ENGINE = os.path.join(MODELS, "glTF2", "2CylinderEngine-glTF-Binary", "2CylinderEngine.glb")
CAMERAS = os.path.join(MODELS, "glTF2", "cameras", "Cameras.gltf")
SIZE = ["--size", "160x120"]


def render(folder, scene, name, *options):
    """Renders `scene` (a path, or a dict written as JSON); returns the pixels."""
    if isinstance(scene, dict):
        path = os.path.join(folder, name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f)
        scene = path
    output = os.path.join(folder, name + ".png")
    st.run(["render", scene, "--output", output] + SIZE + list(options))
    return st.read_png(output)


def visibility(pixels):
    """A --shadow-only frame: visibility in [0, 1] and the geometry mask."""
    return pixels[:, :, 0] / 255.0, pixels[:, :, 1] == 255


def light_node(position, target):
    """A glTF node at `position` whose -z axis points at `target`."""
    d = np.array(target, float) - np.array(position, float)
    d /= np.linalg.norm(d)
    axis = np.cross([0.0, 0.0, -1.0], d)
    s = np.linalg.norm(axis)
    angle = math.atan2(s, -d[2])
    axis = axis / s if s > 1e-9 else np.array([1.0, 0.0, 0.0])
    q = list(axis * math.sin(angle / 2)) + [math.cos(angle / 2)]
    return {"translation": list(position), "rotation": q,
            "extensions": {"KHR_lights_punctual": {"light": 0}}}


with tempfile.TemporaryDirectory() as folder:
    # The spider as the scene: staged on a floor, lit from above, textured
    # from its MTL (brown legs), a soft shadow on the floor.
    shaded = render(folder, SPIDER, "spider")
    rgb = shaded[:, :, :3].astype(float)
    saturation = rgb.max(axis=2) - rgb.min(axis=2)
    st.check((saturation > 25).mean() > 0.01,
             "spider: its MTL's textures colour it (%.1f%% coloured pixels)"
             % (100 * (saturation > 25).mean()))
    vis, mask = visibility(render(folder, SPIDER, "spider-shadow", "--shadow-only"))
    shadowed = mask & (vis < 0.5)
    penumbra = mask & (vis > 0.05) & (vis < 0.95)
    st.check(mask.mean() > 0.6, "spider: the floor fills the view (%.2f)" % mask.mean())
    st.check(0.01 < shadowed.mean() < 0.4,
             "spider: a shadow on the floor (%.1f%% of pixels)" % (100 * shadowed.mean()))
    st.check(penumbra.sum() > 0.2 * shadowed.sum(),
             "spider: the staged light is soft (%d penumbra, %d shadowed pixels)"
             % (penumbra.sum(), shadowed.sum()))
    st.check((mask & (vis > 0.95)).mean() > 0.3, "spider: most of the floor is lit")

    # Every command takes a model file as its scene.
    st.run(["bench", ENGINE, "--techniques", "hard,contact", "--frames", "2"] + SIZE)
    gallery = os.path.join(folder, "gallery")
    st.run(["gallery", ENGINE, "--techniques", "hard,silhouette", "--frames", "1",
            "--output-dir", gallery] + SIZE)
    st.check(os.path.exists(os.path.join(gallery, "gallery.png")), "gallery of a GLB")
    quality = st.run(["quality", BOX, "--techniques", "hard,contact", "--samples", "16"]
                     + SIZE).stdout
    st.check("contact" in quality, "quality of a glTF:\n" + quality)

    # The file's camera: Cameras.gltf looks from (0.5, 0.5, 3) down -z with
    # a vertical field of 0.7 rad. A scene importing it without a camera
    # draws what one with that camera written out draws.
    cameras = {
        "size": [160, 120],
        "actors": [{"import": CAMERAS}],
        "lights": [{"type": "spot", "position": [0.5, 2.0, 2.0], "focal_point": [0.5, 0.0, 0.0]}],
    }
    from_file = render(folder, cameras, "cameras", "--technique", "hard")
    cameras["camera"] = {"position": [0.5, 0.5, 3.0], "focal_point": [0.5, 0.5, 2.0],
                         "view_angle": math.degrees(0.7)}
    by_hand = render(folder, cameras, "cameras-by-hand", "--technique", "hard")
    cameras["camera"]["position"] = [0.5, 0.5, 4.0]
    farther = render(folder, cameras, "cameras-farther", "--technique", "hard")
    difference = np.abs(from_file.astype(int) - by_hand.astype(int)).max()
    st.check(difference <= 2, "Cameras.gltf's camera is used (largest difference %d)" % difference)
    st.check(np.abs(from_file.astype(int) - farther.astype(int)).max() > 50,
             "and another camera would differ")

    # A glTF light (KHR_lights_punctual), on the box: the model as the
    # package ships it, a spot light added beside it. The shadow falls away
    # from the light, whichever side it is on.
    for bin_or_png in ("BoxTextured0.bin", "CesiumLogoFlat.png"):
        shutil.copy(os.path.join(os.path.dirname(BOX), bin_or_png), folder)
    with open(BOX) as f:
        box = json.load(f)
    centroids = {}
    for side in (-1.0, 1.0):
        lit = json.loads(json.dumps(box))
        lit["extensionsUsed"] = ["KHR_lights_punctual"]
        lit["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"type": "spot", "intensity": 1.0, "spot": {"outerConeAngle": 0.7}}]}}
        lit["nodes"].append(light_node([2.0 * side, 3.0, 0.0], [0.0, 0.0, 0.0]))
        lit["scenes"][0]["nodes"].append(len(lit["nodes"]) - 1)
        model = os.path.join(folder, "box-lit.gltf")
        with open(model, "w") as f:
            json.dump(lit, f)
        scene = {
            "size": [160, 120],
            "camera": {"position": [0, 8, 0.01], "focal_point": [0, 0, 0], "view_angle": 40},
            "actors": [{"source": "plane", "params": {"size": [6, 6]}},
                       {"import": model, "position": [0, 0.7, 0]}],
            "shadows": {"technique": "hard"},
        }
        vis, mask = visibility(render(folder, scene, "box-lit", "--shadow-only"))
        # The floor only: the box's top is in the middle of the view.
        rows, columns = np.nonzero(mask & (vis < 0.5))
        st.check(len(columns) > 50, "glTF light on side %+d shadows the floor" % side)
        centroids[side] = columns.mean() - mask.shape[1] / 2
    st.check(centroids[1.0] < -5 and centroids[-1.0] > 5,
             "the shadow falls away from the glTF light (centroids %+.1f, %+.1f px)"
             % (centroids[-1.0], centroids[1.0]))
    result = st.run(["render", os.path.join(folder, "box-lit.json"), "--shadow-only",
                     "--light", "1"], check=False)
    st.check(result.returncode == 2 and "1 light" in result.stderr,
             "the scene has the glTF's one light: %r" % result.stderr)

    # `import` places the model: the spider moved along x moves its shadow.
    shifts = []
    for x in (-1.5, 1.5):
        scene = {
            "size": [160, 120],
            "camera": {"position": [0, 12, 0.01], "focal_point": [0, 0, 0], "view_angle": 40},
            "lights": [{"type": "spot", "position": [0, 8, 0], "cone_angle": 50, "radius": 0.2}],
            "actors": [{"source": "plane", "params": {"size": [8, 8]}},
                       {"import": SPIDER, "position": [x, 0.1, 0], "scale": [0.02, 0.02, 0.02]}],
            "shadows": {"technique": "hard"},
        }
        vis, mask = visibility(render(folder, scene, "placed", "--shadow-only"))
        rows, columns = np.nonzero(mask & (vis < 0.5))
        st.check(len(columns) > 20, "placed spider at x=%g casts a shadow" % x)
        shifts.append(columns.mean())
    st.check(shifts[1] - shifts[0] > 20,
             "the import's position moves it (%.1f -> %.1f px)" % tuple(shifts))

# Broken models: exit code 2 and one line saying what is wrong; VTK 9.1's
# loader would crash on several of these.
broken = {
    "glTF2/TestNoRootNode/NoScene.gltf": "no scene",
    "glTF2/RecursiveNodes/RecursiveNodes.gltf": "its own ancestor",
    "glTF2/MissingBin/BoxTextured.gltf": "missing",
    "glTF2/wrongTypes/badArray.gltf": "primitives is not an array",
    "glTF2/wrongTypes/badObject.gltf": "is not an object",
    "glTF2/SchemaFailures/sceneWrongType.gltf": "scene is not an index",
    "glTF2/draco/2CylinderEngine.gltf": "Draco",
    "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb": "not finite",
    "OBJ/point_cloud.obj": "no polygons",
    "OBJ/box_UTF16BE.obj": "NUL",
}
# Colours after a vertex's coordinates: VTK 9.1's importer gives them to
# too few points, which is refused; 9.3's reads them.
VERTEX_COLORS = "OBJ/cube_with_vertexcolors.obj"
# Indices past a glTF accessor's data: VTK 9.6's loader refuses them itself,
# earlier ones load them and the mesh check refuses the point ids.
broken["glTF2/IndexOutOfRange/IndexOutOfRange.gltf"] = (
    "point id" if st.vtk_version() < (9, 6) else "Error loading model data")
if st.vtk_version() < (9, 3):
    broken[VERTEX_COLORS] = "values"
else:
    result = st.run(["render", os.path.join(MODELS, VERTEX_COLORS), "--output", os.devnull]
                    + SIZE, check=False)
    st.check(result.returncode == 0 and not result.stderr.strip(),
             "%s renders (%d: %r)" % (VERTEX_COLORS, result.returncode, result.stderr))
for name, needle in sorted(broken.items()):
    result = st.run(["render", os.path.join(MODELS, name), "--output", os.devnull] + SIZE,
                    check=False)
    message = result.stderr.strip()
    st.check(result.returncode == 2, "%s: exit code 2 (got %d: %r)"
             % (name, result.returncode, message))
    st.check(needle in message and "\n" not in message,
             "%s: one line with %r: %r" % (name, needle, message))
# An import that names something else, and a missing one, are the field's.
with tempfile.TemporaryDirectory() as folder:
    for value, needle in ((SPIDER.replace(".obj", ".mtl"), "not a model file"),
                          ("nowhere.glb", "no such file")):
        path = os.path.join(folder, "s.json")
        with open(path, "w") as f:
            json.dump({"actors": [{"import": value}]}, f)
        result = st.run(["render", path], check=False)
        st.check(result.returncode == 2 and "actors[0].import" in result.stderr
                 and needle in result.stderr, "import %s: %r" % (value, result.stderr))
        with open(path, "w") as f:
            json.dump({"actors": [{"import": SPIDER, "color": [1, 0, 0]}]}, f)
        result = st.run(["render", path], check=False)
        st.check(result.returncode == 2 and "actors[0].color" in result.stderr,
                 "an import's colour is refused: %r" % result.stderr)
print("ok")
