// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * `softshadows view`: the scene in a window with VTK's trackball camera,
 * and keys to cycle techniques, size the lights, move the first light,
 * show light 0's visibility alone and save screenshots. A corner text shows
 * the technique, the lights' radius and the last frame's time; every change
 * is also printed on stdout, one line each, for scripts driving the window.
 */

#ifndef softshadows_Viewer_h
#define softshadows_Viewer_h

#include "SceneFile.h"
#include "Techniques.h"

#include <cstddef>
#include <vector>

class vtkRenderWindow;
class vtkRenderer;

namespace softshadows
{
/// The keys, as the viewer's help text and the README list them.
extern const char* const ViewerKeys;

/**
 * Shows `renderer` in `window` (on screen) until the window is closed or
 * `q` is pressed, starting with `techniques[first]`. Screenshots go to
 * `<scene name>-view-<n>.png` in the current folder.
 */
void RunViewer(const Scene& scene, vtkRenderer* renderer, vtkRenderWindow* window,
  std::vector<TechniqueInstance>& techniques, std::size_t first);
}

#endif
