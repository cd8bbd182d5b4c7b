// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkRayCastScene
 * @brief   Triangles in Embree's ray tracer, and the visible fraction of a
 *          light from a point on them: what the module's ray casting shares.
 *
 * Holds every surface added (in world coordinates) twice over: all of them,
 * for the nearest surface along a ray, and the opaque ones, which alone cast
 * shadows. A light is seen as the ray-cast truth samples it
 * (vtkRayCastLightVisibility): spot and point lights as a sphere of their
 * radius (vtkShadowLightSize::GetRadius()) sampled uniformly over the solid
 * angle it subtends, directional lights as a cone of directions of that
 * angular radius, with strata x strata stratified samples jittered per
 * point. Only polygons and strips count; lines and vertices neither cast
 * nor receive. Rays leaving below a point's side are blocked by its own
 * surface.
 *
 * Commit() after the last Add...(); the queries are then safe from many
 * threads at once.
 */

#ifndef vtkRayCastScene_h
#define vtkRayCastScene_h

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <string>

class vtkLight;
class vtkPolyData;
class vtkRenderer;

class vtkRayCastScene
{
public:
  vtkRayCastScene();
  ~vtkRayCastScene();
  vtkRayCastScene(const vtkRayCastScene&) = delete;
  vtkRayCastScene& operator=(const vtkRayCastScene&) = delete;

  /**
   * The triangles of `data` placed by `modelToWorld`, casting if `opaque`;
   * triangles with a non-finite corner are dropped.
   */
  void AddPolyData(vtkPolyData* data, const glm::dmat4& modelToWorld, bool opaque);

  /**
   * The polygons of every caster the renderer draws (each polydata block,
   * assembly part and composite prop's part its own surface; translucent
   * ones only receive), and in `bounds` its visible props' bounds, whose
   * computation brings their inputs up to date.
   */
  void AddRenderer(vtkRenderer* renderer, double bounds[6]);

  /**
   * Whether a point or direction survives as Embree's floats: a double
   * beyond float range is infinite there, and Embree aborts on a ray that
   * is not finite.
   */
  static bool Castable(const glm::dvec3& v);

  /**
   * Builds Embree's scenes of what was added. False, with why in `error`,
   * where Embree cannot.
   */
  bool Commit(std::string& error);

  /**
   * A surface a ray meets: which one (the order it was added in), where,
   * and its geometric normal facing the ray's origin.
   */
  struct Hit
  {
    unsigned int Surface = 0;
    glm::dvec3 Position{ 0.0 };
    glm::dvec3 Normal{ 0.0 };
  };

  /**
   * The nearest surface along the ray from `origin` in the unit
   * `direction`; false where it meets none.
   */
  bool Intersect(const glm::dvec3& origin, const glm::dvec3& direction, Hit& hit) const;

  /**
   * A light as the shadow rays see it.
   */
  struct Light
  {
    bool Directional = false;
    glm::dvec3 Position{ 0.0 }; // positional lights
    glm::dvec3 ToLight{ 0.0 };  // directional lights: unit vector towards the light
    double Radius = 0.0;        // positional: world units; directional: radians
    bool Spot = false;
    glm::dvec3 Axis{ 0.0 }; // spot: unit direction of the cone
    double ConeAngle = 0.0; // spot: half-angle, radians
  };

  /**
   * `light` as it shines in the world (its transformed position and focal
   * point). False, with why in `error`, for a directional light without a
   * direction.
   */
  static bool MakeLight(vtkLight* source, Light& light, std::string& error);

  /**
   * What a point sees of a light.
   */
  struct Sight
  {
    double Visible = 0.0; // the fraction of the light's samples that reach it
    double Facing = 0.0;  // the normal's cosine to the light's centre
    bool InCone = false;  // inside 0.9 of a spot light's cone (always for others)
  };

  /**
   * What the point `at` on a surface whose unit normal `n` faces the side
   * that receives sees of `light` (n zero: no surface, every direction
   * open): strata x strata samples (one for a light of no size), their
   * pattern shifted by `jitter` in [0, 1)^2, each shadow ray starting
   * `offset` off the surface. A point inside a positional light sees all
   * of it. `twoSided`: the surface receives on whichever side faces the
   * light's centre.
   */
  Sight See(const Light& light, const glm::dvec3& at, const glm::dvec3& n, int strata,
    const glm::dvec2& jitter, double offset, bool twoSided = false) const;

  /**
   * A hash of an index (a pixel, a point) and a seed, to [0, 1)^2: the
   * index's jitter of the stratified pattern (a Cranley-Patterson
   * rotation).
   */
  static glm::dvec2 Jitter(unsigned int index, unsigned int seed);

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
