#include "vtkSoftShadowPass.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkLight.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkShadowCubeLayersGS.h"
#include "vtkShadowCubeLookupFS.h"
#include "vtkShadowNormalOffsetFS.h"
#include "vtkSoftShadowReceiverFS.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <sstream>

vtkInformationKeyMacro(vtkSoftShadowPass, RADIUS, Double);

// The depth-only pre-pass as a step of the delegate's opaque sequence: it
// runs after the camera pass has cleared and set up the frame.
class vtkSoftShadowPass::vtkDepthPrePassStep : public vtkRenderPass
{
public:
  static vtkDepthPrePassStep* New();
  vtkTypeMacro(vtkDepthPrePassStep, vtkRenderPass);
  vtkSoftShadowPass* Owner = nullptr;
  void Render(const vtkRenderState* s) override { this->Owner->RenderDepthPrePass(s); }
};
vtkStandardNewMacro(vtkSoftShadowPass::vtkDepthPrePassStep);

namespace
{
glm::dmat4 ToGlm(vtkMatrix4x4* m)
{
  glm::dmat4 result;
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      result[col][row] = m->GetElement(row, col);
    }
  }
  return result;
}

void SetMatrix(vtkShaderProgram* program, const std::string& name, const glm::dmat4& m)
{
  glm::mat4 single(m);
  program->SetUniformMatrix4x4(name.c_str(), glm::value_ptr(single));
}

// The fragment's world position and geometric normal from derivatives: the
// face's true orientation, which the normal offset needs (interpolated
// normals lie on coarse meshes). Derivatives of the triangle's own
// interpolants: right at silhouettes too, unlike a depth buffer's.
const char* const SurfaceCode =
  "  vec4 vtkShadowPositionWC = vtkShadowViewToWorld * vec4(vertexVCVSOutput.xyz, 1.0);\n"
  "  vec3 vtkShadowNormalWC = normalize(mat3(vtkShadowViewToWorld) *\n"
  "    cross(dFdx(vertexVCVSOutput.xyz), dFdy(vertexVCVSOutput.xyz)));\n";

