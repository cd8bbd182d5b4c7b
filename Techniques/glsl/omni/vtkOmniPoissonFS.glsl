// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Technique `omni`, Poisson filter: soft shadows of a spherical light of
// radius R from a cube map of squared distances. A blocker search over the
// light's extent gives the mean blocker distance b; the penumbra at a
// receiver at distance d then spans w = R (d - b) / b on each side
// (w_penumbra = (d_receiver - d_blocker) w_light / d_blocker), and a
// percentage-closer filter over Poisson taps of that radius, rotated per
// pixel against banding, gives the visibility.
// Uses: vtkShadowCubeLookupFS.glsl, vtkSoftShadowReceiverFS.glsl (vtkShadowCubeTexel,
//   vtkShadowNormalBias, vtkShadowDistanceBias, vtkShadowCube, vtkShadowCubeCenter,
//   vtkShadowCubeRange); GL_ARB_gpu_shader5 (a sampler array indexed in a loop).
uniform vec2 omniPoisson[32]; // a Poisson disk in the unit disc
uniform int omniTaps;
uniform float omniLightRadius[VTK_SHADOW_CUBES];

// The squared distance from the light, along tap direction `e`, to the
// receiver's own plane (through `d`, the light-to-receiver vector, with
// normal `n`), times the distance bias: what a tap compares the cube map
// with. Comparing every tap with the receiver's own distance instead puts
// surfaces seen at a grazing angle from the light in their own shadow
// (noise and darkening on lit floors). A tap whose direction misses the
// plane keeps the receiver's distance.
float vtkOmniTapReference(vec3 n, vec3 d, vec3 e, float reference)
{
  float s = dot(n, d) / dot(n, e); // the plane's point along e is s * e
  return s > 0.0 ? s * s * dot(e, e) * vtkShadowDistanceBias : reference;
}

float vtkOmniPoissonLookup(samplerCube cube, vec3 center, vec4 positionWC, vec3 normalWC,
  float range, float radius)
{
  float size;
  vec3 d = vtkShadowCubeDirection(
    center, positionWC, normalWC, vtkShadowCubeTexel, vtkShadowNormalBias, size);
  float receiver = length(d);
  float reference = dot(d, d) * vtkShadowDistanceBias;
  vec3 n = normalWC;
  vec3 u, v;
  vtkShadowCubeBasis(d, u, v);
  float angle = 6.2831853 * fract(sin(dot(gl_FragCoord.xy, vec2(12.9898, 78.233))) * 43758.5453);
  mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));

  // Blocker search: offsets up to 2R at the receiver see blockers down to a
  // third of the way from the light.
  float blockers = 0.0;
  float count = 0.0;
  for (int i = 0; i < omniTaps; ++i)
  {
    vec2 o = rotation * omniPoisson[i] * (2.0 * radius);
    vec3 e = d + o.x * u + o.y * v;
    float stored = vtkShadowCubeStored(cube, e, range);
    if (stored < vtkOmniTapReference(n, d, e, reference))
    {
      blockers += sqrt(stored);
      count += 1.0;
    }
  }
  if (count == 0.0)
  {
    return 1.0;
  }
  float blocker = blockers / count;
  float width = max(radius * (receiver - blocker) / max(blocker, 1e-6), size);

  float lit = 0.0;
  for (int i = 0; i < omniTaps; ++i)
  {
    vec2 o = rotation * omniPoisson[i] * width;
    vec3 e = d + o.x * u + o.y * v;
    lit += vtkOmniTapReference(n, d, e, reference) <= vtkShadowCubeStored(cube, e, range) ? 1.0 : 0.0;
  }
  return lit / float(omniTaps);
}

// Every cube map's visibility, by vtkOmniPoissonAll(): one loop over the
// point lights instead of one copy of the lookup for each.
float omniVisibility[VTK_SHADOW_CUBES];

float vtkOmniPoissonAll(vec4 positionWC, vec3 normalWC, int wanted)
{
  for (int c = 0; c < VTK_SHADOW_CUBES; ++c)
  {
    omniVisibility[c] = vtkOmniPoissonLookup(vtkShadowCube[c], vtkShadowCubeCenter[c], positionWC,
      normalWC, vtkShadowCubeRange[c], omniLightRadius[c]);
  }
  return omniVisibility[wanted];
}
