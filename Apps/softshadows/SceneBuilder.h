// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Turns a checked Scene into VTK objects: a renderer with the scene's lights,
 * actors and camera, and an off-screen window to draw it in.
 */

#ifndef softshadows_SceneBuilder_h
#define softshadows_SceneBuilder_h

#include "SceneFile.h"

#include <vtkSmartPointer.h>

#include <array>

class vtkRenderWindow;
class vtkRenderer;

namespace softshadows
{
/**
 * Makes the renderer: actors (meshes read or made, normals added where
 * missing; models imported), scene lights with their radius, background and
 * camera. A scene without lights takes its models' lights, one without a
 * camera the first model camera: both are written into `scene`, as is a
 * staged scene's light. Throws InputError at `actors[i].file` or
 * `actors[i].import` when a file cannot be read.
 */
vtkSmartPointer<vtkRenderer> BuildRenderer(Scene& scene);

/**
 * An off-screen window (on screen when `onScreen`) of `size` pixels showing `renderer`, without
 * multisampling (the shadow passes draw into their own framebuffers), with
 * an alpha channel when `withAlpha`. Throws std::runtime_error when there is
 * no X display or OpenGL context.
 */
vtkSmartPointer<vtkRenderWindow> MakeWindow(
  vtkRenderer* renderer, const std::array<int, 2>& size, bool withAlpha, bool onScreen = false);
}

#endif
