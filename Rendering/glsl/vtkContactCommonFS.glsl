// Shared by the contact-hardening passes (after vtkShadowScreenCommonFS).
// Every map holds the framework's visibility layout
// (vtkShadowScreenBuffers::GetVisibility()), which vtkShadowPackTexel()
// codes for the receivers: r = visibility 1 - S, g = 1 where a blur will touch
// or has touched the pixel (elsewhere receivers keep their own
// full-resolution hard shadow), b = the surface's camera distance (0 on
// background), a = D (<= 0: not blurred).
// Uses: vtkShadowScreenCommonFS.glsl (vtkShadowPackTexel).
uniform sampler2D contactMap;
uniform float contactDepthTolerance;
uniform bool contactDebugView;

vec4 vtkContactFetch(ivec2 pixel)
{
  ivec2 last = textureSize(contactMap, 0) - 1;
  return texelFetch(contactMap, clamp(pixel, ivec2(0), last), 0);
}

// Beyond the paper: taps on another surface (a depth discontinuity in the
// view) do not count, so shadows do not bleed across silhouettes.
bool vtkContactSameSurface(vec4 center, vec4 tap)
{
  return tap.b > 0.0 && abs(tap.b - center.b) <= contactDepthTolerance * center.b;
}

// Pass 5: the receivers' code (vtkShadowPackTexel()) of a filtering texel
// `c` with its filtered visibility `v`, or of the debug view of the paper's
// figure 4 (lit 1, umbra 0.5, penumbra a dark 0.1) on every surface.
vec4 vtkContactOutput(vec4 c, float v)
{
  vec4 texel = vec4(v, c.g, c.b, 0.0);
  if (contactDebugView)
  {
    float marked = v >= 0.999 ? 1.0 : (v <= 0.001 ? 0.5 : 0.1);
    texel = vec4(marked, c.b > 0.0 ? 1.0 : 0.0, c.b, 0.0);
  }
  return vec4(vtkShadowPackTexel(texel));
}
