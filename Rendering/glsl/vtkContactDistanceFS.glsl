// Pass 2 (section 3.2): the distance map. S from the hard shadow test, D from
// the occluder distance: (distance)^Dp * Dm, or, with the light's size, the
// penumbra width w = (d_receiver - d_blocker) * w_light / d_blocker (section
// 6) in pixels, as a kernel size (PCF, Gaussian) or a number of blur passes
// (multi-pass).
// A 2D map's raw depth (through a non-comparing sampler), or, when
// CONTACT_CUBE is defined, a point light's cube map of squared distances.
#ifdef CONTACT_CUBE
uniform samplerCube lightCube;
uniform vec3 cubeCenter;
uniform float cubeTexel;
uniform float cubeRange;
uniform float distanceBias;
#else
uniform sampler2D lightDepth;
#endif
uniform mat4 mapWorldToMap;
uniform vec4 mapEye;
uniform vec3 mapAxis;
uniform vec2 mapFootprint;
uniform vec2 mapDepthRange; // near, far
uniform float normalBias;

uniform bool useLightSize;
uniform float lightSize; // spot: diameter; directional: 2 tan(angular radius)
uniform float distancePower;
uniform float distanceMultiplier;
uniform vec2 pixelFootprint; // world size of a pixel: x + y * camera distance

uniform bool countPasses; // multi-pass: D is a number of passes
uniform float resolutionDivisor; // viewport pixels per pixel of this buffer
uniform int passLimit;
uniform int minimumKernel;
uniform int maximumKernel;
uniform bool growingKernel;
uniform float kernelVariance; // variance of one blur per pixel^2 of kernel size^2

// Distance along the light's axis for a map depth in [0,1].
float vtkContactLightDistance(float depth)
{
  float n = mapDepthRange.x;
  float f = mapDepthRange.y;
  return mapEye.w > 0.0 ? n * f / (f - depth * (f - n)) : n + depth * (f - n);
}

// The number of blur passes whose summed variance comes closest to that of a
// Gaussian of full width `width` (about 4 sigma, 2% to 98%): none for edges
// under about a pixel and a half, which stay hard.
float vtkContactPassesFor(float width)
{
  float target = 0.0625 * width * width;
  float variance = 0.0;
  for (int k = 0; k < passLimit; ++k)
  {
    float size = growingKernel ? float(min(minimumKernel + 2 * k, maximumKernel))
                               : float(maximumKernel);
    float next = variance + kernelVariance * size * size;
    if (abs(next - target) >= abs(variance - target))
    {
      return float(k);
    }
    variance = next;
  }
  return float(passLimit);
}

void main()
{
  float depth;
  if (!vtkScreenHasSurface(depth))
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  vec3 position = vtkScreenPositionWC(texCoord, depth);
  // The face normal from derivatives, cheaper than vtkScreenNormalWC's four
  // neighbours; but where a derivative spans a depth discontinuity (steeper
  // than about 86 degrees), the neighbours' way, which skips the far side.
  float cameraDistance = distance(position, vtkScreenCameraPosition);
  vec3 dx = dFdx(position);
  vec3 dy = dFdy(position);
  float footprint = pixelFootprint.x + pixelFootprint.y * cameraDistance;
  vec3 normal = max(length(dx), length(dy)) < 16.0 * footprint
    ? normalize(cross(dx, dy))
    : vtkScreenNormalWC(depth, position);
  vec4 lit = vec4(0.0, 0.0, cameraDistance / contactDistanceUnit, 0.0);

  // The receiver's and the nearest blocker's distances from the light.
  float receiverDistance;
  float blockerDistance;
#ifdef CONTACT_CUBE
  float size;
  vec3 direction = vtkShadowCubeDirection(
    cubeCenter, vec4(position, 1.0), normal, cubeTexel, normalBias, size);
  float stored = vtkShadowCubeStored(lightCube, direction, cubeRange);
  if (dot(direction, direction) * distanceBias <= stored)
  {
    gl_FragData[0] = lit;
    return;
  }
  receiverDistance = length(direction);
  blockerDistance = sqrt(stored);
  bool perspective = true;
#else
  vec4 receiver = vtkShadowNormalOffset(
    vec4(position, 1.0), normal, mapEye, mapAxis, mapFootprint, normalBias);
  vec4 p = mapWorldToMap * receiver;
  p.xyz /= p.w;
  if (p.w <= 0.0 || any(lessThan(p.xyz, vec3(0.0))) || any(greaterThan(p.xyz, vec3(1.0))))
  {
    gl_FragData[0] = lit;
    return;
  }
  float blockerDepth = texture(lightDepth, p.xy).r;
  if (p.z <= blockerDepth)
  {
    gl_FragData[0] = lit;
    return;
  }
  receiverDistance = vtkContactLightDistance(p.z);
  blockerDistance = vtkContactLightDistance(blockerDepth);
  bool perspective = mapEye.w > 0.0;
#endif
  float occluderDistance = max(receiverDistance - blockerDistance, 0.0);
  float d;
  if (useLightSize)
  {
    float world = occluderDistance * lightSize / (perspective ? blockerDistance : 1.0);
    // The penumbra lies on the receiver, which the view foreshortens by
    // |n.v| across its slope: an isotropic kernel sized for the unforeshortened
    // width blurs that way 1 / |n.v| times too far (seen edge-on, far worse
    // than a hard edge). Sizing for the foreshortened width errs the other
    // way along the slope's level lines, where a narrower blur costs less.
    float facing = abs(dot(normal, normalize(vtkScreenCameraPosition - position)));
    float pixels = world * facing / (pixelFootprint.x + pixelFootprint.y * cameraDistance);
    d = countPasses ? vtkContactPassesFor(pixels) : pixels;
  }
  else
  {
    // Dp and Dm are tuned in full-resolution pixels: a kernel this buffer's
    // `resolutionDivisor` times smaller covers as much, and a blur pass
    // spreads as far as divisor^2 full-resolution ones (variances add).
    d = pow(occluderDistance, distancePower) * distanceMultiplier /
      (countPasses ? resolutionDivisor * resolutionDivisor : resolutionDivisor);
  }
  gl_FragData[0] = vec4(1.0, d, cameraDistance / contactDistanceUnit, 0.0);
}
