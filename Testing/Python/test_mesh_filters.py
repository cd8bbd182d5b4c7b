# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""The mesh-topology filters from Python (`vtksoftshadows`), checked with numpy:
the documented output layouts on a sphere, agreement with vtkFeatureEdges,
brute force against the normal-cone tree, and errors without crashes."""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkFeatureEdges
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkLight

from vtksoftshadows import (vtkEdgeAdjacencyFilter, vtkLightSilhouetteFilter,
                            vtkTopologyAwareMeshFilter)

import shadowtest as st


def sphere(theta=48, phi=30):
    source = vtkSphereSource()
    source.SetThetaResolution(theta)
    source.SetPhiResolution(phi)
    source.Update()
    return source.GetOutput()


def triangles(mesh):
    conn = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())
    return conn.reshape(-1, 3)


def face_normals(points, tris):
    n = np.cross(points[tris[:, 1]] - points[tris[:, 0]], points[tris[:, 2]] - points[tris[:, 0]])
    return n / np.linalg.norm(n, axis=1)[:, None]


mesh = sphere()
points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
tris = triangles(mesh)
normals = face_normals(points, tris)

# --- Edge adjacency: every edge once, its faces' normals, vtkFeatureEdges' counts.
adjacency = vtkEdgeAdjacencyFilter()
adjacency.SetInputData(mesh)
adjacency.Update()
edges_out = adjacency.GetOutput()
# Copies: the filter's arrays go when it runs again.
lines = np.array(vtk_to_numpy(edges_out.GetLines().GetConnectivityArray())).reshape(-1, 2)
face_ids = np.array(vtk_to_numpy(edges_out.GetCellData().GetArray("FaceIds")))
face_normals_out = np.array(vtk_to_numpy(edges_out.GetCellData().GetArray("FaceNormals")))
edge_type = np.array(vtk_to_numpy(edges_out.GetCellData().GetArray("EdgeType")))
expected_edges = {tuple(sorted((int(t[k]), int(t[(k + 1) % 3])))) for t in tris for k in range(3)}
st.check(len(lines) == len(expected_edges), "one line per unique edge")
st.check({tuple(sorted(map(int, e))) for e in lines} == expected_edges, "the same edges")
st.check(np.all(edge_type == 1) and np.all(face_ids >= 0), "a closed sphere: all manifold")
st.check(np.allclose(face_normals_out[:, :3], normals[face_ids[:, 0]], atol=1e-6) and
         np.allclose(face_normals_out[:, 3:], normals[face_ids[:, 1]], atol=1e-6),
         "FaceNormals are the normals of FaceIds")

holed = vtkPolyData()
holed.SetPoints(mesh.GetPoints())
keep = np.ones(len(tris), bool)
keep[::9] = False
cells = vtkCellArray()
cells.SetData(3, numpy_to_vtkIdTypeArray(tris[keep].astype(np.int64).ravel(), deep=True))
holed.SetPolys(cells)
adjacency.SetInputData(holed)
adjacency.Update()
feature = vtkFeatureEdges()
feature.SetInputData(holed)
feature.FeatureEdgesOff()
feature.ManifoldEdgesOff()
feature.NonManifoldEdgesOff()
feature.BoundaryEdgesOn()
feature.Update()
st.check(adjacency.GetNumberOfBorderEdges() == feature.GetOutput().GetNumberOfLines(),
         "border edges as vtkFeatureEdges counts them (%d, %d)" % (
             adjacency.GetNumberOfBorderEdges(), feature.GetOutput().GetNumberOfLines()))

# --- TAM: the default layout, vertex by vertex.
tam = vtkTopologyAwareMeshFilter()
tam.SetInputData(mesh)
tam.Update()
out = tam.GetOutput()
pd = out.GetPointData()
position = vtk_to_numpy(pd.GetArray("Position"))
face = vtk_to_numpy(pd.GetArray("FacePositions")).reshape(-1, 3, 3)
adjacent = vtk_to_numpy(pd.GetArray("AdjacentNormals")).reshape(-1, 3, 3)
st.check(out.GetNumberOfPoints() == 3 * len(tris), "3 vertices a face")
st.check(np.allclose(face[0::3], points[tris], atol=1e-6), "FacePositions are the face's corners")
st.check(np.array_equal(face[0::3], face[1::3]) and np.array_equal(face[0::3], face[2::3]),
         "the same face data in the face's three vertices")
st.check(np.allclose(position.reshape(-1, 3, 3), points[tris], atol=1e-6),
         "Position is the vertex's own corner")
st.check(np.allclose(np.linalg.norm(adjacent, axis=2), 1.0, atol=1e-6), "unit adjacent normals")
ratio = tam.GetMemoryRatio()
st.check(abs(ratio - tam.GetTopologyAwareMeshBytes() / tam.GetInputMeshBytes()) < 1e-12,
         "memory ratio")

half = vtkTopologyAwareMeshFilter()
half.SetInputData(mesh)
half.HalfPrecisionOn()
half.PerFaceAttributesOn()
half.Update()
half_normals = vtk_to_numpy(half.GetOutput().GetCellData().GetArray("AdjacentNormals"))
st.check(half_normals.dtype == np.uint16, "half precision arrays are unsigned short")
decoded = half_normals.view(np.float16).astype(np.float32).reshape(-1, 3, 3)
st.check(np.allclose(decoded, adjacent[0::3], atol=1e-3), "half floats decode to the normals")
st.check(abs(half.GetMemoryRatio() * 7 - ratio) < 1e-9,
         "half, per face: 36 bytes a face against 252 (%g, %g)" % (half.GetMemoryRatio(), ratio))

# --- Silhouettes: brute force and tree, positional and directional lights,
# and a vtkLight.
brute = vtkLightSilhouetteFilter()
brute.SetInputData(mesh)
brute.SetMethodToBruteForce()
tree = vtkLightSilhouetteFilter()
tree.SetInputData(mesh)
rng = np.random.default_rng(3)
for i in range(12):
    light = rng.uniform(-3, 3, 3)
    for f in (brute, tree):
        f.SetLightPosition(*light)
        f.SetPositional(i % 2 == 0)
        f.Update()
    a = np.sort(vtk_to_numpy(brute.GetOutput().GetCellData().GetArray("EdgeIds")))
    b = np.sort(vtk_to_numpy(tree.GetOutput().GetCellData().GetArray("EdgeIds")))
    st.check(np.array_equal(a, b), "brute force and tree agree, light %d" % i)
    # Each silhouette edge separates a face toward the light from one away.
    w = 1.0 if i % 2 == 0 else 0.0
    g = normals @ light - w * np.einsum("ij,ij->i", normals, points[tris[:, 0]])
    front = g > 0  # face_ids: the sphere's edges, numbered as the silhouettes' EdgeIds
    expected = np.nonzero(front[face_ids[:, 0]] != front[face_ids[:, 1]])[0]
    st.check(np.array_equal(a, expected), "the silhouette test, by numpy, light %d" % i)

light = vtkLight()
light.SetPositional(True)
light.SetPosition(2.0, 1.0, 0.5)
tree.SetLight(light)
tree.Update()
n_light = tree.GetNumberOfSilhouetteEdges()
brute.SetLightPosition(2.0, 1.0, 0.5)
brute.SetPositional(True)
brute.Update()
st.check(n_light == brute.GetNumberOfSilhouetteEdges() and n_light > 0, "vtkLight")

# --- Errors: reported, empty output, no exception.
errors = []
bad = vtkPolyData()
pts = vtkPoints()
pts.InsertNextPoint(0, 0, 0)
pts.InsertNextPoint(float("nan"), 0, 0)
bad.SetPoints(pts)
for cls in (vtkEdgeAdjacencyFilter, vtkTopologyAwareMeshFilter, vtkLightSilhouetteFilter):
    f = cls()
    f.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(obj.GetClassName()))
    f.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda obj, event: None)
    f.SetInputData(bad)
    f.Update()
    st.check(f.GetOutput().GetNumberOfPoints() == 0, "%s: empty output on bad input" % cls.__name__)
st.check(len(errors) == 3, "one error a filter: %s" % errors)

print("all mesh filter checks passed")
