// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowGPUTimer.h"

//------------------------------------------------------------------------------
void vtkShadowGPUTimer::Start()
{
  this->Timer.ReusableStart();
  this->Used = true;
}

//------------------------------------------------------------------------------
void vtkShadowGPUTimer::Stop()
{
  this->Timer.ReusableStop();
  // 0 while no flight of queries has completed since the last one read.
  const double seconds = this->Timer.GetReusableElapsedSeconds();
  if (seconds > 0.0)
  {
    this->Milliseconds = 1000.0 * seconds;
  }
}

//------------------------------------------------------------------------------
void vtkShadowGPUTimer::ReleaseGraphicsResources()
{
  this->Timer.ReleaseGraphicsResources();
}
