// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowCasterRegistry
 * @brief   What casts shadows this frame, and how: the one place that
 *          decides it for every technique.
 *
 * Part of the framework, refreshed at the start of every frame
 * (vtkSoftShadowPass::Render()). The rule, the same in every technique:
 * what an actor draws is what it casts.
 * - GetProps(): the visible props, which light-space draws render through
 *   VTK's own mappers (the light's depth map: everything opaque casts
 *   there as it is drawn, lines, points, imposters, glyphs and image
 *   slices too).
 * - GetCasters(): each polydata an opaque, visible actor draws (each
 *   visible block of a composite mapper, block visibility and opacity
 *   inherited as the mapper does; each visible part of a vtkAssembly, and of
 *   composite props that list their parts, such as vtkAxesActor; a
 *   vtkGlyph3DMapper's instances, each at its own transform, as one mesh,
 *   for the techniques that take caster geometry; vtkDataSetMapper's
 *   surface) with its model matrix, for techniques that derive their own
 *   data from it (a topology aware mesh, an edge table, triangles), cached
 *   with vtkShadowCasterCache until the data changes. Its Faces flag says
 *   whether the actor draws the polygons and strips filled: faces drawn as
 *   wireframe or points, and imposter mappers (spheres, sticks, point
 *   Gaussians), cast only what they draw, through the depth map.
 * - GetDepthMapProps(): the props that draw something techniques cannot
 *   take as faces (lines, points, faces not drawn filled, mappers other
 *   than polydata mappers): a technique whose shadows come from faces
 *   alone (aliasfree) draws these into a depth map of their own, so that
 *   they cast as `hard` casts them.
 * - Translucent actors and blocks are drawn and receive shadows but cast
 *   none, as in VTK: they are not casters; GetTranslucent() lists their
 *   polydata for those that need every drawn surface (the ray-cast truth).
 *   Hidden actors, parts and blocks cast nothing.
 * Light and camera actors (vtkLightActor, vtkCameraActor), pictures of the
 * scene's lights and cameras, cast nothing. Props without bounds (a mapper
 * without input) are left out, as the renderer's culler leaves them out.
 * Polydata that vtkSoftShadowsMeshCheck refuses (point ids out of range,
 * non-finite points) casts nothing either, with one error naming the actor
 * each time the data changes.
 */

#ifndef vtkShadowCasterRegistry_h
#define vtkShadowCasterRegistry_h

#include "vtkSmartPointer.h"               // for vtkSmartPointer
#include "vtkSoftShadowsRenderingModule.h" // for export macro
#include "vtkType.h"                       // for vtkMTimeType
#include "vtkWeakPointer.h"                // for vtkWeakPointer

#include <glm/mat4x4.hpp> // for glm::dmat4
#include <glm/vec3.hpp>   // for glm::dvec3
#include <glm/vec4.hpp>   // for glm::dvec4

#include <functional> // for std::function
#include <map>        // for std::map
#include <memory>     // for std::unique_ptr
#include <set>        // for std::set
#include <vector>     // for std::vector

class vtkActor;
class vtkCompositeDataDisplayAttributes;
class vtkShadowGlyphInstances;
class vtkDataObject;
class vtkMatrix4x4;
class vtkPolyData;
class vtkProp;
class vtkRenderer;

