//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause

// Point-light cube maps in one pass: every triangle goes to the six faces
// (gl_Layer) of a layered cube-map framebuffer. The vertex shader drew for
// face 0; since all faces share the light as eye, face f's clip position is
// a fixed matrix times face 0's. The //VTK:: tags let the mapper pass its
// varyings through, as in its own geometry shaders.
// Uses: nothing but the mapper's shaders.

//VTK::PositionVC::Dec
//VTK::PrimID::Dec
//VTK::Color::Dec
//VTK::Normal::Dec
//VTK::Light::Dec
//VTK::TCoord::Dec
//VTK::Picking::Dec
//VTK::DepthPeeling::Dec
//VTK::Clip::Dec
//VTK::Output::Dec

uniform mat4 vtkShadowFaceFromFirst[6];

layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

void main()
{
  //VTK::Normal::Start
  for (int face = 0; face < 6; ++face)
  {
    for (int i = 0; i < 3; ++i)
    {
      //VTK::PrimID::Impl
      //VTK::Clip::Impl
      //VTK::Color::Impl
      //VTK::Normal::Impl
      //VTK::Light::Impl
      //VTK::TCoord::Impl
      //VTK::DepthPeeling::Impl
      //VTK::Picking::Impl
      //VTK::PositionVC::Impl
      gl_Layer = face;
      gl_Position = vtkShadowFaceFromFirst[face] * gl_in[i].gl_Position;
      EmitVertex();
    }
    EndPrimitive();
  }
}