std::string Indexed(const char* name, int i)
{
  return std::string(name) + "[" + std::to_string(i) + "]";
}
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::vtkSoftShadowPass()
  : Maps(new vtkShadowMapManager)
  , Screen(new vtkShadowScreenBuffers)
{
  vtkNew<vtkRenderStepsPass> steps;
  this->SetDelegatePass(steps);
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::~vtkSoftShadowPass()
{
  this->SetDelegatePass(nullptr);
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::SetRadius(double radius, vtkLight* light)
{
  if (!light)
  {
    return;
  }
  if (!(radius >= 0.0)) // also rejects NaN
  {
    vtkGenericWarningMacro("vtkSoftShadowPass::SetRadius: radius must be >= 0, got " << radius);
    return;
  }
  light->GetInformation()->Set(vtkSoftShadowPass::RADIUS(), radius);
}

//------------------------------------------------------------------------------
double vtkSoftShadowPass::GetRadius(vtkLight* light)
{
  if (!light || !light->GetInformation()->Has(vtkSoftShadowPass::RADIUS()))
  {
    return 0.0;
  }
  return light->GetInformation()->Get(vtkSoftShadowPass::RADIUS());
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::SetDelegatePass(vtkRenderPass* pass)
{
  vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, pass);
}

//------------------------------------------------------------------------------
int vtkSoftShadowPass::GetNumberOfShadowedLights() const
{
  return static_cast<int>(this->Maps->GetLights().size());
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::SetStage(Stage stage)
{
  if (stage != this->CurrentStage)
  {
    this->CurrentStage = stage;
    this->StageTime.Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkSoftShadowPass::GetShaderStageMTime()
{
  return this->StageTime;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkErrorMacro("No delegate pass: nothing to render.");
    return;
  }

  vtkRenderer* renderer = s->GetRenderer();
  int width = 0, height = 0;
  renderer->GetTiledSize(&width, &height);
  if (width <= 0 || height <= 0)
  {
    vtkErrorMacro("Renderer has an empty viewport (" << width << "x" << height << ").");
    return;
  }

  // 1. Decide: which lights cast shadows, and their frusta.
  this->Maps->Update(renderer);
  auto& shadowed = this->Maps->GetLights();
  if (!this->SupportsPointLights())
  {
    const auto points = std::count_if(shadowed.begin(), shadowed.end(),
      [](const vtkShadowMapManager::Light& l) { return l.Point; });
    if (points > 0 && !this->PointLightReported)
    {
      vtkErrorMacro(<< points
                    << " point light(s) (positional, cone angle >= 90): " << this->GetClassName()
                    << " does not shadow point lights yet; they are drawn without shadows.");
      this->PointLightReported = true;
    }
    shadowed.erase(std::remove_if(shadowed.begin(), shadowed.end(),
                     [](const vtkShadowMapManager::Light& l) { return l.Point; }),
      shadowed.end());
  }

  // 2-3. Draw the technique's maps and screen-space passes.
  bool drawn = !shadowed.empty();
  if (drawn)
  {
    drawn = this->RenderShadowMaps(s);
  }
  if (drawn && this->UsesScreenSpace())
  {
    this->Screen->SetResolutionDivisor(this->GetScreenResolutionDivisor());
    drawn = this->Screen->Update(s) && this->RenderScreenSpace(s) &&
      this->Screen->Pack(static_cast<int>(shadowed.size()));
  }
  if (!drawn)
  {
    shadowed.clear();
  }

  // 4. Draw the scene with the shadow term in every receiver's shader.
  this->RenderReceivers(s, drawn && this->UsesScreenSpace());
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::RenderReceivers(const vtkRenderState* s, bool screenSpace)
{
  auto& shadowed = this->Maps->GetLights();
  for (auto& light : shadowed)
  {
    (light.Point ? light.CubeMap : light.DepthMap)->Activate();
  }
  if (screenSpace)
  {
    this->Screen->ActivateTextures();
  }

  // Cube maps are looked up across faces: filter across their seams.
  vtkOpenGLState* state =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable seamless(state, GL_TEXTURE_CUBE_MAP_SEAMLESS);
  state->vtkglEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

  // Gerasimov's depth-only pre-pass (section 12.3.4): opaque depth first, so
  // the shading pass runs only on visible fragments. It is a step slotted
  // before the default delegate's opaque pass, after its camera pass cleared.
  auto* steps = vtkRenderStepsPass::SafeDownCast(this->DelegatePass);
  vtkSmartPointer<vtkRenderPass> opaque = steps ? steps->GetOpaquePass() : nullptr;
  const bool prePass = this->DepthPrePass && !shadowed.empty() && opaque;
  if (prePass)
  {
    vtkNew<vtkDepthPrePassStep> step;
    step->Owner = this;
    vtkNew<vtkRenderPassCollection> passes;
    passes->AddItem(step);
    passes->AddItem(opaque);
    vtkNew<vtkSequencePass> sequence;
    sequence->SetPasses(passes);
    steps->SetOpaquePass(sequence);
  }

  this->SetStage(Stage::Receivers);
  this->PreRender(s);
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  this->PostRender(s);
  this->SetStage(Stage::Idle);
  if (prePass)
  {
    steps->SetOpaquePass(opaque);
  }

  if (screenSpace)
  {
    this->Screen->DeactivateTextures();
  }
  for (auto& light : shadowed)
  {
    (light.Point ? light.CubeMap : light.DepthMap)->Deactivate();
  }
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::RenderLightDepthMaps(const vtkRenderState* s, bool linear)
{
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  this->LinearMaps = linear;
  for (auto& light : this->Maps->GetLights())
  {
    if (light.Point)
    {
      this->Maps->AllocateCubeMap(context, light, this->MapSize, this->PackedCubeMaps);
      if (!this->Maps->RenderDistanceCube(s, this, light.Faces, light.CubeMap))
      {
        return false;
      }
      continue;
    }
    this->Maps->AllocateDepthMap(context, light, this->MapSize, linear);
    if (!this->Maps->RenderDepth(s, this, light.Map, light.DepthMap))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::RenderCameraDepth(
  const vtkRenderState* s, const std::vector<vtkTextureObject*>& targets)
{
  if (!targets.empty())
  {
    // Mappers write lighting code, where the camera pass code goes, only for
    // the renderer's lighting complexity, which its lights pass updates
    // later in the frame (and on the first frame, not yet at all).
    this->UpdateLightGeometry(s->GetRenderer());
    this->UpdateLights(s->GetRenderer());
  }
  return this->Screen->RenderCameraDepth(s, this, targets);
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::RenderDepthPrePass(const vtkRenderState* s)
{
  // The props carry this pass already (receivers): only the stage changes,
  // to the shading-free depth shaders, then back.
  vtkOpenGLState* state =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDepthMask(GL_TRUE);
  this->SetStage(Stage::LightDepth);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    s->GetPropArray()[i]->RenderOpaqueGeometry(s->GetRenderer());
  }
  this->SetStage(Stage::Receivers);
}

//------------------------------------------------------------------------------
std::string vtkSoftShadowPass::GetVisibilityExpression(int slot)
{
  const auto& light = this->Maps->GetLights()[slot];
  const std::string i = std::to_string(slot);
  const std::string m = std::to_string(light.MapIndex);
  const std::string hard = light.Point
    ? "vtkShadowCubeLookup(vtkShadowCube[" + m + "], vtkShadowCubeCenter[" + m +
      "], vtkShadowPositionWC, vtkShadowNormalWC, vtkShadowCubeTexel, vtkShadowNormalBias, "
      "vtkShadowDistanceBias, vtkShadowCubeRange[" +
      m + "], vtkShadowPCFRadius)"
    : "vtkShadowLookup(vtkShadowMap[" + m + "], vtkShadowWorldToMap[" + i +
      "], vtkShadowReceiver(" + i + ", vtkShadowPositionWC, vtkShadowNormalWC), " +
      "vtkShadowPCFRadius)";
  if (this->UsesScreenSpace())
  {
    return "vtkShadowScreenVisibility(vtkShadowScreen[" + i + "], " + hard + ")";
  }
  return hard;
}

//------------------------------------------------------------------------------
// Receivers: tags are placed before the mapper writes its lighting code, and
// filled after, once it is known whether the shader has lighting at all.
bool vtkSoftShadowPass::PreReplaceShaderValues(std::string&, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  switch (this->CurrentStage)
  {
    case Stage::LightDepth:
      // Depth only: skip all shading. Clipping and depth code come earlier.
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
        "gl_FragData[0] = vec4(1.0);\n  return;\n  //VTK::Light::Impl", false);
      break;
    case Stage::LightDistance:
      if (this->LayeredFaces)
      {
        if (geometryShader.empty())
        {
          geometryShader = vtkShadowCubeLayersGS;
        }
        else if (this->LayeredFallbackProps.insert(prop).second)
        {
          // Edges or wide lines already use the one geometry shader slot.
          vtkWarningMacro("A prop drawn with its own geometry shader (edges or wide lines) casts "
                          "into one cube face only with single-pass cube maps; turn "
                          "SinglePassCubeMaps off for such scenes.");
        }
      }
      // Squared distance to the face's eye (the light) from the fragment's
      // window position: independent of the mapper's lighting varyings.
      // Packed into RGBA8 over the face's far distance squared when asked.
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Dec",
        std::string(vtkShadowCubeLookupFS) +
          "\nuniform mat4 vtkShadowFaceClipToView;\nuniform float vtkShadowFaceSize;\n"
          "uniform float vtkShadowFaceRange;\n//VTK::Light::Dec",
        false);
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
        "vec4 vtkShadowFaceView = vtkShadowFaceClipToView *\n"
        "    vec4(gl_FragCoord.xy / vtkShadowFaceSize * 2.0 - 1.0, gl_FragCoord.z * 2.0 - 1.0, "
        "1.0);\n"
        "  vtkShadowFaceView.xyz /= vtkShadowFaceView.w;\n"
        "  float vtkShadowDistance2 = dot(vtkShadowFaceView.xyz, vtkShadowFaceView.xyz);\n"
        "  gl_FragData[0] = vtkShadowFaceRange > 0.0\n"
        "    ? vtkShadowPackDistance(min(vtkShadowDistance2 / vtkShadowFaceRange, 0.9999))\n"
        "    : vec4(vtkShadowDistance2);\n"
        "  return;\n  //VTK::Light::Impl",
        false);
      break;
    case Stage::CameraDepth:
      vtkShaderProgram::Substitute(
        fragmentShader, "//VTK::Light::Dec", "//VTK::SoftShadow::Dec\n//VTK::Light::Dec", false);
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
        "//VTK::SoftShadow::Impl\n  return;\n  //VTK::Light::Impl", false);
      break;
    case Stage::Receivers:
      if (this->UsesScreenSpace())
      {
        // textureGather (vtkShadowScreenVisibility) in the mappers' GLSL 1.50.
        vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec",
          "//VTK::System::Dec\n#extension GL_ARB_texture_gather : enable", false);
      }
      vtkShaderProgram::Substitute(
        fragmentShader, "//VTK::Light::Dec", "//VTK::SoftShadow::Dec\n//VTK::Light::Dec", false);
      vtkShaderProgram::Substitute(
        fragmentShader, "//VTK::Light::Impl", "//VTK::SoftShadow::Impl\n//VTK::Light::Impl", false);
      break;
    case Stage::Idle:
      break;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // Without lighting the mapper declares no view-space position: nothing to
  // shadow, and such fragments count as lit.
  const bool lit = fragmentShader.find("vertexVCVSOutput") != std::string::npos;
  if (this->CurrentStage == Stage::CameraDepth)
  {
    std::string dec, impl;
    if (this->CameraPassTargets > 0 && lit)
    {
      dec = "uniform mat4 vtkShadowViewToWorld;\n" + this->GetCameraPassDeclarations();
      impl = std::string(SurfaceCode) + this->GetCameraPassImplementation();
    }
    else
    {
      for (int i = 0; i < std::max(this->CameraPassTargets, 1); ++i)
      {
        impl += "  gl_FragData[" + std::to_string(i) + "] = vec4(0.0);\n";
      }
    }
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::SoftShadow::Dec", dec, false);
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::SoftShadow::Impl", impl, false);
    return true;
  }
  if (this->CurrentStage != Stage::Receivers)
  {
    return true;
  }
  const auto& lights = this->Maps->GetLights();
  const bool active = lit && !lights.empty();

  std::string onlyVisibility = "1.0";
  std::ostringstream dec, impl;
  if (active)
  {
    const auto cubes = std::count_if(
      lights.begin(), lights.end(), [](const vtkShadowMapManager::Light& l) { return l.Point; });
    dec << "#define VTK_SHADOW_LIGHTS " << lights.size() << "\n"
        << "#define VTK_SHADOW_MAPS " << lights.size() - cubes << "\n"
        << "#define VTK_SHADOW_CUBES " << cubes << "\n";
    if (this->UsesScreenSpace())
    {
      dec << "#define VTK_SHADOW_SCREEN_SPACE\n";
    }
    dec << vtkShadowNormalOffsetFS << "\n"
        << vtkShadowCubeLookupFS << "\n"
        << vtkSoftShadowReceiverFS << "\n"
        << this->GetVisibilityDeclarations() << "\n";

    impl << SurfaceCode;
    if (this->UsesScreenSpace())
    {
      impl << "  vtkShadowScreenSetup(vtkShadowPositionWC);\n";
    }
    for (size_t slot = 0; slot < lights.size(); ++slot)
    {
      const int n = lights[slot].ShaderIndex;
      const int i = static_cast<int>(slot);
      impl << "  float vtkShadowVisibility" << n << " = " << this->GetVisibilityExpression(i)
           << ";\n"
           << "  float vtkShadowFactor" << n << " = mix(1.0, vtkShadowVisibility" << n
           << ", vtkShadowAttenuation[" << i << "]);\n";

      // Scale the light's contribution: Phong diffuse and specular, PBR
      // radiance (directional and positional forms).
      const std::string color = "lightColor" + std::to_string(n);
      const std::string factor = "vtkShadowFactor" + std::to_string(n);
      vtkShaderProgram::Substitute(fragmentShader, "diffuse += (df * " + color + ");",
        "diffuse += (df * " + factor + " * " + color + ");", false);
      vtkShaderProgram::Substitute(fragmentShader, "specular += (sf * " + color + ");",
        "specular += (sf * " + factor + " * " + color + ");", false);
      vtkShaderProgram::Substitute(fragmentShader, "radiance = " + color + ";",
        "radiance = " + factor + " * " + color + ";", false);
      vtkShaderProgram::Substitute(fragmentShader, "radiance = " + color + " * attenuation;",
        "radiance = " + factor + " * " + color + " * attenuation;", false);

      if (lights[slot].SceneIndex == this->ShadowOnlyLight)
      {
        onlyVisibility = "vtkShadowVisibility" + std::to_string(n);
      }
    }
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::SoftShadow::Dec", dec.str(), false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::SoftShadow::Impl", impl.str(), false);

  if (this->ShadowOnlyLight >= 0)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
      "gl_FragData[0] = vec4(vec3(" + onlyVisibility + "), 1.0);\n  //VTK::Light::Impl", false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (this->CurrentStage == Stage::LightDistance)
  {
    program->SetUniformMatrix4x4("vtkShadowFaceClipToView", this->FaceClipToView);
    program->SetUniformf("vtkShadowFaceSize", this->FaceSize);
    program->SetUniformf("vtkShadowFaceRange", this->FaceRange);
    if (this->LayeredFaces)
    {
      program->SetUniformMatrix4x4v("vtkShadowFaceFromFirst", 6, &this->FaceFromFirst[0][0]);
    }
    return true;
  }
  const bool camera = this->CurrentStage == Stage::CameraDepth;
  if (!(camera || this->CurrentStage == Stage::Receivers) ||
    !program->IsUniformUsed("vtkShadowViewToWorld"))
  {
    return true;
  }
  vtkRenderer* renderer = this->Maps->GetRenderer();
  SetMatrix(program, "vtkShadowViewToWorld",
    glm::inverse(ToGlm(renderer->GetActiveCamera()->GetModelViewTransformMatrix())));
  if (camera)
  {
    this->SetCameraPassUniforms(program);
    return true;
  }
  program->SetUniformf("vtkShadowMapTexel", 1.0f / static_cast<float>(this->MapSize));
  program->SetUniformi("vtkShadowPCFRadius", this->GetPCFRadius());
  program->SetUniformi("vtkShadowPCFBilinear", this->GetPCFBilinear() ? 1 : 0);
  program->SetUniformf("vtkShadowNormalBias", static_cast<float>(this->NormalBias));
  program->SetUniformf("vtkShadowCubeTexel", 2.0f / static_cast<float>(this->MapSize));
  program->SetUniformf("vtkShadowDistanceBias", static_cast<float>(this->DistanceBias));

  const auto& lights = this->Maps->GetLights();
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    const auto& light = lights[slot];
    const int i = static_cast<int>(slot);
    program->SetUniformf(
      Indexed("vtkShadowAttenuation", i).c_str(), static_cast<float>(light.Attenuation));
    if (light.Point)
    {
      program->SetUniformi(
        Indexed("vtkShadowCube", light.MapIndex).c_str(), light.CubeMap->GetTextureUnit());
      const float center[3] = { static_cast<float>(light.Position.x),
        static_cast<float>(light.Position.y), static_cast<float>(light.Position.z) };
      program->SetUniform3f(Indexed("vtkShadowCubeCenter", light.MapIndex).c_str(), center);
      program->SetUniformf(Indexed("vtkShadowCubeRange", light.MapIndex).c_str(),
        this->PackedCubeMaps ? static_cast<float>(light.Faces[0].Far * light.Faces[0].Far) : 0.0f);
      continue;
    }
    vtkShadowMapManager::SetFrustumUniforms(
      program, "vtkShadow", "[" + std::to_string(i) + "]", light.Map, this->MapSize);
    program->SetUniformi(
      Indexed("vtkShadowMap", light.MapIndex).c_str(), light.DepthMap->GetTextureUnit());
  }
  if (this->UsesScreenSpace())
  {
    this->Screen->SetUniforms(program, static_cast<int>(lights.size()));
  }
  this->SetVisibilityUniforms(program);
  return true;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Maps->ReleaseGraphicsResources(w);
  this->Screen->ReleaseGraphicsResources(w);
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MapSize: " << this->MapSize << "\n";
  os << indent << "SlopeScaledBias: " << this->SlopeScaledBias << "\n";
  os << indent << "ConstantBias: " << this->ConstantBias << "\n";
  os << indent << "NormalBias: " << this->NormalBias << "\n";
  os << indent << "DistanceBias: " << this->DistanceBias << "\n";
  os << indent << "SinglePassCubeMaps: " << this->SinglePassCubeMaps << "\n";
  os << indent << "PackedCubeMaps: " << this->PackedCubeMaps << "\n";
  os << indent << "DepthPrePass: " << this->DepthPrePass << "\n";
  os << indent << "ShadowOnlyLight: " << this->ShadowOnlyLight << "\n";
  os << indent << "DelegatePass: ";
  if (this->DelegatePass)
  {
    os << this->DelegatePass->GetClassName() << "\n";
  }
  else
  {
    os << "(none)\n";
  }
}
