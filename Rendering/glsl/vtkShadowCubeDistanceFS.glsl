// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Point lights' cube maps (vtkShadowDistanceStage): the squared distance of
// the fragment to the face's eye, the light, from its window position; or
// (vtkShadowFaceLinear) its linear depth along any frustum's axis.
// Uses: vtkShadowCubeLookupFS.glsl (vtkShadowPackDistance).
uniform mat4 vtkShadowFaceClipToView; // the face's inverse projection
uniform float vtkShadowFaceSize;      // the face's width in texels
uniform float vtkShadowFaceRange;     // 0: float map; else RGBA8, packed over this (far^2)
uniform bool vtkShadowFaceLinear;     // the depth along the axis, not the squared distance
uniform float vtkShadowFaceSlopeBias; // linear depth: offset in texel-to-texel changes

// windowDepth: the fragment's window depth (gl_FragCoord.z, or an imposter's gl_FragDepth).
vec4 vtkShadowFaceDistance(float windowDepth)
{
  vec4 view = vtkShadowFaceClipToView *
    vec4(gl_FragCoord.xy / vtkShadowFaceSize * 2.0 - 1.0, windowDepth * 2.0 - 1.0, 1.0);
  view.xyz /= view.w;
  if (vtkShadowFaceLinear)
  {
    float depth = -view.z;
    return vec4(depth + vtkShadowFaceSlopeBias * max(abs(dFdx(depth)), abs(dFdy(depth))));
  }
  float distance2 = dot(view.xyz, view.xyz);
  return vtkShadowFaceRange > 0.0
    ? vtkShadowPackDistance(min(distance2 / vtkShadowFaceRange, 0.9999))
    : vec4(distance2);
}
