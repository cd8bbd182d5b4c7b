# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Bad input reaching the module, from files and from a user's pipeline:
each mesh file that crashed `softshadows render` (or VTK's own readers) now
gives one printable line naming the field and what is wrong, exit code 2;
the good files beside them still render; scene values out of a double's
range or very long are field errors; a caster with point ids out of range
casts no shadow, with one error naming its actor, under every technique,
while the rest of the scene is shadowed; a mapper without input is silent."""
import json
import os
import tempfile

from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

from vtksoftshadows import (vtkAliasFreeShadowPass, vtkContactHardeningShadowPass,
                            vtkHardShadowPass, vtkOmnidirectionalShadowPass,
                            vtkReferenceShadowPass, vtkSilhouetteShadowPass,
                            vtkSmoothieShadowPass)

import shadowtest as st

meshes = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data", "Meshes")

# What each bad file's message must say (besides the field and the file).
expected = {
    "ascii_huge_count.ply": "COUNT from 0 to 2147483647",
    "ascii_huge_list.ply": "has 2000000000 items",
    "ascii_index_out_of_range.ply": "face 0 (line 13) uses vertex 3, but the file has 3 vertices",
    "ascii_missing_number.ply": "vertex 1 (line 11) has too few numbers",
    "ascii_negative_count.ply": "COUNT from 0",
    "ascii_no_final_newline.ply": "must end with a newline",
    "ascii_truncated.ply": "no end_header",
    "binary_index_out_of_range.ply": "face 0 uses vertex 4, but the file has 4 vertices",
    "binary_long_face.ply": "has 300 items",
    "binary_negative_index.ply": "uses vertex -1",
    "empty_face.ply": "Cell 0 (a polygon) has 0 points",
    "face_before_vertex.ply": "first element must be 'vertex'",
    "no_z.ply": "no 'z' property",
    "not_ply.ply": "does not start with the line 'ply'",
    "element_without_properties.ply": "the element 'e' has no properties",
    "property_before_element.ply": "a property before any element",
    "scalar_vertex_indices.ply": "no 'vertex_indices' list",
    "truncated_binary.ply": "the file ends inside face 1 of 2",
    "vertex_list_without_data.ply": "the vertex property 'vertex_indices' is a list VTK's reader does not read",
    "ascii_unread_list.ply": "the vertex property 'e' is a list VTK's reader does not read",
    "obj_binary_garbage.obj": "byte 32 is a NUL",
    "obj_index_past_end.obj": "line 4: a face uses vertex 4 (counted from 1), but the file has 3",
    "obj_index_zero.obj": "line 4: a face uses vertex 0, and OBJ counts vertices from 1",
    "obj_negative_index.obj": "line 4: a face uses vertex -5, but 3 come before it",
    "obj_texture_index_past_end.obj": "line 5: a face uses texture coordinate 2, but the file has 1",
    "obj_normal_index_past_end.obj": "line 5: a face uses normal 5 (counted from 1), but the file has 1",
    "obj_renumbered_vertex_past_end.obj": "a face uses vertex 9 (counted from 1), but the file has 3",
    "obj_long_material_name.obj": "a material name of 150 characters",
    "obj_nul_byte.obj": "byte 16 is a NUL",
    "stl_huge_count.stl": "header gives 100000000 triangles, but the file holds 1",
    "stl_infinite_vertex.stl": "triangle 0 has a vertex coordinate inf: NaN and infinite",
    "vtp_claimed_points.vtp": "it claims 288230376151711744 points and 1 cells, whose arrays need more than its",
    "vtp_last_offset.vtp": "its last cell offset, 1000000000000, asks for more connectivity than its",
    "vtp_first_piece_components.vtp": "it claims 3 points and 1 cells, whose arrays need more than its",
    "vtp_negative_points.vtp": "a piece claims a negative number of points",
}
st.check(sorted(expected) == sorted(os.listdir(os.path.join(meshes, "bad"))),
         "every bad mesh file has its expectation")


def printable_line(text):
    return "\n" not in text and all(c == "\t" or (" " <= c and c != "\x7f") for c in text)


with tempfile.TemporaryDirectory() as folder:
    def scene_file(scene, name="scene.json"):
        path = os.path.join(folder, name)
        with open(path, "w") as f:
            json.dump(scene, f)
        return path

    def render(path, *args):
        return st.run(["render", path, "--size", "40x30",
                       "--output", os.path.join(folder, "out.png")] + list(args), check=False)

    for name, needle in sorted(expected.items()):
        scene = st.ball_scene(size=(40, 30), map_size=64)
        scene["actors"][1] = {"file": os.path.join(meshes, "bad", name)}
        result = render(scene_file(scene))
        message = result.stderr.strip()
        st.check(result.returncode == 2, "%s: exit code 2 (got %d)" % (name, result.returncode))
        st.check(printable_line(message) and "actors[1].file" in message and name in message
                 and needle in message, "%s: one printable line naming the field, the file and "
                 "%r: %r" % (name, needle, message[:300]))

    for name in sorted(os.listdir(os.path.join(meshes, "good"))):
        scene = st.ball_scene(size=(40, 30), map_size=64)
        scene["actors"][1] = {"file": os.path.join(meshes, "good", name), "position": [0, 1, 0]}
        result = render(scene_file(scene))
        st.check(result.returncode == 0 and "rror" not in result.stderr,
                 "%s: a good file renders (%d %r)" % (name, result.returncode, result.stderr[:300]))

    # Numbers past a double's range are a field error, named by its path.
    for field, number, path in ((("size", 0), "1e400", "size[0]"),
                                (("lights", 0, "position", 1), "-1e999", "lights[0].position[1]")):
        scene = st.ball_scene(size=(40, 30))
        parent = scene
        for key in field[:-1]:
            parent = parent[key]
        parent[field[-1]] = "OVERFLOW"
        text = json.dumps(scene).replace('"OVERFLOW"', number)
        file = os.path.join(folder, "overflow.json")
        with open(file, "w") as f:
            f.write(text)
        result = render(file)
        st.check(result.returncode == 2 and path + ": the number is out of the range of a double"
                 in result.stderr and printable_line(result.stderr.strip()),
                 "%s: a field error at %s: %r" % (number, path, result.stderr))

    # A huge value, with control characters, is cut and escaped in the message.
    scene = st.ball_scene(size=(40, 30))
    scene["shadows"]["technique"] = "\x1b[31m" + "x" * 1000000
    result = render(scene_file(scene))
    message = result.stderr.strip()
    st.check(result.returncode == 2 and len(message) < 600 and printable_line(message)
             and "more bytes" in message, "a 1 MB value: cut, escaped (%d characters)" % len(message))

    # A long scene name still gives a default output name the OS takes.
    scene = st.ball_scene(size=(40, 30), map_size=64)
    scene["name"] = "n" * 400
    path = scene_file(scene, "long.json")
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        result = st.run(["render", path], check=False)
    finally:
        os.chdir(cwd)
    st.check(result.returncode == 0, "a 400-character name renders: %r" % result.stderr[-300:])


# From a user's pipeline: a caster naming a point it does not have, and an
# actor whose mapper has no input, beside the ball, under every technique.
def broken_triangle():
    points = vtkPoints()
    for p in ((1.5, 1, -0.5), (2.5, 1, -0.5), (2, 1, 0.5)):
        points.InsertNextPoint(p)
    cells = vtkCellArray()
    cells.InsertNextCell(3, [0, 1, 3])
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetPolys(cells)
    return data


for pass_class in (vtkHardShadowPass, vtkReferenceShadowPass, vtkContactHardeningShadowPass,
                   vtkOmnidirectionalShadowPass, vtkSilhouetteShadowPass, vtkSmoothieShadowPass,
                   vtkAliasFreeShadowPass):
    name = pass_class.__name__
    window, _, shadows = st.api_ball(pass_class, light_radius=0.1)
    renderer = window.GetRenderers().GetFirstRenderer()
    bad = vtkActor()
    bad.SetMapper(vtkPolyDataMapper())
    bad.GetMapper().SetInputData(broken_triangle())
    empty = vtkActor()
    empty.SetMapper(vtkPolyDataMapper())
    renderer.AddActor(bad)
    renderer.AddActor(empty)
    messages = {"bad": [], "empty": [], "pass": []}
    for key, obj in (("bad", bad), ("empty", empty.GetMapper()), ("pass", shadows)):
        for event in (vtkCommand.ErrorEvent, vtkCommand.WarningEvent):
            obj.AddObserver(event, lambda o, e, key=key, *rest: messages[key].append(e))
    if hasattr(shadows, "SetNumberOfSamples"):
        shadows.SetNumberOfSamples(4)
    for _ in range(3):
        window.Render()
    red = st.grab_red(window)
    st.check(len(messages["bad"]) == 1 and not messages["empty"] and not messages["pass"],
             "%s: one error on the broken actor over 3 frames, none else (%s)" % (name, {
                 k: len(v) for k, v in messages.items()}))
    # The ball's shadow at the ground's centre; open ground lit.
    renderer.SetWorldPoint(0, 0, 0, 1)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    st.check(red[int(round(y)), int(round(x))] < 40, "%s: the ball still casts its shadow" % name)
    renderer.SetWorldPoint(-2, 0, 1.5, 1)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    st.check(red[int(round(y)), int(round(x))] > 200, "%s: open ground lit" % name)
    window.Finalize()

