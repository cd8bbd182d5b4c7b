// Codes a light's visibility texture for the receivers: one float a texel,
// an integer below 2^23, exact: 2048 * visibility in [0, 4094] (4095: not
// valid) plus the camera distance on a log scale in [1, 2047] (0: no
// surface). A receiver's bilinear lookup then gathers the four codes around
// it in one fetch (textureGather) instead of fetching four texels.
uniform sampler2D vtkShadowVisibility;
uniform float vtkShadowLogNear;     // log2 of the smallest camera distance coded
uniform float vtkShadowCodesPerLog; // distance codes per unit of log2

void main()
{
  vec4 t = texelFetch(vtkShadowVisibility, vtkScreenPixel(), 0);
  float visibility = t.g > 0.5 ? floor(clamp(t.r, 0.0, 1.0) * 4094.0 + 0.5) : 4095.0;
  float distance = t.b > 0.0
    ? clamp(floor((log2(t.b) - vtkShadowLogNear) * vtkShadowCodesPerLog + 1.5), 1.0, 2047.0)
    : 0.0;
  gl_FragData[0] = vec4(visibility * 2048.0 + distance, 0.0, 0.0, 0.0);
}
