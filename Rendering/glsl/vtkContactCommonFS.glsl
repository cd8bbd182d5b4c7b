// Shared by the contact-hardening passes (after vtkShadowScreenCommonFS).
// A contact map texel holds r = S (1 shadowed, 0 lit), g = D (the kernel
// control; <= 0: not blurred), b = the surface's distance to the camera (0 on
// background) and a = 1 once a blur will touch or has touched the pixel.
// The camera distance is in units of contactDistanceUnit (the far clipping
// distance), so that half floats hold it in scenes of any scale.
uniform sampler2D contactMap;
uniform float contactDepthTolerance;
uniform float contactDistanceUnit;
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

// Pass 5's input: visibility 1 - S, or the debug view of the paper's
// figure 4 (lit 1, umbra 0.5, penumbra a dark 0.1).
float vtkContactVisibility(float s)
{
  if (contactDebugView)
  {
    return s <= 0.001 ? 1.0 : (s >= 0.999 ? 0.5 : 0.1);
  }
  return 1.0 - s;
}

// Pass 5's texel for the receivers (vtkShadowScreenBuffers::BeginVisibility):
// the visibility, valid where a blur reached (elsewhere receivers keep their
// own full-resolution hard shadow; the debug view marks every surface), and
// the surface's camera distance.
vec4 vtkContactOutput(vec4 c, float s)
{
  bool valid = contactDebugView ? c.b > 0.0 : c.a > 0.5;
  return vec4(vtkContactVisibility(s), valid ? 1.0 : 0.0, c.b * contactDistanceUnit, 0.0);
}
