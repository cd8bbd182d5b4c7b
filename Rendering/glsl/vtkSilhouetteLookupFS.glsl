// Receivers of silhouette-distance shadow maps (Valient & Bujnak, section
// 2.2): a light's depth map, its silhouette map (signed distance to the
// nearest silhouette in texels, positive on the occluder's side, and that
// silhouette point's depth) and its lookup texture, which holds four
// segments side by side (eq. 4), each of silhouetteLookupTexels texels, and
// one row per penumbra width (section 2.2.1; one row for hard shadows).
// Uses: vtkSoftShadowReceiverFS.glsl (vtkShadowInMap), declared before it.

uniform vec4 silhouetteDepthRange[VTK_SHADOW_LIGHTS]; // near, far, 1 if parallel, K
uniform vec2 silhouetteBand[VTK_SHADOW_LIGHTS]; // W: distances span [-W, W]; Wmax: widest penumbra
uniform float silhouetteMapSize;
uniform float silhouetteSpread;     // the three outer samples' distance, in penumbra half-widths
uniform float silhouetteEdgeBias;   // in map depth: how far in front a silhouette must be
uniform vec2 silhouetteLookupTexels; // texels per segment, rows

// A map depth in [0, 1] as a distance along the light's axis.
float silhouetteLinearDepth(vec4 range, float z)
{
  return range.z > 0.0 ? mix(range.x, range.y, z)
                       : 2.0 * range.x * range.y / (range.y + range.x - (2.0 * z - 1.0) * (range.y - range.x));
}

// The penumbra's half-width in texels at a receiver of map depth z behind a
// silhouette of map depth edge: K (r - e) for a directional light's angular
// size, K (r - e) / (e r) for a spot light's radius.
float silhouettePenumbra(vec4 range, float edge, float z)
{
  float e = silhouetteLinearDepth(range, edge);
  float r = silhouetteLinearDepth(range, z);
  float w = range.w * max(r - e, 0.0);
  return range.z > 0.0 ? w : w / max(e * r, 1.0e-20);
}

// One sample: the visibility at map point p. The depth map's four texels
// around p all occluded is the shadow map's verdict (z_O < z): a shadow
// shrunk by up to a texel, which is the paper's offset between the two
// boundaries, made on the shadow map's side so that the silhouette's edge
// stays where the geometry puts it. Then eq. 4, its distance term inset so
// that filtering never mixes two segments, and for soft shadows a row
// chosen by the penumbra's width.
float silhouetteSample(sampler2DShadow map, sampler2D silhouettes, sampler2D lookup, vec3 p,
  int i, bool soft, out float width)
{
  float lit = dot(textureGather(map, p.xy, p.z), vec4(1.0));
  float occluded = lit == 0.0 ? 1.0 : 0.0; // z_O < z
  // d_E, filtered bilinearly from the four texels around p, which also
  // give its gradient (gather order: (0,1), (1,1), (1,0), (0,0)).
  vec4 d4 = textureGather(silhouettes, p.xy, 0);
  vec2 f = fract(p.xy * silhouetteMapSize - 0.5);
  vec2 edge = vec2(mix(mix(d4.w, d4.z, f.x), mix(d4.x, d4.y, f.x), f.y),
    texture(silhouettes, p.xy).g); // d_E, z_E
  if (lit == 4.0)
  {
    // Seen by all four texels, the point is the surface nearest the light:
    // it can lie on a silhouette's occluder side only by being that
    // occluder (a surface beside its own border or silhouette), which does
    // not shadow itself. (Within a shadow's true edge, one of the four is
    // occluded.)
    edge.x = edge.x > 0.0 ? -silhouetteBand[i].x : edge.x;
  }
  else if (occluded > 0.0 && edge.x > 0.0 && all(greaterThan(d4, vec4(-silhouetteBand[i].x))))
  {
    // In the shadow map's shadow, on the occluder's side: the inner half of
    // a penumbra only if the light shows past the silhouette. Across an
    // inner fold (a bump in front of more of the occluder) it does not.
    vec2 gradient = vec2(mix(d4.z - d4.w, d4.y - d4.x, f.y), mix(d4.x - d4.w, d4.y - d4.z, f.x));
    vec2 across = p.xy -
      gradient / max(length(gradient), 1.0e-6) * (edge.x + 1.5) / silhouetteMapSize;
    edge.x = dot(textureGather(map, across, p.z), vec4(1.0)) == 0.0 ? -silhouetteBand[i].x : edge.x;
  }
  float inFront = edge.y < p.z - silhouetteEdgeBias ? 1.0 : 0.0; // z_E < z
  float d = clamp(0.5 + 0.5 * edge.x / silhouetteBand[i].x, 0.0, 1.0);
  d = (0.5 + d * (silhouetteLookupTexels.x - 1.0)) / silhouetteLookupTexels.x;
  float coord = 0.25 * (d + occluded) + 0.5 * inFront; // eq. 4
  // The penumbra's half-width, clamped to the widest the lookup holds.
  width = soft && inFront > 0.0
    ? min(silhouettePenumbra(silhouetteDepthRange[i], edge.y, p.z), silhouetteBand[i].y)
    : 0.0;
  float row = width / silhouetteBand[i].y;
  row = (0.5 + row * (silhouetteLookupTexels.y - 1.0)) / silhouetteLookupTexels.y;
  return texture(lookup, vec2(coord, row)).r;
}

// Light i's visibility at a receiver point (already offset, world space).
// Soft: the point and three around it, silhouetteSpread penumbra
// half-widths away (section 2.2.1), averaged; the lookup's profiles are
// narrowed to match (vtkSilhouetteShadowPass::BuildLookup).
float silhouetteVisibility(sampler2DShadow map, sampler2D silhouettes, sampler2D lookup,
  mat4 worldToMap, vec4 receiverWC, int i, bool soft)
{
  vec3 p;
  if (!vtkShadowInMap(worldToMap, receiverWC, p))
  {
    return 1.0;
  }
  float width;
  float visibility = silhouetteSample(map, silhouettes, lookup, p, i, soft, width);
  if (!soft)
  {
    return visibility;
  }
  float reach = silhouetteSpread * width / silhouetteMapSize;
  const vec2 around[3] = vec2[3](vec2(0.0, 1.0), vec2(-0.8660254, -0.5), vec2(0.8660254, -0.5));
  for (int k = 0; k < 3; ++k)
  {
    float unused;
    visibility += silhouetteSample(
      map, silhouettes, lookup, vec3(p.xy + reach * around[k], p.z), i, soft, unused);
  }
  return 0.25 * visibility;
}

// The debug view: the signed distance map where the receiver looks it up,
// 0.5 on the silhouette, darker on the occluder's side.
float silhouetteDebug(sampler2D silhouettes, mat4 worldToMap, vec4 receiverWC, int i)
{
  vec3 p;
  if (!vtkShadowInMap(worldToMap, receiverWC, p))
  {
    return 1.0;
  }
  return clamp(0.5 - 0.5 * texture(silhouettes, p.xy).r / silhouetteBand[i].x, 0.0, 1.0);
}
