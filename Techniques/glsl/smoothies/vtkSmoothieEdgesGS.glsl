//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Smoothie geometry (Volokh, section 3.1) from one silhouette edge a -> b and
// the silhouette edge b -> c that follows it, as lines with adjacency
// (a, b, c, unused):
// - the smoothie edge: a and b extruded by the thickness t in the light's
//   screen space into two triangles, the direction d the edge turned by 90
//   degrees and flipped to agree with the adjacent faces' normals averaged in
//   screen space (figure 2a);
// - the smoothie corner at b: where the extruded lines of a -> b and b -> c
//   meet (figure 2b), two triangles around b (split in two halves when the
//   edges turn by more than 120 degrees, whose lines meet far away).
// Extruded vertices keep their silhouette vertex's depth. Screen space is the
// draw's normalized device coordinates (the map is square).
// Uses: vtkSmoothieEdgesVS.glsl (its outputs), vtkSmoothieEdgesFS.glsl.

layout(lines_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;

in vec3 smoothieVertex[];
in vec4 smoothieNormal[];

uniform mat4 vtkShadowModelToClip;
uniform mat4 vtkShadowModelToWorld;
uniform mat4 smoothieClipToWorld; // the draw's frustum, inverted
uniform vec3 smoothieEye;         // the frustum's eye and axis
uniform vec3 smoothieAxis;
// x: a fixed thickness (screen units), 0 to size it from the light; y: K,
// the outer penumbra's width in screen units per unit of 1/b - 1/r
// (perspective) or of r - b (parallel); z: 1 if parallel; w: the widest t.
uniform vec4 smoothieThickness;
uniform float smoothieFar; // the frustum's far depth
// The receivers (vtkSmoothieEdgesFS.glsl's): what lies behind an edge sizes
// its smoothie.
#ifdef SMOOTHIE_CUBE_FACE
uniform samplerCube smoothieReceivers; // squared distances from the eye
#else
uniform sampler2D smoothieReceivers; // linear depths along the axis
#endif

out vec3 smoothieWorld;       // the fragment's world position
flat out vec4 smoothieShape;  // edge: its line (d, d . a, 0); corner: (b, 0, 1)
flat out float smoothieWidth; // t at the fragment's silhouette vertex

vec2 screen(vec4 clip)
{
  return clip.xy / clip.w;
}

// The thickness at a silhouette vertex `world`: fixed, or the outer
// penumbra a light of the radius gives there over `ratio`, the least
// blocker-to-receiver ratio behind it (0: a receiver infinitely far behind
// a perspective blocker, the far plane behind a parallel one), as
// vtkSmoothieEdgesFS.glsl's alpha' reaches 1.
float thickness(vec3 world, float ratio)
{
  if (smoothieThickness.x > 0.0)
  {
    return smoothieThickness.x;
  }
  float b = max(dot(world - smoothieEye, smoothieAxis), 1.0e-6);
  float t = smoothieThickness.z > 0.0
    ? smoothieThickness.y * max(min(b / max(ratio, 1.0e-6), smoothieFar) - b, 0.0)
    : smoothieThickness.y / b * (1.0 - ratio);
  return min(t, smoothieThickness.w);
}

// The blocker's depth at silhouette point `world` in the units the
// fragment shader compares: axial, or a cube face's distance from the eye.
float blockerDepth(vec3 world)
{
#ifdef SMOOTHIE_CUBE_FACE
  return distance(world, smoothieEye);
#else
  return dot(world - smoothieEye, smoothieAxis);
#endif
}

// The ratio of blocker depth b to the receiver's at screen point s (clip:
// the silhouette point's, for depth); 0 where nothing lies behind.
float receiverRatio(vec4 clip, vec2 s, float b)
{
#ifdef SMOOTHIE_CUBE_FACE
  vec4 at = smoothieClipToWorld * vec4(s * clip.w, clip.z, clip.w);
  float r = sqrt(textureLod(smoothieReceivers, at.xyz / at.w - smoothieEye, 0.0).r);
#else
  float r = textureLod(smoothieReceivers, 0.5 * s + 0.5, 0.0).r;
#endif
  return clamp(b / r, 0.0, 1.0);
}

// The least ratio behind the edge p -> q (clip cp, cq, world wp, wq) on its
// side d: at its ends and middle, a third, two thirds and all of the widest
// smoothie (the receiver infinitely far) out; the fragment shader's alpha'
// reaches 1 within the thickness this gives wherever the receivers between
// vary no more than these show.
float leastRatio(vec4 cp, vec4 cq, vec3 wp, vec3 wq, vec2 d)
{
  float widest = max(thickness(wp, 0.0), thickness(wq, 0.0));
  float least = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    float f = 0.5 * float(k);
    vec4 c = mix(cp, cq, f);
    float b = blockerDepth(mix(wp, wq, f));
    for (int j = 1; j <= 3; ++j)
    {
      least = min(least, receiverRatio(c, screen(c) + d * (widest * float(j) / 3.0), b));
    }
  }
  return least;
}

