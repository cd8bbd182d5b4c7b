//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec

// Shared by every screen-space shadow pass: the camera depth pre-pass and
// the matrix taking its clip coordinates back to world coordinates.
// Uses: nothing (CreateQuad() adds vtkShadowScreenCodeFS.glsl after it).
#ifdef VTK_SHADOW_TILES
// Drawn by tiles, as points (vtkShadowScreenTilesVS.glsl), which give every
// fragment the same values: the texture coordinate of the pixel's centre,
// as the full-screen quad interpolates it.
uniform vec2 vtkShadowTileTargetSize;
#define texCoord (gl_FragCoord.xy / vtkShadowTileTargetSize)
#else
in vec2 texCoord;
#endif
uniform sampler2D vtkShadowCameraDepth;
uniform mat4 vtkShadowCameraClipToWorld;
uniform vec3 vtkShadowCameraPosition;

// This pixel. From texCoord rather than gl_FragCoord so that every pass uses
// the quad's texture coordinates (VTK's quad helper binds them). Tiles are
// drawn into targets of the camera depth's size
// (vtkShadowScreenBuffers::DrawTiles()): there it is the fragment's own,
// with no uniform to load for every fragment.
ivec2 vtkShadowScreenPixel()
{
#ifdef VTK_SHADOW_TILES
  return ivec2(gl_FragCoord.xy);
#else
  return ivec2(texCoord * vec2(textureSize(vtkShadowCameraDepth, 0)));
#endif
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
