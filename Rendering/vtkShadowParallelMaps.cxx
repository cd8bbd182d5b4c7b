// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowParallelMaps.h"

#include "vtkCommunicator.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtkShadowVTKVersion.h"

#include <cfloat>

//------------------------------------------------------------------------------
vtkShadowParallelMaps::vtkShadowParallelMaps() = default;
vtkShadowParallelMaps::~vtkShadowParallelMaps() = default;

//------------------------------------------------------------------------------
void vtkShadowParallelMaps::SetController(vtkMultiProcessController* controller)
{
  this->Controller = controller;
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkShadowParallelMaps::GetController() const
{
  return this->Controller;
}

//------------------------------------------------------------------------------
bool vtkShadowParallelMaps::IsParallel() const
{
  return this->Controller && this->Controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
bool vtkShadowParallelMaps::CombineBounds(double bounds[6], bool finite)
{
  // One MAX reduction: minima negated, and a flag for non-finite bounds
  // (MPI leaves the reduction of NaNs undefined). A process showing nothing
  // takes no room.
  const bool none = !finite || !vtkMath::AreBoundsInitialized(bounds);
  double local[7];
  for (int axis = 0; axis < 3; ++axis)
  {
    local[2 * axis] = none ? -DBL_MAX : -bounds[2 * axis];
    local[2 * axis + 1] = none ? -DBL_MAX : bounds[2 * axis + 1];
  }
  local[6] = finite ? 0.0 : 1.0;
  double global[7];
  this->Controller->AllReduce(local, global, 7, vtkCommunicator::MAX_OP);
  if (global[6] > 0.0)
  {
    return false;
  }
  if (global[0] == -DBL_MAX)
  {
    vtkMath::UninitializeBounds(bounds); // nothing anywhere
    return true;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    bounds[2 * axis] = -global[2 * axis];
    bounds[2 * axis + 1] = global[2 * axis + 1];
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkShadowParallelMaps::CombineMinimum(int value)
{
  int least = value;
  this->Controller->AllReduce(&value, &least, 1, vtkCommunicator::MIN_OP);
  return least;
}

//------------------------------------------------------------------------------
void vtkShadowParallelMaps::CombineDepth(vtkTextureObject* map)
{
  const int w = static_cast<int>(map->GetWidth());
  const int h = static_cast<int>(map->GetHeight());
  const std::size_t n = static_cast<std::size_t>(w) * h;
  this->Floats.resize(n);
  this->ReducedFloats.resize(n);
  map->Activate();
  vtkOpenGLState* state = map->GetContext()->GetState();
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, this->Floats.data());
  this->Controller->AllReduce(this->Floats.data(), this->ReducedFloats.data(),
    static_cast<vtkIdType>(n), vtkCommunicator::MIN_OP);
  glTexSubImage2D(
    GL_TEXTURE_2D, 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, this->ReducedFloats.data());
  map->Deactivate();
}

//------------------------------------------------------------------------------
void vtkShadowParallelMaps::CombineCube(vtkTextureObject* cube)
{
  const int w = static_cast<int>(cube->GetWidth());
  const int h = static_cast<int>(cube->GetHeight());
  const std::size_t face = static_cast<std::size_t>(w) * h;
  const bool packed = cube->GetComponents() == 4;
  cube->Activate();
  vtkOpenGLState* state = cube->GetContext()->GetState();
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  state->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (!packed)
  {
    this->Floats.resize(6 * face);
    this->ReducedFloats.resize(6 * face);
    for (int f = 0; f < 6; ++f)
    {
      glGetTexImage(
        GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RED, GL_FLOAT, this->Floats.data() + f * face);
    }
    this->Controller->AllReduce(this->Floats.data(), this->ReducedFloats.data(),
      static_cast<vtkIdType>(6 * face), vtkCommunicator::MIN_OP);
    for (int f = 0; f < 6; ++f)
    {
      glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, w, h, GL_RED, GL_FLOAT,
        this->ReducedFloats.data() + f * face);
    }
  }
  else
  {
    // vtkShadowPackDistance() (vtkShadowCubeLookupFS.glsl) puts the most
    // significant byte in red: as a big-endian word the bytes order as the
    // distances do.
    this->Bytes8.resize(4 * face);
    this->Words.resize(6 * face);
    this->ReducedWords.resize(6 * face);
    for (int f = 0; f < 6; ++f)
    {
      glGetTexImage(
        GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA, GL_UNSIGNED_BYTE, this->Bytes8.data());
      for (std::size_t i = 0; i < face; ++i)
      {
        const unsigned char* b = &this->Bytes8[4 * i];
        this->Words[f * face + i] = (unsigned int)b[0] << 24 | (unsigned int)b[1] << 16 |
          (unsigned int)b[2] << 8 | (unsigned int)b[3];
      }
    }
    this->Controller->AllReduce(this->Words.data(), this->ReducedWords.data(),
      static_cast<vtkIdType>(6 * face), vtkCommunicator::MIN_OP);
    for (int f = 0; f < 6; ++f)
    {
      for (std::size_t i = 0; i < face; ++i)
      {
        const unsigned int word = this->ReducedWords[f * face + i];
        unsigned char* b = &this->Bytes8[4 * i];
        b[0] = static_cast<unsigned char>(word >> 24);
        b[1] = static_cast<unsigned char>(word >> 16);
        b[2] = static_cast<unsigned char>(word >> 8);
        b[3] = static_cast<unsigned char>(word);
      }
      glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE,
        this->Bytes8.data());
    }
  }
  cube->Deactivate();
}
