// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Progress of long work (`reference`'s samples, ray casting, the techniques
 * of `bench` and `gallery`) on stderr: one line rewritten in place and
 * cleared when the work is done, only when stderr is a terminal and the
 * command was not given `--quiet`, so that scripts and logs see nothing.
 */

#ifndef softshadows_Progress_h
#define softshadows_Progress_h

#include <vtkSmartPointer.h>

#include <chrono>
#include <functional>
#include <string>

class vtkCallbackCommand;
class vtkObject;

namespace softshadows
{
class Progress
{
public:
  /// Shown when stderr is a terminal and not `quiet`.
  explicit Progress(bool quiet);
  ~Progress();

  bool Enabled() const { return this->Shown; }

  /// Shows `what` and the percentage `fraction` (in [0, 1]) stands for; at
  /// most ten lines a second, but always the first and the last.
  void Show(const std::string& what, double fraction);
  /// Clears the line, so that what is printed next starts on a clean one.
  void Clear();

  /**
   * While the returned object lives, `object`'s ProgressEvents (a double*
   * fraction, as vtkAlgorithm and vtkReferenceShadowPass send them) go to
   * `report`. Does nothing when progress is not shown.
   */
  class Observation
  {
  public:
    Observation() = default;
    Observation(vtkObject* object, std::function<void(double)> report);
    ~Observation();
    Observation(Observation&& other) noexcept;
    Observation& operator=(Observation&& other) noexcept;
    Observation(const Observation&) = delete;
    Observation& operator=(const Observation&) = delete;

  private:
    vtkObject* Object = nullptr;
    unsigned long Tag = 0;
    vtkSmartPointer<vtkCallbackCommand> Command;
    std::function<void(double)> Report;
  };
  Observation Observe(vtkObject* object, std::function<void(double)> report) const;

  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

private:
  bool Shown;
  bool LineOpen = false;
  std::chrono::steady_clock::time_point Last;
};
}

#endif
