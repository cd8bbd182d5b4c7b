// The lookup table of sample-based visibility (Sintorn et al., section 4.2):
// for a plane, the bitmask of the light samples on its positive side. A
// plane is its unit normal n in the light's frame (two angles) and its
// distance d: light sample s (in the light's shape scaled to the unit ball;
// for directional lights, on the unit disc their cone of directions crosses
// at unit distance) is set when dot(n, s) > d.
// Only the hemisphere n.z >= 0 is stored: the opposite plane (-n, -d) reads
// the same cell and complements it, so that the two sides of an edge shared
// by two triangles split the samples exactly, with no crack between them.
// Cells are uniform in the polar angle (over [0, pi/2]), the azimuth and d
// (over [-1, 1]); the mask of a cell is that of the plane at its centre.
// Used by vtkAliasFreeLookupBuildCS.glsl and vtkAliasFreeCastersFS.glsl.

// Polar angles and azimuths (2.8 degrees a cell), and distances (1/32 a cell).
const ivec2 aliasfreeLookupAngles = ivec2(32, 128);
const int aliasfreeLookupDistances = 64;
uniform int aliasfreeWords; // 32-bit words a mask: light samples / 32

const float aliasfreePi = 3.14159265358979;

// The plane at the centre of `cell`.
void aliasfreeCellPlane(int cell, out vec3 n, out float d)
{
  int polar = cell % aliasfreeLookupAngles.x;
  int azimuth = (cell / aliasfreeLookupAngles.x) % aliasfreeLookupAngles.y;
  int distance = cell / (aliasfreeLookupAngles.x * aliasfreeLookupAngles.y);
  float theta = (float(polar) + 0.5) / float(aliasfreeLookupAngles.x) * 0.5 * aliasfreePi;
  float phi = (float(azimuth) + 0.5) / float(aliasfreeLookupAngles.y) * 2.0 * aliasfreePi - aliasfreePi;
  n = vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
  d = (float(distance) + 0.5) / float(aliasfreeLookupDistances) * 2.0 - 1.0;
}

// Where the mask of plane (n, d) comes from: `cell` (-1: every word is
// `fill`), complemented by XOR with `flip`.
struct aliasfreePlaneMask
{
  int cell;
  uint fill;
  uint flip;
};

aliasfreePlaneMask aliasfreeFindCell(vec3 n, float d)
{
  aliasfreePlaneMask m;
  m.flip = 0u;
  if (n.z < 0.0)
  {
    n = -n;
    d = -d;
    m.flip = 0xffffffffu;
  }
  m.fill = d >= 1.0 ? 0u : 0xffffffffu; // every sample behind, or none
  m.cell = -1;
  if (abs(d) < 1.0)
  {
    float theta = acos(clamp(n.z, 0.0, 1.0));
    float phi = atan(n.y, n.x);
    int polar = min(int(theta / (0.5 * aliasfreePi) * float(aliasfreeLookupAngles.x)),
      aliasfreeLookupAngles.x - 1);
    int azimuth = int((phi + aliasfreePi) / (2.0 * aliasfreePi) * float(aliasfreeLookupAngles.y));
    azimuth = clamp(azimuth, 0, aliasfreeLookupAngles.y - 1);
    int distance =
      clamp(int((d + 1.0) * 0.5 * float(aliasfreeLookupDistances)), 0, aliasfreeLookupDistances - 1);
    m.cell = polar + aliasfreeLookupAngles.x * (azimuth + aliasfreeLookupAngles.y * distance);
  }
  return m;
}
