// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// softshadows: render, compare and time the soft-shadow techniques on scenes
// described in JSON files: the README (commands) and docs/scene-format.md.

#include "Benchmark.h"
#include "CommandLine.h"
#include "Images.h"
#include "MessageCapture.h"
#include "Progress.h"
#include "Quality.h"
#include "SceneBuilder.h"
#include "SceneFile.h"
#include "Techniques.h"
#include "Viewer.h"
#include "Visibility.h"

#include "vtkSoftShadowPass.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace softshadows;

namespace
{
const char* const Usage =
  R"(Usage:
  softshadows techniques [--specs]
  softshadows render SCENE.json [--technique SPEC] [--size WxH] [--output FILE]
                     [--shadow-only] [--light I] [--debug-view] [--quiet]
  softshadows view SCENE.json [--technique SPEC] [--size WxH]
  softshadows bench SCENE.json --techniques SPEC,SPEC,... [--size WxH] [--frames N] [--json]
                    [--quiet]
  softshadows gallery SCENE.json --techniques SPEC,SPEC,... --output-dir DIR
                     [--size WxH] [--frames N] [--quiet]
  softshadows truth SCENE.json [--size WxH] [--output FILE] [--light I]
                    [--samples N] [--mask FILE] [--quiet]
  softshadows quality SCENE.json --techniques SPEC,SPEC,... [--size WxH]
                      [--light I] [--samples N] [--json] [--quiet]
  softshadows visibility SCENE.json [--output FILE.vtp] [--samples N] [--cells]
                         [--sun-latitude DEG [--sun-day N] [--sun-step HOURS]
                         [--sun-north X,Y,Z]] [--quiet]

SCENE.json is a scene file, or a model file (.gltf, .glb, .obj) staged on a
floor. A technique SPEC is name[:variant]; `softshadows techniques` lists them
with their parameters. Rendering needs an X display: run under `xvfb-run -a`.
Long work shows its progress on stderr when it is a terminal; --quiet hides it.

  techniques   list techniques, variants and parameters; --specs prints only
               every SPEC, one a line
  render       draw the scene to FILE (default <scene name>-<technique>.png);
               --shadow-only writes light I's visibility as grey + alpha;
               --debug-view marks umbra and penumbra (contact) or shows the
               signed distance map (silhouette)
  view         the scene in a window with VTK's trackball camera; keys cycle
               the techniques, size and move the lights, show the shadow
               alone and save screenshots (h lists them)
  bench        time the techniques in one window, taking turns in blocks of up
               to 5 frames, the first light moving; `hard` is added if missing;
               --json prints one JSON object per technique and line
  gallery      render each technique to DIR/<technique>.png, all of them side by
               side, labelled, to DIR/gallery.png, and print their timings
  truth        the ground truth of light I's visibility by ray casting (N rays
               a pixel, default 256; no display needed), written as
               --shadow-only writes a frame (default <scene name>-truth.png);
               --mask writes the pixels quality is measured on
  quality      each technique's shadow-only frame against the truth: RMSE and
               the share of pixels more than 0.1 off, over those pixels
  visibility   shadows as data: every face the scene draws, in world
               coordinates, with each light's visible fraction (N rays, default
               64) and the irradiance on its points (and --cells), written to
               FILE.vtp (default <scene name>-visibility.vtp; no display
               needed); --sun-latitude adds the hours of sun on day N (default
               80) in steps of HOURS (default 0.25), up the camera's view up,
               north X,Y,Z (default 0,0,-1)
)";

// Frames a technique draws, untimed, before `bench` and `gallery` time it:
// the first compiles shaders and allocates maps.
constexpr int WarmUpFrames = 3;

/// Technique names as file names: `contact:multipass` -> `contact_multipass`.
std::string FileNameOf(std::string text)
{
  // File systems refuse names past 255 bytes; the name has more added to it.
  text.resize(std::min<std::size_t>(text.size(), 100));
  for (char& c : text)
  {
    const bool plain =
      std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '_';
    c = plain ? c : '_';
  }
  return text;
}

