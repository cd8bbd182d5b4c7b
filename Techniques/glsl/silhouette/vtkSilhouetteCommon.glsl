// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Light-space depths shared by the silhouette pass and its receivers
// (vtkSilhouetteEdgesVS.glsl, vtkSilhouetteLookupFS.glsl). range: near, far,
// 1 for a parallel (directional) map, 0 for a perspective one.
// Uses: nothing.

// A map depth in [0, 1] as a distance along the light's axis.
float silhouetteLinearDepth(vec4 range, float z)
{
  return range.z > 0.0 ? mix(range.x, range.y, z)
                       : 2.0 * range.x * range.y / (range.y + range.x - (2.0 * z - 1.0) * (range.y - range.x));
}

// The inverse for a perspective map: the map depth in [0, 1] of a distance
// along the axis.
float silhouettePerspectiveDepth(vec4 range, float distance)
{
  return 0.5 * ((range.y + range.x) / (range.y - range.x) -
    2.0 * range.y * range.x / ((range.y - range.x) * distance)) + 0.5;
}
