// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Quality against physics: the ray-cast truth of a scene's light visibility
 * (vtkRayCastLightVisibility), its images, and how far a technique's
 * shadow-only frame is from it (docs/quality.md).
 */

#ifndef softshadows_Quality_h
#define softshadows_Quality_h

#include "Progress.h"

#include <vtkSmartPointer.h>

#include <array>

class vtkAlgorithm;
class vtkImageData;
class vtkRenderer;

namespace softshadows
{
/// Updates a ray-casting algorithm (the truth, the light visibility
/// filter), its progress shown on `progress`; throws std::runtime_error
/// with VTK's first message when it reports an error.
void UpdateRayCasting(vtkAlgorithm* caster, Progress* progress);

/// The truth for light `light` of `renderer`, at `size` pixels; the ray
/// casting's progress shown on `progress`.
vtkSmartPointer<vtkImageData> CastTruth(vtkRenderer* renderer, const std::array<int, 2>& size,
  int light, int samples, Progress* progress = nullptr);

/// The truth as `render --shadow-only` writes a frame: grey visibility, alpha coverage.
vtkSmartPointer<vtkImageData> TruthImage(vtkImageData* truth);

/// The pixels quality is measured on, grey: 255 measured, 0 not.
vtkSmartPointer<vtkImageData> MaskImage(vtkImageData* truth);

struct QualityFigures
{
  double RMSE = 0.0;     ///< of visibility, over the mask
  double Mismatch = 0.0; ///< share of the mask's pixels more than MismatchTolerance off
  long Pixels = 0;       ///< in the mask
  /// Mean visibility where the truth is umbra (at most UmbraLevel): 0 when
  /// the umbra is as dark as the truth's.
  double Umbra = 0.0;
  /// Pixels in penumbra (strictly between UmbraLevel and 1 - UmbraLevel),
  /// the frame's over the truth's: 1 when penumbrae are as wide.
  double PenumbraRatio = 0.0;
};

/// Visibility within this of 0 is umbra, within this of 1 lit.
constexpr double UmbraLevel = 0.02;

/// A visible error: a tenth of the way between lit and umbra.
constexpr double MismatchTolerance = 0.1;

/// A shadow-only RGBA capture (visibility in red) against the truth.
QualityFigures CompareWithTruth(vtkImageData* shadowOnly, vtkImageData* truth);
}

#endif