/// Runs `step` and files any InputError it throws under the scene file.
template <typename Step>
auto InScene(const std::string& file, Step step)
{
  try
  {
    return step();
  }
  catch (const InputError& error)
  {
    throw error.InFile(file);
  }
}

/// The scene, its renderer, the techniques requested and the window.
class Session
{
public:
  /// Loads the scene and makes `specs`' passes; no specs: the scene's technique.
  Session(const CommandLine& line, std::vector<TechniqueSpec> specs)
  {
    this->Description = InScene(line.Scene(), [&] { return LoadScene(line.Scene()); });
    const SceneShadows& shadows = this->Description.Shadows;
    if (specs.empty())
    {
      // Checked when the scene was loaded.
      specs.push_back(ParseTechniqueSpec(shadows.Technique, "shadows.technique"));
    }
    for (const TechniqueSpec& spec : specs)
    {
      this->Techniques.push_back(
        CreateTechnique(spec, shadows.MapSize, shadows.ParametersOf(spec.Name)));
    }
    this->Renderer = InScene(line.Scene(), [&] { return BuildRenderer(this->Description); });
  }

  ~Session()
  {
    // Passes not on the renderer when the window goes are not released by
    // it, and VTK's shadow map baker complains when destroyed unreleased.
    if (!this->Window)
    {
      return;
    }
    for (const TechniqueInstance& technique : this->Techniques)
    {
      technique.Pass->ReleaseGraphicsResources(this->Window);
    }
  }

  /// Opens the window: `size`, or the scene's size when `size` is {0, 0}.
  vtkRenderWindow* OpenWindow(const std::array<int, 2>& size, bool withAlpha, bool onScreen = false)
  {
    this->Window =
      MakeWindow(this->Renderer, size[0] > 0 ? size : this->Description.Size, withAlpha, onScreen);
    return this->Window;
  }

  /// Draws one frame with `technique`.
  void Render(const TechniqueInstance& technique)
  {
    this->Renderer->SetPass(technique.Pass);
    this->Window->Render();
  }

  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  Scene Description;
  vtkSmartPointer<vtkRenderer> Renderer;
  std::vector<TechniqueInstance> Techniques;
  vtkSmartPointer<vtkRenderWindow> Window;
};

/// Fails the command when VTK logged an error while `watch` lived (a shader
/// that did not compile, a texture unit short...): the frame may be drawn,
/// but not as asked. VTK has printed the error already.
void FailOnError(const MessageCapture& watch)
{
  if (watch.HasError())
  {
    throw std::runtime_error("VTK reported an error while rendering: " + watch.FirstError());
  }
}

std::vector<TechniqueSpec> WithHard(std::vector<TechniqueSpec> specs)
{
  for (const TechniqueSpec& spec : specs)
  {
    if (spec.Name == "hard")
    {
      return specs;
    }
  }
  specs.insert(specs.begin(), ParseTechniqueSpec("hard", "hard"));
  return specs;
}

int ListTechniques(const std::vector<std::string>& arguments)
{
  CommandLine line("techniques", arguments, false, {}, { "--specs" });
  if (line.Has("--specs"))
  {
    for (const std::string& spec : AllTechniqueSpecs())
    {
      std::cout << spec << "\n";
    }
    return 0;
  }
  PrintTechniques(std::cout);
  return 0;
}

