//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec

// Shared by every screen-space shadow pass: the camera depth pre-pass and
// the matrix taking its clip coordinates back to world coordinates.
// Uses: nothing.
in vec2 texCoord;
uniform sampler2D vtkShadowCameraDepth;
uniform mat4 vtkShadowCameraClipToWorld;
uniform vec3 vtkShadowCameraPosition;

// The receivers' code of a visibility texel (r = visibility, g = 1 where r is
// valid, b = camera distance; vtkShadowScreenBuffers::BeginVisibility()):
// one float, an integer below 2^24, exact: the camera distance on a log
// scale in [1, 2047] (0: no surface), plus 2048 * visibility in [0, 254]
// (255: not valid), plus 2^19 times its penumbra's width
// (vtkShadowWidthCode()), negative where the texel's own hard shadow is lit:
// techniques whose receivers are guided by their own hard shadow
// (contact: vtkContactUpsampleFS.glsl) give them as
// g = 1 + lit + 2 * width on valid texels. A receiver's bilinear lookup then
// gathers the four codes around it in one fetch (textureGather) instead of
// fetching four texels, and tells the sides apart with one comparison.
uniform float vtkShadowLogNear;     // log2 of the smallest camera distance coded
uniform float vtkShadowCodesPerLog; // distance codes per unit of log2

float vtkShadowPackTexel(vec4 t)
{
  bool valid = t.g > 0.5;
  float visibility = valid ? floor(clamp(t.r, 0.0, 1.0) * 254.0 + 0.5) : 255.0;
  float flags = valid ? clamp(floor(t.g - 0.5), 0.0, 31.0) : 0.0;
  float width = floor(flags * 0.5);
  float distance = t.b > 0.0
    ? clamp(floor((log2(t.b) - vtkShadowLogNear) * vtkShadowCodesPerLog + 1.5), 1.0, 2047.0)
    : 0.0;
  float code = width * 524288.0 + visibility * 2048.0 + distance;
  return flags - 2.0 * width > 0.5 ? -code : code;
}

// A penumbra `width` buffer pixels wide on its receiver, in 4 bits: 0 for
// none (under a pixel and a half), else k in [1, 15] for 2^(k/2) pixels.
float vtkShadowWidthCode(float width)
{
  return width >= 1.5 ? clamp(floor(2.0 * log2(width) + 0.5), 1.0, 15.0) : 0.0;
}

// This pixel. From texCoord rather than gl_FragCoord so that every pass uses
// the quad's texture coordinates (VTK's quad helper binds them).
ivec2 vtkShadowScreenPixel()
{
  return ivec2(texCoord * vec2(textureSize(vtkShadowCameraDepth, 0)));
}

float vtkShadowCameraDepthAt(ivec2 pixel)
{
  ivec2 last = textureSize(vtkShadowCameraDepth, 0) - 1;
  return texelFetch(vtkShadowCameraDepth, clamp(pixel, ivec2(0), last), 0).r;
}

// Depth 1.0 is background: no surface, nothing to shadow.
bool vtkShadowScreenHasSurface(out float depth)
{
  depth = vtkShadowCameraDepthAt(vtkShadowScreenPixel());
  return depth < 1.0;
}

// World position of the surface at texture coordinate `uv` (this pixel's:
// texCoord) and camera depth `depth`.
vec3 vtkShadowScreenPositionWC(vec2 uv, float depth)
{
  vec4 world = vtkShadowCameraClipToWorld * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  return world.xyz / world.w;
}

// Geometric normal from the depth buffer: on each axis, the difference to
// the neighbour nearer in depth, which most likely lies on the same surface.
vec3 vtkShadowScreenNormalWC(float depth, vec3 positionWC)
{
  ivec2 pixel = vtkShadowScreenPixel();
  vec2 texel = 1.0 / vec2(textureSize(vtkShadowCameraDepth, 0));
  float left = vtkShadowCameraDepthAt(pixel - ivec2(1, 0));
  float right = vtkShadowCameraDepthAt(pixel + ivec2(1, 0));
  float down = vtkShadowCameraDepthAt(pixel - ivec2(0, 1));
  float up = vtkShadowCameraDepthAt(pixel + ivec2(0, 1));
  // Pick the side first, then rebuild one position an axis: shaders on a
  // software rasterizer evaluate both arms of a selection.
  float sx = abs(right - depth) < abs(left - depth) ? 1.0 : -1.0;
  float sy = abs(up - depth) < abs(down - depth) ? 1.0 : -1.0;
  vec3 dx = sx *
    (vtkShadowScreenPositionWC(texCoord + vec2(sx * texel.x, 0.0), sx > 0.0 ? right : left) - positionWC);
  vec3 dy = sy *
    (vtkShadowScreenPositionWC(texCoord + vec2(0.0, sy * texel.y), sy > 0.0 ? up : down) - positionWC);
  return normalize(cross(dx, dy));
}
