// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Viewer.h"

#include "Images.h"

#include "vtkSoftShadowPass.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

namespace softshadows
{
const char* const ViewerKeys =
  R"(Keys (besides VTK's trackball: drag to rotate, wheel to zoom, r to reset):
  n / b          next / previous technique and variant
  + / -          grow / shrink every light's radius (by 1.25; - to 0 at last)
  arrow keys     orbit the first light about its focal point (5 degrees)
  o              light 0's visibility alone (shadow only), or back
  k              save a screenshot, <scene>-view-<n>.png
  h              this help, on stdout and in the window
  q              quit
)";

namespace
{
bool IsArrow(const std::string& sym)
{
  return sym == "Left" || sym == "Right" || sym == "Up" || sym == "Down";
}

/// The state the keys change, and the frame it is drawn in.
class Viewer
{
public:
  Viewer(const Scene& scene, vtkRenderer* renderer, vtkRenderWindow* window,
    std::vector<TechniqueInstance>& techniques, std::size_t first)
    : Description(scene)
    , Renderer(renderer)
    , Window(window)
    , Techniques(techniques)
    , Current(first)
  {
    double bounds[6];
    renderer->ComputeVisiblePropBounds(bounds);
    this->Diagonal = std::max(1e-6,
      std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
        (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
        (bounds[5] - bounds[4]) * (bounds[5] - bounds[4])));
    this->Text->GetTextProperty()->SetFontSize(14);
    this->Text->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
    this->Text->GetTextProperty()->ShadowOn();
    // The help's columns line up.
    this->Text->GetTextProperty()->SetFontFamilyToCourier();
    this->Text->SetDisplayPosition(8, 8);
    renderer->AddActor2D(this->Text);
    renderer->GetBackground(this->Background.data());
  }

  /// Handles a key VTK's style gets; false leaves it to the style.
  bool Key(const std::string& sym, char code)
  {
    if (code == 'n' || code == 'b')
    {
      const std::size_t count = this->Techniques.size();
      this->Select((this->Current + (code == 'n' ? 1 : count - 1)) % count);
    }
    else if (code == '+' || code == '=' || sym == "KP_Add")
    {
      this->ScaleRadii(1.25);
    }
    else if (code == '-' || sym == "KP_Subtract")
    {
      this->ScaleRadii(1.0 / 1.25);
    }
    else if (IsArrow(sym))
    {
      this->OrbitLight(sym == "Left" ? -5.0
          : sym == "Right"           ? 5.0
                                     : 0.0,
        sym == "Up"       ? 5.0
          : sym == "Down" ? -5.0
                          : 0.0);
    }
    else if (code == 'o')
    {
      this->ShadowOnly = !this->ShadowOnly;
      this->ApplyShadowOnly();
    }
    else if (code == 'k')
    {
      this->Screenshot();
      return true;
    }
    else if (code == 'h')
    {
      std::cout << ViewerKeys << std::flush;
      this->Help = !this->Help;
    }
    else
    {
      return false;
    }
    this->Report();
    this->Window->Render();
    return true;
  }

  void Select(std::size_t index)
  {
    // Only the pass in use keeps its maps: 15 techniques' would add up.
    if (index != this->Current)
    {
      this->Techniques[this->Current].Pass->ReleaseGraphicsResources(this->Window);
      if (vtkSoftShadowPass* old = this->Techniques[this->Current].Shadows)
      {
        old->SetShadowOnlyLight(-1);
      }
    }
    this->Current = index;
    this->Renderer->SetPass(this->Techniques[index].Pass);
    this->ApplyShadowOnly();
  }

  /// The first frame's state, on stdout.
  void Report()
  {
    std::cout << "technique " << this->Techniques[this->Current].Spec << ", light radius "
              << this->RadiusText() << ", shadow only " << (this->ShadowOnly ? "on" : "off")
              << std::endl;
  }

  /// Before each frame: the corner text, with the last frame's time.
  void StartFrame()
  {
    std::ostringstream text;
    text << this->Techniques[this->Current].Spec << "   light radius " << this->RadiusText();
    if (this->LastFrameMs >= 0.0)
    {
      text.precision(1);
      text << std::fixed << "   " << this->LastFrameMs << " ms";
    }
    if (this->ShadowOnly)
    {
      text << (this->Techniques[this->Current].Shadows ? "   shadow only (light 0)"
                                                       : "   (no shadow-only view)");
    }
    text << (this->Help ? std::string("\n\n") + ViewerKeys : std::string("   h: keys"));
    this->Text->SetInput(text.str().c_str());
    this->Start = std::chrono::steady_clock::now();
  }

  void EndFrame()
  {
    this->Window->WaitForCompletion();
    const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - this->Start;
    this->LastFrameMs = elapsed.count();
  }

private:
  std::string RadiusText() const
  {
    vtkLightCollection* lights = this->Renderer->GetLights();
    lights->InitTraversal();
    vtkLight* light = lights->GetNextItem();
    if (!light)
    {
      return "(no lights)";
    }
    std::ostringstream text;
    text.precision(3);
    text << vtkSoftShadowPass::GetRadius(light) << (light->GetPositional() ? "" : " deg");
    return text.str();
  }