int Render(const std::vector<std::string>& arguments)
{
  CommandLine line("render", arguments, true, { "--technique", "--size", "--output", "--light" },
    { "--shadow-only", "--debug-view", "--quiet" });
  // Options first: their mistakes are found without reading the scene.
  const bool shadowOnly = line.Has("--shadow-only");
  if (line.Has("--light") && !shadowOnly)
  {
    throw InputError("--light", "only used with --shadow-only");
  }
  std::vector<TechniqueSpec> specs;
  if (line.Has("--technique"))
  {
    specs.push_back(ParseTechniqueSpec(line.Value("--technique"), "--technique"));
  }
  const int lightIndex = line.Integer("--light", 0, std::numeric_limits<int>::max(), 0);
  const std::array<int, 2> size = line.Size();

  Session session(line, specs);
  const Scene& scene = session.Description;
  TechniqueInstance& technique = session.Techniques.front();
  if (line.Has("--debug-view"))
  {
    // The techniques' `debug_view` parameter (contact: the paper's figure 4
    // view; silhouette: the signed distance map).
    if (!SetTechniqueParameter(technique, "debug_view", Json(true)))
    {
      throw InputError("--debug-view",
        "technique '" + technique.Spec + "' has no debug view (contact and silhouette have one)");
    }
  }
  if (shadowOnly)
  {
    if (!technique.Shadows)
    {
      throw InputError("--shadow-only",
        "technique '" + technique.Spec + "' (VTK's vtkShadowMapPass) has no shadow-only output");
    }
    if (lightIndex >= static_cast<int>(scene.Lights.size()))
    {
      throw InputError("--light",
        "the scene has " + std::to_string(scene.Lights.size()) + " light(s); got index " +
          std::to_string(lightIndex));
    }
    // Visibility in red, coverage in alpha: black, transparent background.
    technique.Shadows->SetShadowOnlyLight(lightIndex);
    session.Renderer->SetBackground(0.0, 0.0, 0.0);
    session.Renderer->SetBackgroundAlpha(0.0);
  }

  const std::filesystem::path output = line.Has("--output")
    ? std::filesystem::path(line.Value("--output"))
    : std::filesystem::path(FileNameOf(scene.Name) + "-" + FileNameOf(technique.Spec) + ".png");

  vtkRenderWindow* window = session.OpenWindow(size, shadowOnly);
  MessageCapture watch(MessageCapture::Mode::Watch);
  Progress progress(line.Has("--quiet"));
  {
    Progress::Observation samples = progress.Observe(technique.Shadows,
      [&](double fraction) { progress.Show(technique.Spec + ": samples", fraction); });
    session.Render(technique);
  }
  progress.Clear();
  vtkSmartPointer<vtkImageData> image = CaptureWindow(window, shadowOnly);
  WritePNG(shadowOnly ? GreyAndAlpha(image) : image, output);
  std::cout << "wrote " << output.string() << "\n";
  FailOnError(watch);
  return 0;
}

int Bench(const std::vector<std::string>& arguments)
{
  CommandLine line(
    "bench", arguments, true, { "--techniques", "--size", "--frames" }, { "--json", "--quiet" });
  const std::vector<TechniqueSpec> specs = WithHard(line.TechniqueList("--techniques"));
  const int frames = line.Integer("--frames", 1, 100000, 30);
  const std::array<int, 2> size = line.Size();

  Session session(line, specs);
  vtkRenderWindow* window = session.OpenWindow(size, false);
  MessageCapture watch(MessageCapture::Mode::Watch);
  Progress progress(line.Has("--quiet"));
  const std::vector<Timing> timings = RunBenchmark(window, session.Renderer, session.Techniques,
    frames, WarmUpFrames, session.Description.Shadows.MapSize, &progress);
  progress.Clear();
  if (line.Has("--json"))
  {
    PrintTimingJson(std::cout, timings);
  }
  else
  {
    PrintTimingTable(std::cout, timings);
  }
  FailOnError(watch);
  return 0;
}

