// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowCompute
 * @brief   OpenGL 4.3 compute for techniques: programs, shader storage
 *          buffers (SSBOs, also usable as atomic counters), image bindings
 *          and memory barriers, in raw OpenGL since VTK 9.1 has no compute
 *          shader type and no SSBO buffer type.
 *
 * Part of the framework. Ask IsSupported() before building anything; a
 * technique whose traits ask for Compute has it asked by vtkSoftShadowPass,
 * which reports a clear error once. Program::Use() tells VTK's shader cache that
 * its own program is no longer bound, so VTK's state stays in sync.
 */

#ifndef vtkShadowCompute_h
#define vtkShadowCompute_h

#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <cstddef> // for size_t
#include <string>  // for std::string

class vtkOpenGLRenderWindow;
class vtkTextureObject;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowCompute
{
public:
  /**
   * Whether `context` has compute shaders, shader storage buffers, image
   * load/store and atomic counters (OpenGL 4.3, or the four ARB
   * extensions). When it lacks any, `missing` names them.
   */
  static bool IsSupported(vtkOpenGLRenderWindow* context, std::string* missing = nullptr);

  /// A compute program.
  class VTKSOFTSHADOWSRENDERING_EXPORT Program
  {
  public:
    Program() = default;
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    /// Compile and link `source` (a whole shader, from its #version line).
    /// False with the compiler's log in `log`.
    bool Build(const std::string& source, std::string* log = nullptr);
    bool IsBuilt() const { return this->Handle != 0; }

    /// Bind the program (and unbind VTK's).
    void Use(vtkOpenGLRenderWindow* context);
    /// Run `x` * `y` * `z` work groups, then unbind the program.
    void Dispatch(unsigned int x, unsigned int y = 1, unsigned int z = 1);

    ///@{
    /** Uniforms of the bound program (Use() first). */
    void SetUniformi(const char* name, int value);
    void SetUniformf(const char* name, float value);
    void SetUniform2i(const char* name, int x, int y);
    void SetUniform3i(const char* name, const int value[3]);
    void SetUniform3f(const char* name, const float value[3]);
    void SetUniform4f(const char* name, const float value[4]);
    /// Column-major, as glm stores them.
    void SetUniformMatrix3f(const char* name, const float value[9]);
    void SetUniformMatrix4f(const char* name, const float value[16]);
    ///@}

    /// Delete the program; the context must be current.
    void Release();

  private:
    unsigned int Handle = 0;
  };

  /// A buffer object for SSBOs and atomic counters.
  class VTKSOFTSHADOWSRENDERING_EXPORT Buffer
  {
  public:
    Buffer() = default;
    ~Buffer();
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    /// (Re)allocate `bytes`, filled from `data` when given.
    void Allocate(size_t bytes, const void* data = nullptr);
    /// Set every 32-bit word to `value`.
    void Clear(unsigned int value = 0);
    /// Bind to `index` of GL_SHADER_STORAGE_BUFFER (or GL_ATOMIC_COUNTER_BUFFER).
    void BindStorage(unsigned int index);
    void BindAtomicCounter(unsigned int index);
    /// Copy the first `bytes` to `out` (waits for the GPU).
    void Read(void* out, size_t bytes) const;
    size_t GetSize() const { return this->Size; }

    void Release();

  private:
    unsigned int Handle = 0;
    size_t Size = 0;
  };

  /**
   * Bind level 0 of `texture` to image unit `unit` for `access`
   * (GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE) in `format` (e.g. GL_R32F).
   */
  static void BindImage(
    unsigned int unit, vtkTextureObject* texture, unsigned int access, unsigned int format);

  /// glMemoryBarrier(bits): make compute writes visible to what reads next.
  static void Barrier(unsigned int bits);
};

#endif
