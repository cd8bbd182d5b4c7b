#include "vtkContactHardeningShadowPass.h"

#include "vtkCamera.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowSampling.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkContactCommonFS.h"
#include "vtkContactDistanceFS.h"
#include "vtkContactGaussianFS.h"
#include "vtkContactMultiPassFS.h"
#include "vtkContactPCFFS.h"
#include "vtkContactPrepareFS.h"
#include "vtkContactResolveFS.h"
#include "vtkShadowCubeLookupFS.h"
#include "vtkShadowNormalOffsetFS.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include <array>
#include <cmath>
#include <string>

namespace
{
constexpr int MaximumTaps = 64;

vtkSmartPointer<vtkTextureObject> FloatTexture(vtkOpenGLRenderWindow* context, int w, int h)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(context);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetInternalFormat(GL_RGBA16F);
  texture->SetFormat(GL_RGBA);
  texture->SetDataType(GL_FLOAT);
  texture->Allocate2D(w, h, 4, VTK_FLOAT);
  return texture;
}
}

class vtkContactHardeningShadowPass::vtkInternals
{
public:
  std::unique_ptr<vtkOpenGLQuadHelper> Distance, DistanceCube, Prepare, MultiPass, PCF, Gaussian,
    Resolve;
  // Contact maps: [0] pass 2's output, [1] and [2] the ping-pong pair.
  std::array<vtkSmartPointer<vtkTextureObject>, 3> Maps;
  // Depth used as a pixel mask: which blur passes draw a pixel (see the
  // prepare pass).
  vtkSmartPointer<vtkTextureObject> Mask;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  unsigned int RawDepthSampler = 0;   // reads a depth map without comparison
  unsigned int Queries[2] = { 0, 0 }; // did the last blur pass draw any pixel?
  float DistanceUnit = 1.0f;          // camera distances in the maps, in world units
  bool Unsupported = false;
  // Section 3.1: up to 64 Poisson-disk points in [-1,1]^2, the first at the
  // origin.
  std::vector<glm::vec2> Poisson = vtkShadowSampling::PoissonDisk(MaximumTaps, 7, false, true);

  /// Offsets and normalised Gaussian weights of the first `count` points,
  /// with sigma = size / 3 for offsets scaled by size / 2 (the weights do not
  /// depend on the size); and the per-axis variance of that kernel per
  /// pixel^2 of size^2.
  std::vector<float> Taps(int count, float& variance) const
  {
    std::vector<float> taps;
    float total = 0.0f;
    for (int i = 0; i < count; ++i)
    {
      const float r2 = glm::dot(this->Poisson[i], this->Poisson[i]);
      const float w = std::exp(-r2 * 9.0f / 8.0f);
      taps.insert(taps.end(), { this->Poisson[i].x, this->Poisson[i].y, w });
      total += w;
    }
    variance = 0.0f;
    for (int i = 0; i < count; ++i)
    {
      taps[3 * i + 2] /= total;
      variance += taps[3 * i + 2] * 0.25f * 0.5f * glm::dot(this->Poisson[i], this->Poisson[i]);
    }
    return taps;
  }

  void Draw(vtkShadowScreenBuffers* screen, std::unique_ptr<vtkOpenGLQuadHelper>& quad,
    vtkTextureObject* input, const std::function<void(vtkShaderProgram*)>& uniforms,
    float depthTolerance, bool debugView,
    vtkShadowScreenBuffers::QuadMask mask = vtkShadowScreenBuffers::QuadMask::None,
    float quadDepth = 0.5f)
  {
    if (input)
    {
      input->Activate();
    }
    screen->DrawQuad(
      quad.get(),
      [&](vtkShaderProgram* program)
      {
        if (input)
        {
          program->SetUniformi("contactMap", input->GetTextureUnit());
        }
        program->SetUniformf("contactDepthTolerance", depthTolerance);
        program->SetUniformf("contactDistanceUnit", this->DistanceUnit);
        program->SetUniformi("contactDebugView", debugView ? 1 : 0);
        uniforms(program);
      },
      mask, quadDepth);
    if (input)
    {
      input->Deactivate();
    }
  }

  /// Bind the framebuffer with `first` (and `second`) as colour targets and,
  /// when `masked`, the blur mask as depth.
  void Target(vtkOpenGLRenderWindow* context, int w, int h, vtkTextureObject* first,
    vtkTextureObject* second = nullptr, bool masked = false)
  {
    this->Framebuffer->Bind();
    if (masked)
    {
      this->Framebuffer->AddDepthAttachment(this->Mask);
    }
    this->Framebuffer->AddColorAttachment(0, first);
    if (second)
    {
      this->Framebuffer->AddColorAttachment(1, second);
    }
    this->Framebuffer->ActivateDrawBuffers(second ? 2 : 1);
    context->GetState()->vtkglViewport(0, 0, w, h);
    context->GetState()->vtkglScissor(0, 0, w, h);
  }