int Gallery(const std::vector<std::string>& arguments)
{
  CommandLine line("gallery", arguments, true,
    { "--techniques", "--output-dir", "--size", "--frames" }, { "--quiet" });
  const std::vector<TechniqueSpec> shown = line.TechniqueList("--techniques");
  const std::filesystem::path folder = line.Value("--output-dir");
  const int frames = line.Integer("--frames", 1, 100000, 10);
  const std::array<int, 2> size = line.Size();

  // The timings need `hard` for their ratios; the pictures show what was asked.
  Session session(line, WithHard(shown));
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error)
  {
    throw std::runtime_error("cannot create " + folder.string() + ": " + error.message());
  }

  vtkRenderWindow* window = session.OpenWindow(size, false);
  MessageCapture watch(MessageCapture::Mode::Watch);
  Progress progress(line.Has("--quiet"));
  std::vector<vtkSmartPointer<vtkImageData>> tiles;
  for (const TechniqueInstance& technique : session.Techniques)
  {
    const bool wanted = std::any_of(shown.begin(), shown.end(),
      [&](const TechniqueSpec& spec) { return spec.ToString() == technique.Spec; });
    if (!wanted)
    {
      continue;
    }
    const double done = static_cast<double>(tiles.size()) / static_cast<double>(shown.size());
    const std::string what = "gallery: " + technique.Spec + " (" +
      std::to_string(tiles.size() + 1) + "/" + std::to_string(shown.size()) + ")";
    progress.Show(what, done);
    {
      Progress::Observation samples = progress.Observe(technique.Shadows,
        [&](double fraction)
        { progress.Show(what, done + fraction / static_cast<double>(shown.size())); });
      session.Render(technique);
    }
    progress.Clear();
    vtkSmartPointer<vtkImageData> image = CaptureWindow(window, false);
    const std::filesystem::path file = folder / (FileNameOf(technique.Spec) + ".png");
    WritePNG(image, file);
    std::cout << "wrote " << file.string() << "\n";
    DrawLabel(image, technique.Spec);
    tiles.push_back(image);
  }
  const int count = static_cast<int>(tiles.size());
  const int columns = count <= 3 ? count : static_cast<int>(std::ceil(std::sqrt(count)));
  WritePNG(ComposeGrid(tiles, columns), folder / "gallery.png");
  std::cout << "wrote " << (folder / "gallery.png").string() << "\n\n";

  const std::vector<Timing> timings = RunBenchmark(window, session.Renderer, session.Techniques,
    frames, WarmUpFrames, session.Description.Shadows.MapSize, &progress);
  progress.Clear();
  PrintTimingTable(std::cout, timings);
  FailOnError(watch);
  return 0;
}

int View(const std::vector<std::string>& arguments)
{
  CommandLine line("view", arguments, true, { "--technique", "--size" }, {});
  std::vector<TechniqueSpec> specs;
  for (const std::string& spec : AllTechniqueSpecs())
  {
    specs.push_back(ParseTechniqueSpec(spec, spec));
  }
  // The technique asked for (or the scene's) first shown, wherever it is
  // in the cycle; one the cycle lacks (a default variant named) joins it.
  const std::string asked = line.Has("--technique")
    ? ParseTechniqueSpec(line.Value("--technique"), "--technique").ToString()
    : std::string();
  Session session(line, specs);
  const std::string first = asked.empty() ? session.Description.Shadows.Technique : asked;
  auto found = std::find_if(session.Techniques.begin(), session.Techniques.end(),
    [&](const TechniqueInstance& technique) { return technique.Spec == first; });
  if (found == session.Techniques.end())
  {
    const TechniqueSpec spec = ParseTechniqueSpec(first, "--technique");
    session.Techniques.insert(session.Techniques.begin(),
      CreateTechnique(spec, session.Description.Shadows.MapSize,
        session.Description.Shadows.ParametersOf(spec.Name)));
    found = session.Techniques.begin();
  }
  const auto index = static_cast<std::size_t>(found - session.Techniques.begin());
  vtkRenderWindow* window = session.OpenWindow(line.Size(), false, true);
  window->SetWindowName(("softshadows: " + session.Description.Name).c_str());
  std::cout << ViewerKeys << std::flush;
  RunViewer(session.Description, session.Renderer, window, session.Techniques, index);
  return 0;
}

/// Light I of the scene (--light), checked against its lights.
int LightOption(const CommandLine& line, const Scene& scene)
{
  const int light = line.Integer("--light", 0, std::numeric_limits<int>::max(), 0);
  if (light >= static_cast<int>(scene.Lights.size()))
  {
    throw InputError("--light",
      "the scene has " + std::to_string(scene.Lights.size()) + " light(s); got index " +
        std::to_string(light));
  }
  return light;
}

