//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
// The smoothie buffer (Volokh, sections 3.3 to 3.5): each smoothie fragment
// writes its depth b and its corrected alpha, alpha' = alpha / (1 - b/r)
// clamped to [0, 1], r the receiver's depth in the linear shadow map. Drawn
// with MIN blending: the nearest smoothie's depth and the darkest alpha stay.
// alpha is the fragment's screen distance x from the silhouette edge (or
// corner point, |v - p|) over the thickness t; sized from the light's
// radius, alpha' = x / W with W the outer penumbra's width at the receiver,
// which for a perspective light is exactly the report's correction of an
// alpha over t = W(r infinitely far).
// The square root of alpha' (Falloff) rises fastest at the umbra, as the
// outer half of a disc light's penumbra does (docs/quality.md).
// On a point light's cube face (SMOOTHIE_CUBE_FACE), depths are distances
// from the light: their ratio along a ray is the same.
// Uses: vtkSmoothieEdgesGS.glsl (its outputs).

in vec3 smoothieWorld;
flat in vec4 smoothieShape;
flat in float smoothieWidth;

uniform vec3 smoothieEye;
uniform vec3 smoothieAxis;
uniform vec4 smoothieThickness; // as in vtkSmoothieEdgesGS.glsl
uniform float smoothieMapSize;
uniform int smoothieFalloff; // 0: alpha' as the report has it; 1: its square root
#ifdef SMOOTHIE_CUBE_FACE
uniform samplerCube smoothieReceivers; // the framework's squared distances
#else
uniform sampler2D smoothieReceivers; // the linear shadow map
#endif

out vec4 fragOutput0; // r: smoothie depth, g: alpha'

void main()
{
  vec2 p = gl_FragCoord.xy / smoothieMapSize * 2.0 - 1.0;
  float x = smoothieShape.w > 0.5 ? distance(p, smoothieShape.xy)
                                  : dot(smoothieShape.xy, p) - smoothieShape.z;
  float axial = dot(smoothieWorld - smoothieEye, smoothieAxis);
#ifdef SMOOTHIE_CUBE_FACE
  float b = distance(smoothieWorld, smoothieEye);
  float r = sqrt(texture(smoothieReceivers, smoothieWorld - smoothieEye).r);
#else
  float b = axial;
  float r = texelFetch(smoothieReceivers, ivec2(gl_FragCoord.xy), 0).r;
#endif
  // b ~ r (the receiver is the blocker, or lies in front of it): no shadow
  // from this smoothie, alpha' = 1, as the report handles it.
  // Past a corner's radius: round corners.
  float ratio = b / r;
  if (ratio > 0.999 || (smoothieShape.w > 0.5 && x >= smoothieWidth))
  {
    discard;
  }
  float alpha;
  if (smoothieThickness.x > 0.0)
  {
    alpha = (x / smoothieWidth) / (1.0 - ratio);
  }
  else if (smoothieThickness.z > 0.0)
  {
    alpha = x / (smoothieThickness.y * (r - b));
  }
  else
  {
    alpha = x / (smoothieThickness.y / axial * (1.0 - ratio));
  }
  alpha = clamp(alpha, 0.0, 1.0);
  fragOutput0 = vec4(b, smoothieFalloff == 1 ? sqrt(alpha) : alpha, 0.0, 1.0);
}