// Figure 2a: the edge p -> q turned to the side its faces' summed normal n
// points to in screen space (its screen direction at the midpoint, exactly:
// the derivative of the projection); where that is undecided (a border
// edge's normals cancel; a face seen edge-on), the side the silhouette
// filter oriented the edge for: its right, away from the occluder.
vec2 extrusion(vec3 p, vec3 q, vec3 n, vec4 cp, vec4 cq)
{
  vec2 e = screen(cq) - screen(cp);
  vec2 d = normalize(vec2(e.y, -e.x));
  vec4 m = vtkShadowModelToClip * vec4(0.5 * (p + q), 1.0);
  vec4 dn = vtkShadowModelToClip * vec4(n, 0.0);
  vec2 ns = dn.xy * m.w - m.xy * dn.w;
  float agree = dot(d, ns);
  if (abs(agree) > 1.0e-3 * length(ns) && length(ns) > 0.0)
  {
    d *= sign(agree);
  }
  return d;
}

// A vertex at silhouette vertex `clip` moved by `offset` in screen space,
// at the same depth.
void emit(vec4 clip, vec2 offset, vec4 shape, float width)
{
  vec4 c = clip + vec4(offset * clip.w, 0.0, 0.0);
  vec4 world = smoothieClipToWorld * c;
  smoothieWorld = world.xyz / world.w;
  smoothieShape = shape;
  smoothieWidth = width;
  gl_Position = c;
  EmitVertex();
}

// A corner quad at b between the directions u and v (at most 90 degrees
// apart): b, b + t u, the meeting point of the two extruded lines, b + t v.
void corner(vec4 cb, vec2 u, vec2 v, float t)
{
  vec2 miter = (u + v) / max(1.0 + dot(u, v), 1.0e-3);
  vec4 shape = vec4(screen(cb), 0.0, 1.0);
  emit(cb, vec2(0.0), shape, t);
  emit(cb, t * u, shape, t);
  emit(cb, t * v, shape, t);
  emit(cb, t * miter, shape, t);
  EndPrimitive();
}

void main()
{
  vec3 a = smoothieVertex[0], b = smoothieVertex[1], c = smoothieVertex[2];
  vec4 ca = vtkShadowModelToClip * vec4(a, 1.0);
  vec4 cb = vtkShadowModelToClip * vec4(b, 1.0);
  vec4 cc = vtkShadowModelToClip * vec4(c, 1.0);
  // Behind the eye (a cube face's plane cuts the edge): no screen position.
  if (ca.w <= 1.0e-6 || cb.w <= 1.0e-6)
  {
    return;
  }
  vec2 sa = screen(ca), sb = screen(cb);
  if (distance(sa, sb) < 1.0e-7)
  {
    return; // seen end-on: no smoothie edge
  }
  vec2 d1 = extrusion(a, b, smoothieNormal[0].xyz, ca, cb);
  vec3 wa = (vtkShadowModelToWorld * vec4(a, 1.0)).xyz;
  vec3 wb = (vtkShadowModelToWorld * vec4(b, 1.0)).xyz;
  float ratio = smoothieThickness.x > 0.0 ? 0.0 : leastRatio(ca, cb, wa, wb, d1);
  float ta = thickness(wa, ratio);
  float tb = thickness(wb, ratio);

  vec4 line = vec4(d1, dot(d1, sa), 0.0);
  emit(ca, vec2(0.0), line, ta);
  emit(cb, vec2(0.0), line, tb);
  emit(ca, ta * d1, line, ta);
  emit(cb, tb * d1, line, tb);
  EndPrimitive();

  // The corner at b, where the next silhouette edge starts.
  if (smoothieNormal[2].w < 0.5 || cc.w <= 1.0e-6)
  {
    return;
  }
  vec2 sc = screen(cc);
  if (distance(sb, sc) < 1.0e-7)
  {
    return; // the case of coincident screen points, omitted as in the report
  }
  vec2 d2 = extrusion(b, c, smoothieNormal[2].xyz, cb, cc);
  vec2 e1 = normalize(sb - sa), e2 = normalize(sc - sb);
  // The two smoothie edges leave a gap where the silhouette turns away from
  // their side; where it turns towards it they overlap.
  if (dot(e2, d1) >= 0.0 && dot(-e1, d2) >= 0.0)
  {
    return;
  }
  if (dot(d1, d2) >= -0.5)
  {
    corner(cb, d1, d2, tb);
  }
  else
  {
    vec2 bisector = d1 + d2;
    vec2 m = dot(bisector, bisector) > 1.0e-6 ? normalize(bisector) : e1;
    corner(cb, d1, m, tb);
    corner(cb, m, d2, tb);
  }
}