int Truth(const std::vector<std::string>& arguments)
{
  CommandLine line("truth", arguments, true,
    { "--size", "--output", "--light", "--samples", "--mask" }, { "--quiet" });
  const std::array<int, 2> size = line.Size();
  const int samples = line.Integer("--samples", 1, 65536, 256);
  Session session(line, {});
  const Scene& scene = session.Description;
  const int light = LightOption(line, scene);
  Progress progress(line.Has("--quiet"));
  vtkSmartPointer<vtkImageData> truth =
    CastTruth(session.Renderer, size[0] > 0 ? size : scene.Size, light, samples, &progress);
  const std::filesystem::path output = line.Has("--output")
    ? std::filesystem::path(line.Value("--output"))
    : std::filesystem::path(FileNameOf(scene.Name) + "-truth.png");
  WritePNG(TruthImage(truth), output);
  std::cout << "wrote " << output.string() << "\n";
  if (line.Has("--mask"))
  {
    WritePNG(MaskImage(truth), line.Value("--mask"));
    std::cout << "wrote " << line.Value("--mask") << "\n";
  }
  return 0;
}

int Quality(const std::vector<std::string>& arguments)
{
  CommandLine line("quality", arguments, true, { "--techniques", "--size", "--light", "--samples" },
    { "--json", "--quiet" });
  const std::vector<TechniqueSpec> specs = line.TechniqueList("--techniques");
  const int samples = line.Integer("--samples", 1, 65536, 256);
  Session session(line, specs);
  const Scene& scene = session.Description;
  const int light = LightOption(line, scene);
  for (const TechniqueInstance& technique : session.Techniques)
  {
    if (!technique.Shadows)
    {
      throw InputError("--techniques",
        "technique '" + technique.Spec + "' (VTK's vtkShadowMapPass) has no shadow-only output");
    }
    technique.Shadows->SetShadowOnlyLight(light);
  }
  const std::array<int, 2> pixels = line.Size()[0] > 0 ? line.Size() : scene.Size;
  Progress progress(line.Has("--quiet"));
  vtkSmartPointer<vtkImageData> truth =
    CastTruth(session.Renderer, pixels, light, samples, &progress);
  session.Renderer->SetBackground(0.0, 0.0, 0.0);
  session.Renderer->SetBackgroundAlpha(0.0);
  vtkRenderWindow* window = session.OpenWindow(pixels, true);
  MessageCapture watch(MessageCapture::Mode::Watch);
  const bool json = line.Has("--json");
  if (!json)
  {
    std::cout << "against the ray-cast truth (" << samples << " rays a pixel), " << pixels[0] << "x"
              << pixels[1] << ", light " << light << ":\n";
    std::printf("%-24s %8s %9s %8s %7s %9s\n", "technique", "RMSE", "mismatch", "pixels", "umbra",
      "penumbra");
  }
  for (const TechniqueInstance& technique : session.Techniques)
  {
    {
      Progress::Observation samples = progress.Observe(technique.Shadows,
        [&](double fraction) { progress.Show(technique.Spec + ": samples", fraction); });
      session.Render(technique);
    }
    progress.Clear();
    const QualityFigures figures = CompareWithTruth(CaptureWindow(window, true), truth);
    if (json)
    {
      std::printf("{\"technique\": \"%s\", \"rmse\": %.5f, \"mismatch\": %.5f, "
                  "\"pixels\": %ld, \"samples\": %d, \"size\": [%d, %d], \"umbra\": %.5f, "
                  "\"penumbra_ratio\": %.5f}\n",
        technique.Spec.c_str(), figures.RMSE, figures.Mismatch, figures.Pixels, samples, pixels[0],
        pixels[1], figures.Umbra, figures.PenumbraRatio);
    }
    else
    {
      std::printf("%-24s %8.4f %8.1f%% %8ld %7.3f %9.2f\n", technique.Spec.c_str(), figures.RMSE,
        100.0 * figures.Mismatch, figures.Pixels, figures.Umbra, figures.PenumbraRatio);
    }
  }
  FailOnError(watch);
  return 0;
}