  void ScaleRadii(double factor)
  {
    vtkLightCollection* lights = this->Renderer->GetLights();
    lights->InitTraversal();
    while (vtkLight* light = lights->GetNextItem())
    {
      // A point light grows to a hundredth of the scene first; the sun's
      // angular radius (0.27 degrees) is where a directional one starts.
      const double start = light->GetPositional() ? 0.01 * this->Diagonal : 0.25;
      const double maximum = light->GetPositional() ? this->Diagonal : 45.0;
      double radius = vtkSoftShadowPass::GetRadius(light);
      if (factor > 1.0)
      {
        radius = radius > 0.0 ? std::min(maximum, radius * factor) : start;
      }
      else
      {
        radius = radius * factor < start / 2.0 ? 0.0 : radius * factor;
      }
      vtkSoftShadowPass::SetRadius(radius, light);
    }
  }

  /// The first light's position about its focal point, in degrees: azimuth
  /// about y (up), elevation towards it, kept off the poles.
  void OrbitLight(double azimuth, double elevation)
  {
    vtkLightCollection* lights = this->Renderer->GetLights();
    lights->InitTraversal();
    vtkLight* light = lights->GetNextItem();
    if (!light)
    {
      return;
    }
    const double* p = light->GetPosition();
    const double* f = light->GetFocalPoint();
    const double d[3] = { p[0] - f[0], p[1] - f[1], p[2] - f[2] };
    const double distance = vtkMath::Norm(d);
    if (distance <= 0.0)
    {
      return;
    }
    double around = std::atan2(d[0], d[2]) + vtkMath::RadiansFromDegrees(azimuth);
    double up =
      std::asin(std::clamp(d[1] / distance, -1.0, 1.0)) + vtkMath::RadiansFromDegrees(elevation);
    up = std::clamp(up, vtkMath::RadiansFromDegrees(-85.0), vtkMath::RadiansFromDegrees(85.0));
    light->SetPosition(f[0] + distance * std::cos(up) * std::sin(around),
      f[1] + distance * std::sin(up), f[2] + distance * std::cos(up) * std::cos(around));
  }

  void ApplyShadowOnly()
  {
    vtkSoftShadowPass* shadows = this->Techniques[this->Current].Shadows;
    if (shadows)
    {
      shadows->SetShadowOnlyLight(this->ShadowOnly ? 0 : -1);
    }
    if (this->ShadowOnly && shadows)
    {
      this->Renderer->SetBackground(0.0, 0.0, 0.0);
    }
    else
    {
      this->Renderer->SetBackground(this->Background.data());
    }
  }

  void Screenshot()
  {
    vtkNew<vtkWindowToImageFilter> capture;
    capture->SetInput(this->Window);
    capture->SetInputBufferTypeToRGB();
    capture->Update();
    const std::string file =
      this->Description.Name + "-view-" + std::to_string(this->Screenshots++) + ".png";
    try
    {
      WritePNG(capture->GetOutput(), file);
      std::cout << "wrote " << file << std::endl;
    }
    catch (const std::runtime_error& error)
    {
      std::cerr << "softshadows: " << error.what() << std::endl;
    }
  }

  const Scene& Description;
  vtkRenderer* Renderer;
  vtkRenderWindow* Window;
  std::vector<TechniqueInstance>& Techniques;
  std::size_t Current;
  double Diagonal = 1.0;
  bool ShadowOnly = false;
  bool Help = false;
  int Screenshots = 0;
  std::array<double, 3> Background{ 0.0, 0.0, 0.0 };
  double LastFrameMs = -1.0;
  std::chrono::steady_clock::time_point Start;
  vtkNew<vtkTextActor> Text;
};

/// VTK's trackball camera, with the viewer's keys first.
class ViewerStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static ViewerStyle* New();
  vtkTypeMacro(ViewerStyle, vtkInteractorStyleTrackballCamera);

  Viewer* Keys = nullptr;

  void OnChar() override
  {
    vtkRenderWindowInteractor* interactor = this->GetInteractor();
    const std::string sym = interactor->GetKeySym() ? interactor->GetKeySym() : "";
    if (IsArrow(sym))
    {
      return; // OnKeyPress() took it
    }
    if (!this->Keys->Key(sym, interactor->GetKeyCode()))
    {
      this->Superclass::OnChar();
    }
  }

  void OnKeyPress() override
  {
    // Arrow keys send no character: they come here only.
    vtkRenderWindowInteractor* interactor = this->GetInteractor();
    const std::string sym = interactor->GetKeySym() ? interactor->GetKeySym() : "";
    if (IsArrow(sym))
    {
      this->Keys->Key(sym, 0);
      return;
    }
    this->Superclass::OnKeyPress();
  }
};
vtkStandardNewMacro(ViewerStyle);
}

//------------------------------------------------------------------------------
void RunViewer(const Scene& scene, vtkRenderer* renderer, vtkRenderWindow* window,
  std::vector<TechniqueInstance>& techniques, std::size_t first)
{
  Viewer viewer(scene, renderer, window, techniques, first);
  viewer.Select(first);

  vtkNew<vtkCallbackCommand> start;
  start->SetClientData(&viewer);
  start->SetCallback(
    [](vtkObject*, unsigned long, void* self, void*) { static_cast<Viewer*>(self)->StartFrame(); });
  vtkNew<vtkCallbackCommand> end;
  end->SetClientData(&viewer);
  end->SetCallback(
    [](vtkObject*, unsigned long, void* self, void*) { static_cast<Viewer*>(self)->EndFrame(); });
  window->AddObserver(vtkCommand::StartEvent, start);
  window->AddObserver(vtkCommand::EndEvent, end);

  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<ViewerStyle> style;
  style->Keys = &viewer;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(window);
  interactor->Initialize();
  window->Render();
  viewer.Report();
  interactor->Start();
  window->RemoveObserver(start);
  window->RemoveObserver(end);
}
}