  void Untarget() { this->Framebuffer->RemoveColorAttachments(2); }
};

vtkStandardNewMacro(vtkContactHardeningShadowPass);

//------------------------------------------------------------------------------
vtkContactHardeningShadowPass::vtkContactHardeningShadowPass()
  : Internals(new vtkInternals)
{
}

vtkContactHardeningShadowPass::~vtkContactHardeningShadowPass() = default;

//------------------------------------------------------------------------------
bool vtkContactHardeningShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  // Pass 1. Unfiltered: pass 2 reads raw depths, the translucent fallback
  // compares binary.
  return this->RenderLightDepthMaps(s, false);
}

//------------------------------------------------------------------------------
bool vtkContactHardeningShadowPass::RenderScreenSpace(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkInternals& in = *this->Internals;
  if (in.Unsupported)
  {
    return false;
  }
  if (!in.RawDepthSampler)
  {
    if (!(GLEW_VERSION_3_3 || GLEW_ARB_sampler_objects))
    {
      vtkErrorMacro("Contact-hardening shadows need OpenGL 3.3 or ARB_sampler_objects to read "
                    "shadow-map depths; drawing without shadows.");
      in.Unsupported = true;
      return false;
    }
    glGenSamplers(1, &in.RawDepthSampler);
    glSamplerParameteri(in.RawDepthSampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(in.RawDepthSampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(in.RawDepthSampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(in.RawDepthSampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(in.RawDepthSampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }

  const std::string common =
    std::string(vtkShadowNormalOffsetFS) + "\n" + vtkShadowCubeLookupFS + "\n" + vtkContactCommonFS;
  auto build = [&](std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* source)
  {
    if (!quad)
    {
      quad = this->Screen->CreateQuad(context, common + "\n" + source);
    }
    return quad->Program != nullptr;
  };
  const std::string distanceCube = std::string("#define CONTACT_CUBE\n") + vtkContactDistanceFS;
  if (!build(in.Distance, vtkContactDistanceFS) || !build(in.DistanceCube, distanceCube.c_str()) ||
    !build(in.Prepare, vtkContactPrepareFS) || !build(in.MultiPass, vtkContactMultiPassFS) ||
    !build(in.PCF, vtkContactPCFFS) || !build(in.Gaussian, vtkContactGaussianFS) ||
    !build(in.Resolve, vtkContactResolveFS))
  {
    vtkErrorMacro("Could not build the contact-hardening shaders.");
    in.Unsupported = true;
    return false;
  }

  const int w = this->Screen->GetWidth();
  const int h = this->Screen->GetHeight();
  for (auto& map : in.Maps)
  {
    if (!map)
    {
      map = FloatTexture(context, w, h);
    }
    map->Resize(w, h);
  }
  if (!in.Mask)
  {
    in.Mask = vtkSmartPointer<vtkTextureObject>::New();
    in.Mask->SetContext(context);
    in.Mask->AllocateDepth(w, h, vtkTextureObject::Fixed24);
  }
  in.Mask->Resize(w, h);
  if (!in.Framebuffer)
  {
    in.Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.Framebuffer->SetContext(context);
  }

  // The camera's pixel footprint, to turn world penumbra widths into pixels.
  vtkCamera* camera = renderer->GetActiveCamera();
  in.DistanceUnit = static_cast<float>(std::max(camera->GetClippingRange()[1], 1e-30));
  float pixelFootprint[2] = { 0.0f, 0.0f };
  if (camera->GetParallelProjection())
  {
    pixelFootprint[0] = static_cast<float>(2.0 * camera->GetParallelScale() / h);
  }
  else
  {
    pixelFootprint[1] =
      static_cast<float>(2.0 * std::tan(glm::radians(camera->GetViewAngle()) / 2.0) / h);
  }
  float kernelVariance = 0.0f;
  const std::vector<float> taps = in.Taps(this->PoissonTaps, kernelVariance);
  const float tolerance = 0.1f;

  vtkOpenGLState* state = context->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  state->vtkglDisable(GL_BLEND);
  state->PushFramebufferBindings();

  auto& lights = this->Maps->GetLights();
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    const auto& light = lights[slot];

    // Pass 2: the distance map, into Maps[0]. 2D maps are read through the
    // non-comparing sampler; cube maps hold distances already.
    in.Target(context, w, h, in.Maps[0]);
    vtkTextureObject* map = light.Point ? light.CubeMap : light.DepthMap;
    map->Activate();
    const int unit = map->GetTextureUnit();
    if (!light.Point)
    {
      glBindSampler(unit, in.RawDepthSampler);
    }
    in.Draw(
      this->Screen.get(), light.Point ? in.DistanceCube : in.Distance, nullptr,
      [&](vtkShaderProgram* program)
      {
        if (light.Point)
        {
          program->SetUniformi("lightCube", unit);
          const float center[3] = { static_cast<float>(light.Position.x),
            static_cast<float>(light.Position.y), static_cast<float>(light.Position.z) };
          program->SetUniform3f("cubeCenter", center);
          program->SetUniformf("cubeTexel", 2.0f / static_cast<float>(this->MapSize));
          const double far = light.Faces[0].Far;
          program->SetUniformf(
            "cubeRange", this->PackedCubeMaps ? static_cast<float>(far * far) : 0.0f);
          program->SetUniformf("distanceBias", static_cast<float>(this->DistanceBias));
        }
        else
        {
          program->SetUniformi("lightDepth", unit);
          vtkShadowMapManager::SetFrustumUniforms(program, "map", "", light.Map, this->MapSize);
          float range[2] = { static_cast<float>(light.Map.Near),
            static_cast<float>(light.Map.Far) };
          program->SetUniform2f("mapDepthRange", range);
        }
        program->SetUniformf("normalBias", static_cast<float>(this->NormalBias));
        program->SetUniformi("useLightSize", this->UseLightSize ? 1 : 0);
        const double size =
          light.Directional ? 2.0 * std::tan(glm::radians(light.Radius)) : 2.0 * light.Radius;
        program->SetUniformf("lightSize", static_cast<float>(size));
        program->SetUniformf("distancePower", static_cast<float>(this->DistancePower));
        program->SetUniformf("distanceMultiplier", static_cast<float>(this->DistanceMultiplier));
        program->SetUniform2f("pixelFootprint", pixelFootprint);
        program->SetUniformi("countPasses", this->Variant == MultiPass ? 1 : 0);
        program->SetUniformf("resolutionDivisor", static_cast<float>(this->ResolutionDivisor));
        program->SetUniformi("passLimit", this->PassLimit);
        program->SetUniformi("minimumKernel", this->MinimumKernelSize);
        program->SetUniformi("maximumKernel", this->MaximumKernelSize);
        program->SetUniformi("growingKernel", this->GrowingKernel ? 1 : 0);
        program->SetUniformf("kernelVariance", kernelVariance);
      },
      tolerance, this->DebugView);
    if (!light.Point)
    {
      glBindSampler(unit, 0);
    }
    map->Deactivate();
    in.Untarget();

    // Umbra early-out and pass 3, into both ping-pong buffers.
    in.Target(context, w, h, in.Maps[1], in.Maps[2], true);
    in.Draw(
      this->Screen.get(), in.Prepare, in.Maps[0],
      [&](vtkShaderProgram* program)
      {
        program->SetUniformi("earlyOut", this->UmbraEarlyOut ? 1 : 0);
        program->SetUniformi("earlyOutRadius", this->EarlyOutKernelSize / 2);
        program->SetUniformi("dilation", this->Dilation ? 1 : 0);
        program->SetUniformf("dilationSize", static_cast<float>(this->DilationSize));
        program->SetUniform3fv("taps", this->PoissonTaps, taps.data());
        program->SetUniformi("tapCount", this->PoissonTaps);
      },
      tolerance, this->DebugView, vtkShadowScreenBuffers::QuadMask::Write);
    in.Untarget();

    // Pass 4, and pass 5's visibility into the framework's texture.
    vtkTextureObject* last = in.Maps[1];
    if (this->Variant == MultiPass)
    {
      // Pass k draws only the pixels the prepare pass's depth lets through
      // (D > k - 1), and only if pass k - 1 drew any: passes after the
      // widest penumbra's cost nothing. The condition stays on the GPU. A
      // pixel's last blur is followed by a pass that copies it into the
      // other buffer, unless the pass limit comes first; either way the last
      // target holds every pixel's final value.
      if (!in.Queries[0])
      {
        glGenQueries(2, in.Queries);
      }
      for (int pass = 0; pass < this->PassLimit; ++pass)
      {
        vtkTextureObject* source = in.Maps[1 + pass % 2];
        vtkTextureObject* target = in.Maps[1 + (pass + 1) % 2];
        const int size = this->GrowingKernel
          ? std::min(this->MinimumKernelSize + 2 * pass, this->MaximumKernelSize)
          : this->MaximumKernelSize;
        if (pass > 0)
        {
          glBeginConditionalRender(in.Queries[(pass - 1) % 2], GL_QUERY_WAIT);
        }
        glBeginQuery(GL_SAMPLES_PASSED, in.Queries[pass % 2]);
        in.Target(context, w, h, target, nullptr, true);
        in.Draw(
          this->Screen.get(), in.MultiPass, source,
          [&](vtkShaderProgram* program)
          {
            program->SetUniform3fv("taps", this->PoissonTaps, taps.data());
            program->SetUniformi("tapCount", this->PoissonTaps);
            program->SetUniformf("kernelSize", static_cast<float>(size));
          },
          tolerance, this->DebugView, vtkShadowScreenBuffers::QuadMask::Test,
          1.0f - static_cast<float>(pass) / 256.0f);
        in.Untarget();
        glEndQuery(GL_SAMPLES_PASSED);
        if (pass > 0)
        {
          glEndConditionalRender();
        }
      }
      last = in.Maps[1 + this->PassLimit % 2];
    }
    else if (this->Variant == Gaussian)
    {
      in.Target(context, w, h, in.Maps[2]);
      in.Draw(
        this->Screen.get(), in.Gaussian, in.Maps[1],
        [&](vtkShaderProgram* program)
        {
          program->SetUniformi("maximumKernel", this->MaximumKernelSize);
          program->SetUniform2i("direction", std::array<int, 2>{ 1, 0 }.data());
          program->SetUniformi("lastPass", 0);
        },
        tolerance, this->DebugView);
      in.Untarget();
      last = in.Maps[2];
    }

    this->Screen->BeginVisibility(static_cast<int>(slot), 1.0f);
    if (this->Variant == PCF)
    {
      in.Draw(
        this->Screen.get(), in.PCF, last,
        [&](vtkShaderProgram* program)
        { program->SetUniformi("maximumKernel", this->MaximumKernelSize); },
        tolerance, this->DebugView);
    }
    else if (this->Variant == Gaussian)
    {
      in.Draw(
        this->Screen.get(), in.Gaussian, last,
        [&](vtkShaderProgram* program)
        {
          program->SetUniformi("maximumKernel", this->MaximumKernelSize);
          program->SetUniform2i("direction", std::array<int, 2>{ 0, 1 }.data());
          program->SetUniformi("lastPass", 1);
        },
        tolerance, this->DebugView);
    }
    else
    {
      in.Draw(
        this->Screen.get(), in.Resolve, last, [](vtkShaderProgram*) {}, tolerance, this->DebugView);
    }
    this->Screen->EndVisibility();
  }
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  vtkInternals& in = *this->Internals;
  for (auto* quad : { &in.Distance, &in.DistanceCube, &in.Prepare, &in.MultiPass, &in.PCF,
         &in.Gaussian, &in.Resolve })
  {
    quad->reset();
  }
  for (auto* texture : { &in.Maps[0], &in.Maps[1], &in.Maps[2], &in.Mask })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(w);
    }
    *texture = nullptr;
  }
  if (in.Framebuffer)
  {
    in.Framebuffer->ReleaseGraphicsResources(w);
    in.Framebuffer = nullptr;
  }
  if (in.RawDepthSampler)
  {
    glDeleteSamplers(1, &in.RawDepthSampler);
    in.RawDepthSampler = 0;
  }
  if (in.Queries[0])
  {
    glDeleteQueries(2, in.Queries);
    in.Queries[0] = in.Queries[1] = 0;
  }
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* names[] = { "PCF", "Gaussian", "MultiPass" };
  os << indent << "Variant: " << names[this->Variant] << "\n";
  os << indent << "UseLightSize: " << this->UseLightSize << "\n";
  os << indent << "DistancePower: " << this->DistancePower << "\n";
  os << indent << "DistanceMultiplier: " << this->DistanceMultiplier << "\n";
  os << indent << "PassLimit: " << this->PassLimit << "\n";
  os << indent << "MinimumKernelSize: " << this->MinimumKernelSize << "\n";
  os << indent << "MaximumKernelSize: " << this->MaximumKernelSize << "\n";
  os << indent << "GrowingKernel: " << this->GrowingKernel << "\n";
  os << indent << "PoissonTaps: " << this->PoissonTaps << "\n";
  os << indent << "Dilation: " << this->Dilation << "\n";
  os << indent << "DilationSize: " << this->DilationSize << "\n";
  os << indent << "UmbraEarlyOut: " << this->UmbraEarlyOut << "\n";
  os << indent << "EarlyOutKernelSize: " << this->EarlyOutKernelSize << "\n";
  os << indent << "ResolutionDivisor: " << this->ResolutionDivisor << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
}