/// One polydata drawn by a visible actor.
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowCaster
{
  vtkProp* Prop = nullptr;        ///< the renderer's prop; not owned; valid during a frame
  vtkActor* Actor = nullptr;      ///< the actor drawing Data: Prop, or a part of it
  vtkPolyData* Data = nullptr;    ///< the mapper's input, or one block of it
  unsigned int FlatIndex = 0;     ///< the block's flat index in a composite input; 0 otherwise
  glm::dmat4 ModelToWorld{ 1.0 }; ///< the actor's matrix, an assembly's composed in
  glm::dmat4 WorldToModel{ 1.0 };
  /// The actor draws Data's polygons and strips filled (representation
  /// Surface, edges shown or not, by a mapper that draws faces): techniques
  /// that take triangles take these. Its lines and vertices, and faces
  /// drawn otherwise, cast through the light's depth map only.
  bool Faces = true;

  /// A world point (a light's position) in this caster's model coordinates.
  glm::dvec3 PointToModel(const glm::dvec3& world) const;
  /// A world direction (a directional light's) in model coordinates, unit length.
  glm::dvec3 DirectionToModel(const glm::dvec3& world) const;
  /// A light as a homogeneous world point (vtkShadowMapManager::Light::
  /// GetHomogeneous(): w 1 a position, w 0 the direction towards it) in
  /// model coordinates, directions unit length.
  glm::dvec4 LightToModel(const glm::dvec4& light) const;
};

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowCasterRegistry
{
public:
  vtkShadowCasterRegistry();
  ~vtkShadowCasterRegistry();
  vtkShadowCasterRegistry(const vtkShadowCasterRegistry&) = delete;
  vtkShadowCasterRegistry& operator=(const vtkShadowCasterRegistry&) = delete;

  /// Collect this frame's casters from the renderer's visible props.
  void Update(vtkRenderer* renderer);

  /// Whether glyph mappers' instances are built into casters' meshes (on,
  /// the default), or left to the mappers, which draw them in every map
  /// (for techniques that take no caster geometry).
  void SetBuildGlyphInstances(bool build) { this->BuildGlyphInstances = build; }

  /// Every visible prop, in the view or not.
  const std::vector<vtkProp*>& GetProps() const { return this->Props; }
  /// The polydata opaque visible actors draw, which cast.
  const std::vector<vtkShadowCaster>& GetCasters() const { return this->Casters; }
  /// The props among GetProps() that draw anything not listed as faces.
  const std::vector<vtkProp*>& GetDepthMapProps() const { return this->DepthMapProps; }
  /// The polydata translucent visible actors and blocks draw: they cast nothing.
  const std::vector<vtkShadowCaster>& GetTranslucent() const { return this->Translucent; }

  /**
   * A caster's faces (polygons and strips, not lines or points) with its
   * coincident points merged (vtkCleanPolyData, 1e-6 of the bounds'
   * diagonal): what silhouette-based techniques build their topology from.
   * Faces meet where they share a point id, and flat-shaded meshes or seams
   * a rounding apart would otherwise make every edge there a border, always
   * a silhouette.
   */
  static vtkSmartPointer<vtkPolyData> MergedFaces(vtkPolyData* data);

private:
  /// Adds `caster` (to the translucent ones unless `opaque`) unless
  /// vtkSoftShadowsMeshCheck refuses its data.
  void AddCaster(vtkShadowCaster caster, bool opaque);
  void AddActors(vtkProp* prop);
  void AddActor(vtkProp* prop, vtkActor* actor, vtkMatrix4x4* matrix);
  void AddBlocks(vtkDataObject* node, bool visible, bool opaque, unsigned int& flatIndex,
    vtkCompositeDataDisplayAttributes* attributes, const vtkShadowCaster& actor);

  std::vector<vtkProp*> Props;
  std::vector<vtkShadowCaster> Casters;
  std::vector<vtkProp*> DepthMapProps;
  std::vector<vtkShadowCaster> Translucent;
  bool FacesOnly = true; ///< the prop being added draws faces only, so far
  bool BuildGlyphInstances = true;
  std::unique_ptr<vtkShadowGlyphInstances> Glyphs;

  /// Each polydata's check, kept until it is modified: refused and reported once.
  struct Checked
  {
    vtkWeakPointer<vtkPolyData> Data;
    vtkMTimeType Time = 0;
    bool Valid = false;
  };
  std::map<const vtkPolyData*, Checked> Checks;
  int Refused = 0; ///< casters refused, in all
};

/**
 * What a technique derives from each caster's polydata, kept until the
 * data is modified or released: Get() rebuilds an entry only when its
 * polydata is new, gone and replaced, or has a newer MTime, or when the
 * technique's `Options` for building it (compared with ==) changed.
 */
template <typename T, typename Options = int>
class vtkShadowCasterCache
{
public:
  using Builder = std::function<void(vtkPolyData* data, T& value)>;

  /// The value for `caster`'s data built with `options`, built with `build` if needed.
  T& Get(const vtkShadowCaster& caster, const Builder& build, const Options& options = {});

  /// Drop the entries of data that is not among `casters` (this frame's).
  void Prune(const vtkShadowCasterRegistry& casters);
  void Clear() { this->Entries.clear(); }
  size_t GetNumberOfEntries() const { return this->Entries.size(); }
  /// How many times Get() has built a value, in all.
  int GetNumberOfBuilds() const { return this->Builds; }

private:
  struct Entry
  {
    vtkWeakPointer<vtkPolyData> Data;
    vtkMTimeType Time = 0;
    Options BuiltWith{};
    T Value;
  };
  std::map<const vtkPolyData*, Entry> Entries;
  int Builds = 0;
};

#include "vtkPolyData.h" // for vtkPolyData::GetMTime, in the template

template <typename T, typename Options>
T& vtkShadowCasterCache<T, Options>::Get(
  const vtkShadowCaster& caster, const Builder& build, const Options& options)
{
  Entry& entry = this->Entries[caster.Data];
  // A weak pointer gone null: the address was freed and reused by new data.
  if (entry.Data != caster.Data || entry.Time != caster.Data->GetMTime() ||
    !(entry.BuiltWith == options))
  {
    entry.Data = caster.Data;
    entry.Time = caster.Data->GetMTime();
    entry.BuiltWith = options;
    entry.Value = T();
    build(caster.Data, entry.Value);
    ++this->Builds;
  }
  return entry.Value;
}

template <typename T, typename Options>
void vtkShadowCasterCache<T, Options>::Prune(const vtkShadowCasterRegistry& casters)
{
  std::set<const vtkPolyData*> current;
  for (const vtkShadowCaster& caster : casters.GetCasters())
  {
    current.insert(caster.Data);
  }
  for (auto it = this->Entries.begin(); it != this->Entries.end();)
  {
    it = it->second.Data && current.count(it->first) ? std::next(it) : this->Entries.erase(it);
  }
}

#endif
