// Packs a light's visibility texture for the receivers: each texel of the
// output holds, one float each, the codes of the 2x2 texels whose lower left
// is the same texel of the input (x: itself, y: right, z: above, w: above
// right), so that a receiver's bilinear lookup is one fetch, not four. A
// code is an integer below 2^23, exact in a float: 2048 * visibility in
// [0, 4094] (4095: not valid) plus the camera distance on a log scale in
// [1, 2047] (0: no surface).
uniform sampler2D vtkShadowVisibility;
uniform float vtkShadowLogNear;     // log2 of the camera's near distance
uniform float vtkShadowCodesPerLog; // distance codes per unit of log2

float vtkShadowCode(ivec2 pixel)
{
  ivec2 last = textureSize(vtkShadowVisibility, 0) - 1;
  vec4 t = texelFetch(vtkShadowVisibility, min(pixel, last), 0);
  float visibility = t.g > 0.5 ? floor(clamp(t.r, 0.0, 1.0) * 4094.0 + 0.5) : 4095.0;
  float distance = t.b > 0.0
    ? clamp(floor((log2(t.b) - vtkShadowLogNear) * vtkShadowCodesPerLog + 1.5), 1.0, 2047.0)
    : 0.0;
  return visibility * 2048.0 + distance;
}

void main()
{
  ivec2 pixel = vtkScreenPixel();
  gl_FragData[0] = vec4(vtkShadowCode(pixel), vtkShadowCode(pixel + ivec2(1, 0)),
    vtkShadowCode(pixel + ivec2(0, 1)), vtkShadowCode(pixel + ivec2(1, 1)));
}
