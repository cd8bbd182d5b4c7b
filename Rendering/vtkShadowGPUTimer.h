// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowGPUTimer
 * @brief   GPU time of a stretch of OpenGL work, by timer queries read
 *          without waiting.
 *
 * Part of the framework: vtkSoftShadowPass times its steps with it, and a
 * technique may time its own passes. Start() and Stop() around the work,
 * with the context current, every frame; GetMilliseconds() is the last
 * stretch whose queries had completed at a Stop() (usually the frame
 * before), 0 until one has or where the context has no timer queries.
 * VTK's vtkOpenGLRenderTimer (its reusable queries) does the timing.
 */

#ifndef vtkShadowGPUTimer_h
#define vtkShadowGPUTimer_h

#include "vtkOpenGLRenderTimer.h"          // for vtkOpenGLRenderTimer
#include "vtkSoftShadowsRenderingModule.h" // for export macro

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowGPUTimer
{
public:
  vtkShadowGPUTimer() = default;
  vtkShadowGPUTimer(const vtkShadowGPUTimer&) = delete;
  vtkShadowGPUTimer& operator=(const vtkShadowGPUTimer&) = delete;

  void Start();
  /// Ends the stretch, and reads the last one whose queries have completed.
  void Stop();
  double GetMilliseconds() const { return this->Milliseconds; }
  /// Whether Start() was ever called: what times nothing reads no time.
  bool IsUsed() const { return this->Used; }

  /// Times a stretch for as long as it lives: Start() now, Stop() on every
  /// way out of the scope.
  class Scope
  {
  public:
    explicit Scope(vtkShadowGPUTimer& timer)
      : Timer(timer)
    {
      this->Timer.Start();
    }
    ~Scope() { this->Timer.Stop(); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    vtkShadowGPUTimer& Timer;
  };

  /// Frees the queries; the context must be current.
  void ReleaseGraphicsResources();

private:
  vtkOpenGLRenderTimer Timer;
  double Milliseconds = 0.0;
  bool Used = false;
};

#endif