int Visibility(const std::vector<std::string>& arguments)
{
  CommandLine line("visibility", arguments, true,
    { "--output", "--samples", "--sun-latitude", "--sun-day", "--sun-step", "--sun-north" },
    { "--cells", "--quiet" });
  const int samples = line.Integer("--samples", 1, 65536, 64);
  SunDay sun;
  sun.On = line.Has("--sun-latitude");
  for (const char* option : { "--sun-day", "--sun-step", "--sun-north" })
  {
    if (line.Has(option) && !sun.On)
    {
      throw InputError(option, "only used with --sun-latitude");
    }
  }
  sun.Latitude = line.Number("--sun-latitude", -90.0, 90.0, 0.0);
  sun.Day = line.Integer("--sun-day", 1, 366, 80);
  sun.Step = line.Number("--sun-step", 1.0 / 60.0, 24.0, 0.25);
  sun.North = line.Vector("--sun-north", sun.North);
  Session session(line, {});
  const Scene& scene = session.Description;
  sun.Up = scene.Camera.ViewUp;
  const std::array<double, 3>& u = sun.Up;
  const std::array<double, 3>& n = sun.North;
  const double across[3] = { u[1] * n[2] - u[2] * n[1], u[2] * n[0] - u[0] * n[2],
    u[0] * n[1] - u[1] * n[0] };
  if (sun.On &&
    !(std::hypot(across[0], across[1], across[2]) >
      1.0e-9 * std::hypot(u[0], u[1], u[2]) * std::hypot(n[0], n[1], n[2])))
  {
    throw InputError("--sun-north", "must not be parallel to the scene camera's view up");
  }
  Progress progress(line.Has("--quiet"));
  vtkSmartPointer<vtkPolyData> surfaces =
    CastVisibility(session.Renderer, samples, line.Has("--cells"), sun, &progress);
  const std::filesystem::path output = line.Has("--output")
    ? std::filesystem::path(line.Value("--output"))
    : std::filesystem::path(FileNameOf(scene.Name) + "-visibility.vtp");
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(surfaces);
  writer->SetFileName(output.string().c_str());
  if (!writer->Write())
  {
    throw std::runtime_error("could not write " + output.string());
  }
  std::cout << "wrote " << output.string() << " (" << surfaces->GetNumberOfPoints() << " points, "
            << scene.Lights.size() << " light(s)" << (sun.On ? ", the sun's hours" : "") << ")\n";
  return 0;
}

int Run(const std::vector<std::string>& arguments)
{
  if (arguments.empty())
  {
    std::cerr << Usage;
    return 2;
  }
  const std::string& command = arguments.front();
  const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
  if (command == "help" || command == "--help" || command == "-h")
  {
    std::cout << Usage;
    return 0;
  }
  if (command == "techniques")
  {
    return ListTechniques(rest);
  }
  if (command == "render")
  {
    return Render(rest);
  }
  if (command == "bench")
  {
    return Bench(rest);
  }
  if (command == "gallery")
  {
    return Gallery(rest);
  }
  if (command == "truth")
  {
    return Truth(rest);
  }
  if (command == "view")
  {
    return View(rest);
  }
  if (command == "quality")
  {
    return Quality(rest);
  }
  if (command == "visibility")
  {
    return Visibility(rest);
  }
  throw InputError(command,
    "unknown command (known: techniques, render, view, bench, gallery, truth, quality, "
    "visibility, help)");
}
}

int main(int argc, char* argv[])
{
  try
  {
    return Run(std::vector<std::string>(argv + 1, argv + argc));
  }
  catch (const InputError& error)
  {
    std::cerr << (error.File().empty() ? "softshadows" : error.File()) << ": "
              << (error.Where().empty() ? "" : error.Where() + ": ") << error.what() << "\n";
    return 2;
  }
  catch (const std::exception& error)
  {
    std::cerr << "softshadows: error: " << error.what() << "\n";
    return 1;
  }
}
