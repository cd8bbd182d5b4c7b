// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Progress.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkObject.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace softshadows
{
//------------------------------------------------------------------------------
Progress::Progress(bool quiet)
  : Shown(!quiet && ::isatty(STDERR_FILENO) == 1)
{
}

//------------------------------------------------------------------------------
Progress::~Progress()
{
  this->Clear();
}

//------------------------------------------------------------------------------
void Progress::Show(const std::string& what, double fraction)
{
  if (!this->Shown)
  {
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  const bool last = fraction >= 1.0;
  if (this->LineOpen && !last && now - this->Last < std::chrono::milliseconds(100))
  {
    return;
  }
  this->Last = now;
  const int percent = static_cast<int>(std::floor(100.0 * std::clamp(fraction, 0.0, 1.0)));
  // Back to the line's start, the text, and the rest of the old line erased.
  std::fprintf(stderr, "\r%s %3d%%\033[K", what.c_str(), percent);
  std::fflush(stderr);
  this->LineOpen = true;
}

//------------------------------------------------------------------------------
void Progress::Clear()
{
  if (this->LineOpen)
  {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    this->LineOpen = false;
  }
}

//------------------------------------------------------------------------------
Progress::Observation Progress::Observe(vtkObject* object, std::function<void(double)> report) const
{
  if (!this->Shown || !object)
  {
    return {};
  }
  return Observation(object, std::move(report));
}

//------------------------------------------------------------------------------
Progress::Observation::Observation(vtkObject* object, std::function<void(double)> report)
  : Object(object)
  , Command(vtkSmartPointer<vtkCallbackCommand>::New())
  , Report(std::move(report))
{
  this->Command->SetClientData(&this->Report);
  this->Command->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void* callData)
    {
      if (callData)
      {
        (*static_cast<std::function<void(double)>*>(clientData))(*static_cast<double*>(callData));
      }
    });
  this->Tag = object->AddObserver(vtkCommand::ProgressEvent, this->Command);
}

//------------------------------------------------------------------------------
Progress::Observation::~Observation()
{
  if (this->Object)
  {
    this->Object->RemoveObserver(this->Tag);
  }
}

//------------------------------------------------------------------------------
Progress::Observation::Observation(Observation&& other) noexcept
{
  *this = std::move(other);
}

//------------------------------------------------------------------------------
Progress::Observation& Progress::Observation::operator=(Observation&& other) noexcept
{
  if (this != &other)
  {
    if (this->Object)
    {
      this->Object->RemoveObserver(this->Tag);
    }
    this->Object = other.Object;
    this->Tag = other.Tag;
    this->Command = std::move(other.Command);
    this->Report = std::move(other.Report);
    // The callback holds the address of the function it calls: this one's.
    if (this->Command)
    {
      this->Command->SetClientData(&this->Report);
    }
    other.Object = nullptr;
  }
  return *this;
}
}
