# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Your own mesh with soft shadows: a pipeline from a VTK reader (OBJ, PLY,
STL or VTP by the file's extension) through vtkPolyDataNormals, the model
scaled to stand 2 units tall on a floor under a spot light of radius 0.3,
drawn with contact-hardening shadows. MESH defaults to the Wuson model of
Debian's assimp-testmodels (apt-get install assimp-testmodels).

    PYTHONPATH=build/lib/python3/dist-packages \\
      xvfb-run -a /usr/bin/python3 Examples/Python/reader_pipeline.py [MESH] [OUTPUT.png] [--plain]
"""
import os
import sys

from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from vtksoftshadows import vtkContactHardeningShadowPass

import example_scene as ex

READERS = {".obj": vtkOBJReader, ".ply": vtkPLYReader, ".stl": vtkSTLReader,
           ".vtp": vtkXMLPolyDataReader}
arguments = [a for a in sys.argv[1:] if a != "--plain"]
mesh = "/usr/share/assimp/models/OBJ/WusonOBJ.obj"
if arguments and not arguments[0].lower().endswith(".png"):
    mesh = arguments.pop(0)
extension = os.path.splitext(mesh)[1].lower()
if extension not in READERS or not os.path.isfile(mesh):
    sys.exit("reader_pipeline.py: %s: no such .obj, .ply, .stl or .vtp file" % mesh)
sys.argv[1:] = arguments + (["--plain"] if "--plain" in sys.argv else [])

reader = READERS[extension]()
reader.SetFileName(mesh)
reader.Update()
bounds = reader.GetOutput().GetBounds()
if reader.GetOutput().GetNumberOfPolys() == 0:
    sys.exit("reader_pipeline.py: %s: no polygons in it" % mesh)

# Standing on the floor, 2 units tall, centred.
scale = 2.0 / max(bounds[3] - bounds[2], 1e-12)
place = vtkTransform()
place.Scale(scale, scale, scale)
place.Translate(-(bounds[0] + bounds[1]) / 2, -bounds[2], -(bounds[4] + bounds[5]) / 2)
placed = vtkTransformPolyDataFilter()
placed.SetInputConnection(reader.GetOutputPort())
placed.SetTransform(place)
normals = vtkPolyDataNormals()
normals.SetInputConnection(placed.GetOutputPort())

sys.exit(ex.render("reader_pipeline", [ex.floor(8.0), ex.actor(normals, (0.85, 0.75, 0.55))],
                   [ex.spot_light((2.0, 6.0, 2.0), 0.3)], vtkContactHardeningShadowPass(),
                   camera_position=(6.0, 3.5, 4.5), focal_point=(0.0, 0.8, 0.0)))
