// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowCompute.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"

#include <vector>

//------------------------------------------------------------------------------
bool vtkShadowCompute::IsSupported(vtkOpenGLRenderWindow* context, std::string* missing)
{
  if (!context)
  {
    if (missing)
    {
      *missing = "an OpenGL context";
    }
    return false;
  }
  if (VTK_SHADOW_GL_HAS(VERSION_4_3))
  {
    return true;
  }
  std::string lacking;
  auto need = [&](bool has, const char* what)
  {
    if (!has)
    {
      lacking += (lacking.empty() ? "" : ", ") + std::string(what);
    }
  };
  need(VTK_SHADOW_GL_HAS(ARB_compute_shader), "compute shaders (ARB_compute_shader)");
  need(VTK_SHADOW_GL_HAS(ARB_shader_storage_buffer_object),
    "shader storage buffers (ARB_shader_storage_buffer_object)");
  need(VTK_SHADOW_GL_HAS(ARB_shader_image_load_store),
    "image load/store (ARB_shader_image_load_store)");
  need(
    VTK_SHADOW_GL_HAS(ARB_shader_atomic_counters), "atomic counters (ARB_shader_atomic_counters)");
  if (missing)
  {
    *missing = lacking;
  }
  return lacking.empty();
}

//------------------------------------------------------------------------------
vtkShadowCompute::Program::~Program()
{
  this->Release();
}

//------------------------------------------------------------------------------
bool vtkShadowCompute::Program::Build(const std::string& source, std::string* log)
{
  this->Release();
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  auto readLog = [&](GLuint object, bool isProgram)
  {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> text(static_cast<size_t>(length) + 1, '\0');
    isProgram ? glGetProgramInfoLog(object, length, nullptr, text.data())
              : glGetShaderInfoLog(object, length, nullptr, text.data());
    if (log)
    {
      *log = text.data();
    }
  };
  if (ok != GL_TRUE)
  {
    readLog(shader, false);
    glDeleteShader(shader);
    return false;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader); // freed with the program
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE)
  {
    readLog(program, true);
    glDeleteProgram(program);
    return false;
  }
  this->Handle = program;
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Program::Use(vtkOpenGLRenderWindow* context)
{
  // VTK binds its programs lazily through the shader cache: tell it its
  // last one is no longer bound.
  context->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(this->Handle);
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Program::Dispatch(unsigned int x, unsigned int y, unsigned int z)
{
  glDispatchCompute(x, y, z);
  glUseProgram(0);
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Program::SetUniformi(const char* name, int value)
{
  glUniform1i(glGetUniformLocation(this->Handle, name), value);
}

void vtkShadowCompute::Program::SetUniformf(const char* name, float value)
{
  glUniform1f(glGetUniformLocation(this->Handle, name), value);
}

void vtkShadowCompute::Program::SetUniform2i(const char* name, int x, int y)
{
  glUniform2i(glGetUniformLocation(this->Handle, name), x, y);
}

void vtkShadowCompute::Program::SetUniform3i(const char* name, const int value[3])
{
  glUniform3iv(glGetUniformLocation(this->Handle, name), 1, value);
}
void vtkShadowCompute::Program::SetUniform3f(const char* name, const float value[3])
{
  glUniform3fv(glGetUniformLocation(this->Handle, name), 1, value);
}
void vtkShadowCompute::Program::SetUniform4f(const char* name, const float value[4])
{
  glUniform4fv(glGetUniformLocation(this->Handle, name), 1, value);
}
void vtkShadowCompute::Program::SetUniformMatrix3f(const char* name, const float value[9])
{
  glUniformMatrix3fv(glGetUniformLocation(this->Handle, name), 1, GL_FALSE, value);
}
void vtkShadowCompute::Program::SetUniformMatrix4f(const char* name, const float value[16])
{
  glUniformMatrix4fv(glGetUniformLocation(this->Handle, name), 1, GL_FALSE, value);
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Program::Release()
{
  if (this->Handle)
  {
    glDeleteProgram(this->Handle);
    this->Handle = 0;
  }
}

//------------------------------------------------------------------------------
vtkShadowCompute::Buffer::~Buffer()
{
  this->Release();
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Buffer::Allocate(size_t bytes, const void* data)
{
  if (!this->Handle)
  {
    glGenBuffers(1, &this->Handle);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_COPY);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  this->Size = bytes;
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Buffer::Clear(unsigned int value)
{
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Buffer::BindStorage(unsigned int index)
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, this->Handle);
}

void vtkShadowCompute::Buffer::BindAtomicCounter(unsigned int index)
{
  glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, index, this->Handle);
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Buffer::Read(void* out, size_t bytes) const
{
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), out);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Buffer::Release()
{
  if (this->Handle)
  {
    glDeleteBuffers(1, &this->Handle);
    this->Handle = 0;
    this->Size = 0;
  }
}

//------------------------------------------------------------------------------
void vtkShadowCompute::BindImage(
  unsigned int unit, vtkTextureObject* texture, unsigned int access, unsigned int format)
{
  glBindImageTexture(unit, texture->GetHandle(), 0, GL_FALSE, 0, access, format);
}

//------------------------------------------------------------------------------
void vtkShadowCompute::Barrier(unsigned int bits)
{
  glMemoryBarrier(bits);
}
