// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReferenceShadowPass.h"

#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowSampling.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"

#include "vtkReferenceAccumulateFS.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vec2.hpp>

#include <cmath>
#include <random>

class vtkReferenceShadowPass::vtkInternals
{
public:
  // This frame's accumulation passes, kept by the screen buffers.
  vtkOpenGLQuadHelper *Accumulate = nullptr, *AccumulateCube = nullptr;
  int NormalsUnit = -1; // the camera pass's normals, while accumulating
};

vtkStandardNewMacro(vtkReferenceShadowPass);

//------------------------------------------------------------------------------
vtkReferenceShadowPass::vtkReferenceShadowPass()
  : Internals(new vtkInternals)
{
}

vtkReferenceShadowPass::~vtkReferenceShadowPass() = default;

//------------------------------------------------------------------------------
vtkSoftShadowPass::Traits vtkReferenceShadowPass::GetTraits() const
{
  Traits traits;
  traits.PointLights = true;
  traits.ScreenSpace = true; // the samples' visibility, added up per pixel
  return traits;
}

//------------------------------------------------------------------------------
bool vtkReferenceShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  // The light's own map serves the fragments screen space cannot (translucent).
  return this->RenderLightDepthMaps(s, false);
}

//------------------------------------------------------------------------------
bool vtkReferenceShadowPass::RenderScreenSpace(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  internals.Accumulate = this->GetScreenQuad("reference.accumulate",
    []() { return vtkSoftShadowPass::GetLightSpaceLookupCode() + vtkReferenceAccumulateFS; });
  internals.AccumulateCube = this->GetScreenQuad("reference.accumulatecube",
    []()
    {
      return vtkSoftShadowPass::GetLightSpaceLookupCode() + "#define ACCUMULATE_CUBE\n" +
        vtkReferenceAccumulateFS;
    });
  if (!internals.Accumulate || !internals.AccumulateCube)
  {
    return false;
  }

  // The camera pass writes each pixel's face normal for the accumulation;
  // points and lines (no face) take the receivers' own hard shadow.
  vtkTextureObject* normals = this->Screen->GetTexture("reference.normals", 4);
  CameraPassCode code;
  code.Implementation =
    "  gl_FragData[0] = vtkShadowFaceDefined ? vec4(vtkShadowNormalWC, 1.0) : vec4(0.0);\n";
  if (!this->RenderCameraDepth(s, { normals }, code))
  {
    return false;
  }
  normals->Activate();
  internals.NormalsUnit = normals->GetTextureUnit();
  auto& lights = this->Maps->GetLights();
  // ProgressEvent's fraction over every light's samples: a frame can take
  // seconds.
  int total = 0;
  for (const auto& light : lights)
  {
    total += light.Radius > 0.0 ? this->NumberOfSamples : 1;
  }
  int done = 0;
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    const auto& light = lights[slot];
    const int count = light.Radius > 0.0 ? this->NumberOfSamples : 1;
    std::vector<glm::dvec3> points;
    if (this->Sampling == Sphere)
    {
      points = vtkShadowSampling::HaltonBall(count, this->Seed);
    }
    else
    {
      for (const auto& d : vtkShadowSampling::StratifiedDisc(count, this->Seed))
      {
        points.emplace_back(d, 0.0);
      }
    }
    const float weight = 1.0f / static_cast<float>(points.size());
    glm::dvec3 e1, e2;
    vtkShadowMatrices::Basis(light.Direction, e1, e2);

    this->Screen->BeginVisibility(static_cast<int>(slot), 0.0f);
    for (const auto& d : points)
    {
      // Spot and point lights: points on the disc or in the sphere of
      // `radius` (z along the axis). Directional: directions within the
      // angular radius, from the points' x and y.
      glm::dvec3 eye = light.Position;
      glm::dvec3 direction = light.Direction;
      if (light.Directional)
      {
        direction = glm::normalize(light.Direction + light.GetHalfSize() * (d.x * e1 + d.y * e2));
      }
      else
      {
        eye += light.Radius * (d.x * e1 + d.y * e2 + d.z * light.Direction);
      }
      const double eyeWC[3] = { eye.x, eye.y, eye.z };
      const double directionWC[3] = { direction.x, direction.y, direction.z };
      if (!this->AccumulateSample(s, static_cast<int>(slot), eyeWC, directionWC, weight))
      {
        this->Screen->EndVisibility();
        normals->Deactivate();
        return false;
      }
      double progress = static_cast<double>(++done) / static_cast<double>(total);
      this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
    }
    this->Screen->EndVisibility();
  }
  normals->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
bool vtkReferenceShadowPass::AccumulateSample(const vtkRenderState* s, int slot,
  const double eyeWC[3], const double directionWC[3], float weight)
{
  const auto& light = this->Maps->GetLights()[slot];
  const glm::dvec3 eye(eyeWC[0], eyeWC[1], eyeWC[2]);
  const glm::dvec3 direction(directionWC[0], directionWC[1], directionWC[2]);
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  vtkOpenGLState* state = context->GetState();
  vtkInternals& internals = *this->Internals;

  // The sample's map, a scratch map every light's samples draw in turn.
  vtkShadowMapManager::Frustum frustum;
  std::array<vtkShadowMapManager::Frustum, 6> faces;
  vtkTextureObject* map = nullptr;
  if (light.Point)
  {
    map = this->Maps->GetScratch(0, vtkShadowTextureSpec::DistanceCube(this->PackedCubeMaps));
    faces = this->Maps->CubeFaces(eye);
    if (!this->RenderDistanceCube(s, faces, map))
    {
      return false;
    }
  }
  else
  {
    map = this->Maps->GetScratch(1, vtkShadowTextureSpec::DepthMap(false));
    frustum = this->Maps->FitFrustum(light, eye, direction);
    if (!this->RenderDepthMap(s, frustum, map))
    {
      return false;
    }
  }

  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFunc(GL_ONE, GL_ONE);
  map->Activate();
  if (light.Point)
  {
    this->Screen->DrawQuad(internals.AccumulateCube,
      [&](vtkShaderProgram* program)
      {
        program->SetUniformi("referenceCube", map->GetTextureUnit());
        vtkShadowMapManager::SetCubeUniforms(program, "reference", "", faces, this->PackedCubeMaps);
        vtkShadowMapManager::SetLookupUniforms(
          program, "reference", this->MapSize, this->NormalBias, this->DistanceBias);
        program->SetUniformf("referenceWeight", weight);
        program->SetUniformi("referenceNormals", internals.NormalsUnit);
      });
  }
  else
  {
    this->Screen->DrawQuad(internals.Accumulate,
      [&](vtkShaderProgram* program)
      {
        program->SetUniformi("referenceMap", map->GetTextureUnit());
        vtkShadowMapManager::SetFrustumUniforms(program, "reference", "", frustum, this->MapSize);
        vtkShadowMapManager::SetLookupUniforms(
          program, "reference", this->MapSize, this->NormalBias, this->DistanceBias);
        program->SetUniformf("referenceWeight", weight);
        program->SetUniformi("referenceNormals", internals.NormalsUnit);
      });
  }
  map->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkReferenceShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "Sampling: " << (this->Sampling == Sphere ? "Sphere" : "Disc") << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
