// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowGeometry
 * @brief   Technique-owned geometry: triangles with their own vertex
 *          attributes and shaders, drawn by vtkShadowDrawer through a draw's
 *          frustum (a topology aware mesh, smoothie quads).
 *
 * Part of the framework. SetInput() takes triangle polydata: its points
 * become the attribute `vtkShadowVertexMC` (vec3), each point-data array of
 * 1 to 4 components an attribute of the array's name, and each array of 9
 * components (three vec3, as vtkTopologyAwareMeshFilter writes) the three
 * vec3 attributes `<name>0`, `<name>1`, `<name>2`. Triangles are drawn as
 * they come (3 vertices each, no index buffer: a TAM's vertices are per face
 * anyway); with SetPrimitive(LinesAdjacency), the input's 4-point lines are
 * drawn as GL_LINES_ADJACENCY, for a geometry shader to build triangles from
 * (smoothies' silhouette edges). Data kept once per face (cell data, as
 * vtkTopologyAwareMeshFilter::PerFaceAttributes writes it) is drawn with
 * TriangleInstances (an instance of 3 corners a triangle, the cell data per
 * instance, gl_VertexID the corner) or TrianglePoints (a point a triangle,
 * for a geometry shader). With SetHalfFloat(), unsigned short arrays are
 * IEEE binary16 bit patterns (vtkTopologyAwareMeshFilter::HalfPrecision),
 * uploaded as they are and read as GL_HALF_FLOAT. The data is uploaded on
 * the first Draw() after it changed, only the attributes the shaders use.
 *
 * The shaders are the technique's, each beginning with //VTK::System::Dec;
 * they declare what they use of `uniform mat4 vtkShadowModelToClip` (model
 * to the draw's clip space) and `vtkShadowModelToWorld`, which Draw() sets.
 */

#ifndef vtkShadowGeometry_h
#define vtkShadowGeometry_h

#include "vtkSmartPointer.h"               // for vtkSmartPointer
#include "vtkSoftShadowsRenderingModule.h" // for export macro
#include "vtkType.h"                       // for vtkMTimeType

#include <glm/mat4x4.hpp> // for glm::dmat4

#include <functional> // for std::function
#include <memory>     // for std::shared_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkDataArray;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkPolyData;
class vtkShaderProgram;
class vtkWindow;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowGeometry
{
public:
  vtkShadowGeometry();
  ~vtkShadowGeometry();

  /**
   * A geometry that releases its graphics resources when the last owner
   * lets it go (kept in a vtkShadowCasterCache entry, which is dropped with
   * new data or a caster gone).
   */
  static std::shared_ptr<vtkShadowGeometry> NewShared();

  void SetInput(vtkPolyData* data);
  /// What the input's cells are drawn as.
  enum class Primitive
  {
    Triangles,         ///< its 3-point polygons, point data per corner (default)
    TriangleInstances, ///< its 3-point polygons, cell data per instance of 3 corners
    TrianglePoints,    ///< a point per 3-point polygon, with its cell data
    LinesAdjacency     ///< its 4-point lines, point data per end
  };
  void SetPrimitive(Primitive primitive);
  /// Unsigned short arrays hold binary16 bits, read as GL_HALF_FLOAT. Default off.
  void SetHalfFloat(bool half);
  /// Primitives a draw call: larger inputs are drawn in batches, each
  /// finished before the one after the next starts, so that a software
  /// rasterizer (llvmpipe) holds at most two batches' binned primitives.
  /// For geometry shaders that emit large regions; not for
  /// TriangleInstances. Default 0: one draw.
  void SetBatchSize(int primitives) { this->BatchSize = primitives; }
  void SetShaders(const std::string& vertex, const std::string& fragment,
    const std::string& geometry = std::string());
  /// `source` (a shader beginning with //VTK::System::Dec) with `prefix`
  /// (defines, shared declarations) put after that line.
  static std::string WithPrefix(const std::string& source, const std::string& prefix);
  void SetModelToWorld(const glm::dmat4& modelToWorld) { this->ModelToWorld = modelToWorld; }

  /// The technique's own uniforms, set before every draw.
  void SetUniforms(const std::function<void(vtkShaderProgram*)>& uniforms)
  {
    this->Uniforms = uniforms;
  }

  /// Number of vertices drawn (3 a triangle, 1 with TrianglePoints, 4 a line with adjacency).
  int GetNumberOfVertices() const
  {
    return this->Kind == Primitive::TrianglePoints ? this->Primitives
                                                   : this->Primitives * this->CornersPerPrimitive();
  }

  /// Bytes of the vertex buffers on the GPU: the attributes the shaders use.
  vtkIdType GetUploadedBytes() const;

  /// Draw with `worldToClip` (the draw's frustum). False if the shaders fail.
  bool Draw(vtkOpenGLRenderWindow* context, const glm::dmat4& worldToClip);
  /// The same at another placement, with other uniforms: one geometry (of
  /// one polydata) drawn for each actor that draws that polydata.
  bool Draw(vtkOpenGLRenderWindow* context, const glm::dmat4& worldToClip,
    const glm::dmat4& modelToWorld, const std::function<void(vtkShaderProgram*)>& uniforms);

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  vtkShadowGeometry(const vtkShadowGeometry&) = delete;
  void operator=(const vtkShadowGeometry&) = delete;

  /// One attribute the input offers: `Components` components of `Array` from `First`.
  struct Source
  {
    std::string Name;
    vtkDataArray* Array;
    int First;
    int Components;
  };
  /// Point data for Triangles and LinesAdjacency, cell data for the others.
  std::vector<Source> GetSources() const;
  bool PerFace() const
  {
    return this->Kind == Primitive::TriangleInstances || this->Kind == Primitive::TrianglePoints;
  }
  int CornersPerPrimitive() const { return this->Kind == Primitive::LinesAdjacency ? 4 : 3; }
  bool HasAttribute(const std::string& name) const;
  void Upload(vtkShaderProgram* program);
  bool MissesAttributes(vtkShaderProgram* program) const;

  struct Attribute
  {
    std::string Name;
    int Components = 0;
    bool Half = false; ///< binary16 values, else float
    vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
  };
  vtkSmartPointer<vtkPolyData> Input;
  Primitive Kind = Primitive::Triangles;
  bool HalfFloat = false;
  int BatchSize = 0;
  vtkMTimeType UploadTime = 0;
  std::vector<Attribute> Attributes;
  int Primitives = 0; ///< triangles or lines drawn
  std::string VertexShader, FragmentShader, GeometryShader;
  glm::dmat4 ModelToWorld{ 1.0 };
  std::function<void(vtkShaderProgram*)> Uniforms;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* BoundProgram = nullptr; ///< the VAO's attributes are bound to it
};

#endif
