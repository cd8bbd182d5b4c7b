#include "Techniques.h"

#include "vtkAliasFreeShadowPass.h"
#include "vtkContactHardeningShadowPass.h"
#include "vtkHardShadowPass.h"
#include "vtkOmnidirectionalShadowPass.h"
#include "vtkReferenceShadowPass.h"
#include "vtkSilhouetteShadowPass.h"
#include "vtkSmoothieShadowPass.h"
#include "vtkSoftShadowPass.h"

#include <vtkCameraPass.h>
#include <vtkNew.h>
#include <vtkRenderPassCollection.h>
#include <vtkSequencePass.h>
#include <vtkShadowMapBakerPass.h>
#include <vtkShadowMapPass.h>

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace softshadows
{
namespace
{
template <typename PassType>
PassType* Get(TechniqueInstance& instance)
{
  return PassType::SafeDownCast(instance.Shadows);
}

template <typename PassType>
TechniqueInstance Wrap(vtkSmartPointer<PassType> pass)
{
  TechniqueInstance instance;
  instance.Pass = pass;
  instance.Shadows = pass;
  return instance;
}

/// A parameter that reaches the pass through its Set/Get methods.
template <typename PassType, typename Value>
TechniqueParameter Bind(const char* key, ValueType type, const Range& allowed, const char* meaning,
  void (PassType::*set)(Value), Value (PassType::*get)())
{
  return { key, type, allowed, meaning,
    [set](TechniqueInstance& t, const Json& v) { (Get<PassType>(t)->*set)(v.get<Value>()); },
    [get](TechniqueInstance& t) { return Json((Get<PassType>(t)->*get)()); } };
}

// Parameters every technique built on vtkSoftShadowPass shares.
std::vector<TechniqueParameter> WithCommonParameters(std::vector<TechniqueParameter> own)
{
  own.push_back(
    Bind<vtkSoftShadowPass, double>("slope_scaled_bias", ValueType::Number, Range::Any(),
      "depth offset per unit of depth slope while drawing shadow maps (glPolygonOffset factor)",
      &vtkSoftShadowPass::SetSlopeScaledBias, &vtkSoftShadowPass::GetSlopeScaledBias));
  own.push_back(Bind<vtkSoftShadowPass, double>("constant_bias", ValueType::Number, Range::Any(),
    "constant depth offset while drawing shadow maps (glPolygonOffset units)",
    &vtkSoftShadowPass::SetConstantBias, &vtkSoftShadowPass::GetConstantBias));
  own.push_back(
    Bind<vtkSoftShadowPass, double>("normal_bias", ValueType::Number, Range::Between(0.0, 16.0),
      "how far in front of its surface a receiver point is looked up, along the light's ray, in "
      "shadow-map texels",
      &vtkSoftShadowPass::SetNormalBias, &vtkSoftShadowPass::GetNormalBias));
  own.push_back(
    Bind<vtkSoftShadowPass, double>("distance_bias", ValueType::Number, Range::Between(0.5, 1.0),
      "point lights: factor on squared distances before comparing with the cube map",
      &vtkSoftShadowPass::SetDistanceBias, &vtkSoftShadowPass::GetDistanceBias));
  own.push_back(Bind<vtkSoftShadowPass, bool>("packed_cube_maps", ValueType::Boolean, Range::Any(),
    "point lights: RGBA8 cube maps packing squared distances, not float ones",
    &vtkSoftShadowPass::SetPackedCubeMaps, &vtkSoftShadowPass::GetPackedCubeMaps));
  own.push_back(Bind<vtkSoftShadowPass, bool>("depth_pre_pass", ValueType::Boolean, Range::Any(),
    "draw opaque depth first so that shading and shadow lookups run on visible fragments only",
    &vtkSoftShadowPass::SetDepthPrePass, &vtkSoftShadowPass::GetDepthPrePass));
  return own;
}

// VTK 9.1's own shadows, put together as its TestShadowMapPass does: the baker
// draws the maps, then vtkShadowMapPass draws the opaque geometry with them.
TechniqueInstance MakeVtkShadowMapPass()
{
  vtkNew<vtkShadowMapPass> shadows;
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(shadows->GetShadowMapBakerPass());
  passes->AddItem(shadows);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  auto camera = vtkSmartPointer<vtkCameraPass>::New();
  camera->SetDelegatePass(sequence);

  TechniqueInstance instance;
  instance.Pass = camera;
  instance.Baker = shadows->GetShadowMapBakerPass();
  return instance;
}

// Prints `text` in lines of at most 100 columns, continuation lines indented
// by `indent`; the first line starts at column `column`.
void PrintWrapped(std::ostream& os, const std::string& text, int indent, int column = 0)
{
  const int width = 100;
  os << std::string(static_cast<std::size_t>(std::max(0, indent - column)), ' ');
  column = std::max(column, indent);
  std::istringstream words(text);
  std::string word;
  bool first = true;
  while (words >> word)
  {
    const int length = static_cast<int>(word.size());
    if (!first && column + 1 + length > width)
    {
      os << "\n" << std::string(static_cast<std::size_t>(indent), ' ');
      column = indent;
      first = true;
    }
    os << (first ? "" : " ") << word;
    column += length + (first ? 0 : 1);
    first = false;
  }
  os << "\n";
}

const Technique* FindTechnique(const std::string& name)
{
  const auto& all = Techniques();
  auto found = std::find_if(
    all.begin(), all.end(), [&](const Technique& technique) { return technique.Name == name; });
  return found == all.end() ? nullptr : &*found;
}

const Technique& RequireTechnique(const std::string& name, const std::string& where)
{
  if (const Technique* technique = FindTechnique(name))
  {
    return *technique;
  }
  throw InputError(where,
    "unknown technique '" + name + "' " +
      KnownNames(Techniques(), [](const Technique& technique) { return technique.Name; }));
}

void RequireVariant(
  const Technique& technique, const std::string& variant, const std::string& where)
{
  if (technique.Variants.empty())
  {
    throw InputError(
      where, "unknown variant '" + variant + "': technique '" + technique.Name + "' has none");
  }
  const auto& variants = technique.Variants;
  const bool found = std::any_of(variants.begin(), variants.end(),
    [&](const TechniqueVariant& candidate) { return candidate.Name == variant; });
  if (!found)
  {
    throw InputError(where,
      "unknown variant '" + variant + "' of technique '" + technique.Name + "' " +
        KnownNames(variants, [](const TechniqueVariant& candidate) { return candidate.Name; }));
  }
}
}

//------------------------------------------------------------------------------
std::string TechniqueSpec::ToString() const
{
  return this->Variant.empty() ? this->Name : this->Name + ":" + this->Variant;
}

//------------------------------------------------------------------------------
const std::vector<Technique>& Techniques()
{
  static const std::vector<Technique> techniques = {
    { "hard", "vtkHardShadowPass: one shadow map per light, percentage-closer filtering",
      { { "layered", "point lights' cube maps drawn in one layered pass" },
        { "sixpass", "point lights' cube maps drawn one face a pass, as in the paper" } },
      WithCommonParameters({
        Bind<vtkHardShadowPass, int>("pcf_radius", ValueType::Integer, Range::Between(0, 8),
          "radius in texels of the square PCF kernel: a (2r+1)^2-texel footprint; 0 is one tap",
          &vtkHardShadowPass::SetPCFRadius, &vtkHardShadowPass::GetPCFRadius),
        Bind<vtkHardShadowPass, bool>("hardware_filtering", ValueType::Boolean, Range::Any(),
          "bilinear depth-comparison filtering of every tap; off gives binary taps",
          &vtkHardShadowPass::SetHardwareFiltering, &vtkHardShadowPass::GetHardwareFiltering),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkHardShadowPass>::New();
        pass->SetSinglePassCubeMaps(variant != "sixpass");
        return Wrap(pass);
      } },
    { "reference",
      "vtkReferenceShadowPass: ground truth, the average of many hard shadow maps drawn from "
      "points sampled over each light (slow)",
      { { "disc", "points on a disc across the light's axis (SPEC's reference)" },
        { "sphere",
          "points in the light's sphere, uniform over its disc from every side, as the "
          "ray-cast truth" } },
      WithCommonParameters({
        Bind<vtkReferenceShadowPass, int>("samples", ValueType::Integer, Range::Between(1, 4096),
          "light samples (shadow maps) per light, rounded down to a square",
          &vtkReferenceShadowPass::SetNumberOfSamples, &vtkReferenceShadowPass::GetNumberOfSamples),
        Bind<vtkReferenceShadowPass, unsigned int>("seed", ValueType::Integer, Range::AtLeast(0),
          "seed of the light sample jitter", &vtkReferenceShadowPass::SetSeed,
          &vtkReferenceShadowPass::GetSeed),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkReferenceShadowPass>::New();
        pass->SetSampling(
          variant == "sphere" ? vtkReferenceShadowPass::Sphere : vtkReferenceShadowPass::Disc);
        return Wrap(pass);
      } },
    { "contact",
      "vtkContactHardeningShadowPass: contact-hardening soft shadows in screen space (Cherry & "
      "Kooima): a distance map of S and D, then S softened with a D-sized filter",
      { { "pcf", "the mean over a disc of D pixels on the receiver" },
        { "gaussian", "one separable Gaussian blur of D pixels" },
        { "multipass", "up to pass_limit Poisson-disk Gaussian blurs, D counting them down" } },
      WithCommonParameters({
        Bind<vtkContactHardeningShadowPass, bool>("use_light_size", ValueType::Boolean,
          Range::Any(),
          "size kernels from the light's radius, w = (d_receiver - d_blocker) * w_light / "
          "d_blocker; off uses dp and dm",
          &vtkContactHardeningShadowPass::SetUseLightSize,
          &vtkContactHardeningShadowPass::GetUseLightSize),
        Bind<vtkContactHardeningShadowPass, double>("dp", ValueType::Number,
          Range::Between(0.0, 16.0), "distance power Dp in D = (occluder distance)^Dp * Dm",
          &vtkContactHardeningShadowPass::SetDistancePower,
          &vtkContactHardeningShadowPass::GetDistancePower),
        Bind<vtkContactHardeningShadowPass, double>("dm", ValueType::Number,
          Range::Between(0.0, 1.0e9), "distance multiplier Dm in D = (occluder distance)^Dp * Dm",
          &vtkContactHardeningShadowPass::SetDistanceMultiplier,
          &vtkContactHardeningShadowPass::GetDistanceMultiplier),
        Bind<vtkContactHardeningShadowPass, int>("pass_limit", ValueType::Integer,
          Range::Between(1, 64), "most blur passes (multipass)",
          &vtkContactHardeningShadowPass::SetPassLimit,
          &vtkContactHardeningShadowPass::GetPassLimit),
        Bind<vtkContactHardeningShadowPass, int>("min_kernel", ValueType::Integer,
          Range::Between(1, 255), "first kernel size in pixels when the kernel grows (multipass)",
          &vtkContactHardeningShadowPass::SetMinimumKernelSize,
          &vtkContactHardeningShadowPass::GetMinimumKernelSize),
        Bind<vtkContactHardeningShadowPass, int>("max_kernel", ValueType::Integer,
          Range::Between(1, 255), "largest kernel size in pixels",
          &vtkContactHardeningShadowPass::SetMaximumKernelSize,
          &vtkContactHardeningShadowPass::GetMaximumKernelSize),
        Bind<vtkContactHardeningShadowPass, bool>("growing_kernel", ValueType::Boolean,
          Range::Any(), "grow the kernel by 2 pixels a pass from min_kernel (multipass)",
          &vtkContactHardeningShadowPass::SetGrowingKernel,
          &vtkContactHardeningShadowPass::GetGrowingKernel),
        Bind<vtkContactHardeningShadowPass, int>("taps", ValueType::Integer, Range::Between(1, 64),
          "Poisson-disk taps per blur (multipass)", &vtkContactHardeningShadowPass::SetPoissonTaps,
          &vtkContactHardeningShadowPass::GetPoissonTaps),
        Bind<vtkContactHardeningShadowPass, bool>("dilation", ValueType::Boolean, Range::Any(),
          "spread D to lit pixels near shadows: the outer penumbra (pass 3)",
          &vtkContactHardeningShadowPass::SetDilation, &vtkContactHardeningShadowPass::GetDilation),
        Bind<vtkContactHardeningShadowPass, int>("dilation_size", ValueType::Integer,
          Range::Between(1, 255), "dilation kernel size in pixels",
          &vtkContactHardeningShadowPass::SetDilationSize,
          &vtkContactHardeningShadowPass::GetDilationSize),
        Bind<vtkContactHardeningShadowPass, bool>("early_out", ValueType::Boolean, Range::Any(),
          "D = 0 deep inside the umbra, so blurs skip it",
          &vtkContactHardeningShadowPass::SetUmbraEarlyOut,
          &vtkContactHardeningShadowPass::GetUmbraEarlyOut),
        Bind<vtkContactHardeningShadowPass, int>("early_out_size", ValueType::Integer,
          Range::Between(1, 255), "early-out neighbourhood in pixels (above max_kernel)",
          &vtkContactHardeningShadowPass::SetEarlyOutKernelSize,
          &vtkContactHardeningShadowPass::GetEarlyOutKernelSize),
        Bind<vtkContactHardeningShadowPass, int>("resolution_divisor", ValueType::Integer,
          Range::Between(1, 4),
          "screen-space passes on buffers this many times smaller than the window on each axis; "
          "kernel sizes count their pixels",
          &vtkContactHardeningShadowPass::SetResolutionDivisor,
          &vtkContactHardeningShadowPass::GetResolutionDivisor),
        Bind<vtkContactHardeningShadowPass, bool>("refine_unresolved", ValueType::Boolean,
          Range::Any(),
          "where the buffers cannot hold a penumbra (floors seen nearly edge-on), receivers "
          "filter their hard shadow again in light space over the penumbra's width",
          &vtkContactHardeningShadowPass::SetRefineUnresolved,
          &vtkContactHardeningShadowPass::GetRefineUnresolved),
        Bind<vtkContactHardeningShadowPass, bool>("debug_view", ValueType::Boolean, Range::Any(),
          "mark umbra (grey) and penumbra (dark) as in the paper's figure 4",
          &vtkContactHardeningShadowPass::SetDebugView,
          &vtkContactHardeningShadowPass::GetDebugView),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkContactHardeningShadowPass>::New();
        if (variant == "multipass")
        {
          pass->SetVariantToMultiPass();
        }
        else if (variant == "gaussian")
        {
          pass->SetVariantToGaussian();
        }
        else
        {
          pass->SetVariantToPCF();
        }
        return Wrap(pass);
      } },
    { "omni",
      "vtkOmnidirectionalShadowPass: point lights' cube maps of squared distances (Gerasimov, "
      "GPU Gems ch. 12), filtered; spot and directional lights as hard with 4-tap PCF",
      { { "poisson", "blocker search and rotated Poisson-disk PCF sized by the light's radius" },
        { "pcf4", "the chapter's 4-tap PCF" }, { "hard", "one tap" } },
      WithCommonParameters({
        Bind<vtkOmnidirectionalShadowPass, int>("pcf_radius", ValueType::Integer,
          Range::Between(1, 8), "pcf4: distance between the taps, in texels",
          &vtkOmnidirectionalShadowPass::SetPCFRadius, &vtkOmnidirectionalShadowPass::GetPCFRadius),
        Bind<vtkOmnidirectionalShadowPass, int>("taps", ValueType::Integer, Range::Between(1, 32),
          "poisson: taps of the blocker search and of the filter",
          &vtkOmnidirectionalShadowPass::SetPoissonTaps,
          &vtkOmnidirectionalShadowPass::GetPoissonTaps),
        Bind<vtkSoftShadowPass, bool>("single_pass_cube_maps", ValueType::Boolean, Range::Any(),
          "draw the six cube faces in one layered pass (else six passes, as the paper)",
          &vtkSoftShadowPass::SetSinglePassCubeMaps, &vtkSoftShadowPass::GetSinglePassCubeMaps),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkOmnidirectionalShadowPass>::New();
        if (variant == "pcf4")
        {
          pass->SetFilterToPCF4();
        }
        else if (variant == "hard")
        {
          pass->SetFilterToHard();
        }
        else
        {
          pass->SetFilterToPoisson();
        }
        return Wrap(pass);
      } },
    { "silhouette",
      "vtkSilhouetteShadowPass: silhouette-distance shadow maps (Valient & Bujnak): the signed "
      "distance to the nearest silhouette, drawn from topology aware meshes, anti-aliases the "
      "shadow map's edges and sizes penumbrae from the light's radius",
      { { "soft", "four samples, penumbrae from the light's radius" },
        { "hard", "one sample: anti-aliased hard shadows" } },
      WithCommonParameters({
        Bind<vtkSilhouetteShadowPass, double>("expected_width", ValueType::Number,
          Range::Between(0.0, 256.0),
          "expected silhouette width in shadow-map texels; 0 sizes it from the light (twice the "
          "widest penumbra; 2 for hard shadows)",
          &vtkSilhouetteShadowPass::SetExpectedWidth, &vtkSilhouetteShadowPass::GetExpectedWidth),
        Bind<vtkSilhouetteShadowPass, double>("edge_width", ValueType::Number,
          Range::Between(0.01, 16.0),
          "texels over which a hard edge goes from lit to shadowed (its anti-aliasing)",
          &vtkSilhouetteShadowPass::SetEdgeWidth, &vtkSilhouetteShadowPass::GetEdgeWidth),
        Bind<vtkSilhouetteShadowPass, double>("max_penumbra", ValueType::Number,
          Range::Between(1.0, 128.0),
          "soft: widest penumbra half-width kept, in texels (wider ones are clamped)",
          &vtkSilhouetteShadowPass::SetMaximumPenumbra,
          &vtkSilhouetteShadowPass::GetMaximumPenumbra),
        Bind<vtkSilhouetteShadowPass, double>("sample_spread", ValueType::Number,
          Range::Between(0.0, 0.8),
          "soft: distance of the three outer samples from the point, in penumbra half-widths",
          &vtkSilhouetteShadowPass::SetSampleSpread, &vtkSilhouetteShadowPass::GetSampleSpread),
        Bind<vtkSilhouetteShadowPass, int>("lookup_texels", ValueType::Integer,
          Range::Between(8, 4096), "lookup texture texels per segment of eq. 4",
          &vtkSilhouetteShadowPass::SetLookupTexels, &vtkSilhouetteShadowPass::GetLookupTexels),
        Bind<vtkSilhouetteShadowPass, int>("lookup_rows", ValueType::Integer,
          Range::Between(2, 1024), "soft: lookup texture rows, one penumbra width each",
          &vtkSilhouetteShadowPass::SetLookupRows, &vtkSilhouetteShadowPass::GetLookupRows),
        Bind<vtkSilhouetteShadowPass, bool>("drop_non_silhouette_faces", ValueType::Boolean,
          Range::Any(),
          "for casters that do not change shape: leave faces that can never be on a silhouette "
          "out of their topology aware meshes",
          &vtkSilhouetteShadowPass::SetDropNonSilhouetteFaces,
          &vtkSilhouetteShadowPass::GetDropNonSilhouetteFaces),
        Bind<vtkSilhouetteShadowPass, bool>("debug_view", ValueType::Boolean, Range::Any(),
          "show the signed distance map where receivers look it up (0.5 on a silhouette, "
          "darker on the occluder's side)",
          &vtkSilhouetteShadowPass::SetDebugView, &vtkSilhouetteShadowPass::GetDebugView),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkSilhouetteShadowPass>::New();
        if (variant == "hard")
        {
          pass->SetVariantToHard();
        }
        else
        {
          pass->SetVariantToSoft();
        }
        return Wrap(pass);
      } },
    { "smoothies",
      "vtkSmoothieShadowPass: smoothies (Chan & Durand, as Volokh implements them): soft shadow "
      "edges from geometry extruded along the casters' silhouettes as seen from the light, "
      "outside a hard shadow-map umbra",
      {},
      WithCommonParameters({
        Bind<vtkSmoothieShadowPass, double>("thickness", ValueType::Number,
          Range::Between(0.0, 256.0),
          "fixed smoothie thickness in shadow-map texels, with the report's alpha / (1 - b/r); "
          "0 sizes it from the light's radius (the outer half of its penumbra)",
          &vtkSmoothieShadowPass::SetThickness, &vtkSmoothieShadowPass::GetThickness),
        Bind<vtkSmoothieShadowPass, double>("penumbra_scale", ValueType::Number,
          Range::Between(0.01, 4.0),
          "sized from the radius: the soft edge's width over the outer half of the light's "
          "penumbra",
          &vtkSmoothieShadowPass::SetPenumbraScale, &vtkSmoothieShadowPass::GetPenumbraScale),
        Bind<vtkSmoothieShadowPass, int>("falloff", ValueType::Integer, Range::Between(0, 1),
          "how the shadow rises across a smoothie: 0 linearly (the report's alpha'), 1 as its "
          "square root, steepest at the umbra",
          &vtkSmoothieShadowPass::SetFalloff, &vtkSmoothieShadowPass::GetFalloff),
        Bind<vtkSmoothieShadowPass, double>("max_thickness", ValueType::Number,
          Range::Between(1.0, 1024.0), "widest smoothie, in shadow-map texels",
          &vtkSmoothieShadowPass::SetMaximumThickness, &vtkSmoothieShadowPass::GetMaximumThickness),
        Bind<vtkSmoothieShadowPass, int>("silhouette_search", ValueType::Integer,
          Range::Between(0, 1),
          "how silhouette edges are found: 1 the normal-cone tree, 0 brute force (the same edges)",
          &vtkSmoothieShadowPass::SetSilhouetteSearch, &vtkSmoothieShadowPass::GetSilhouetteSearch),
        Bind<vtkSmoothieShadowPass, bool>("build_on_gpu", ValueType::Boolean, Range::Any(),
          "build smoothie edges and corners in a geometry shader (true) or, per frustum, on the "
          "CPU",
          &vtkSmoothieShadowPass::SetBuildOnGPU, &vtkSmoothieShadowPass::GetBuildOnGPU),
      }),
      [](const std::string&)
      {
        auto pass = vtkSmartPointer<vtkSmoothieShadowPass>::New();
        TechniqueInstance instance = Wrap(pass);
        vtkSmoothieShadowPass* smoothies = pass;
        instance.CpuTime = [smoothies]() { return smoothies->GetSilhouetteTime(); };
        return instance;
      } },
    { "aliasfree",
      "vtkAliasFreeShadowPass: alias-free shadow maps (Sintorn, Eisemann & Assarsson): shadows "
      "tested for exactly the points the camera sees, in OpenGL 4.3 compute; soft shadows as the "
      "fraction of light samples each triangle hides",
      { { "soft", "sample-based visibility of the light's sphere (or disc, rectangle, cone)" },
        { "hard", "alias-free hard shadows from the light's centre" } },
      WithCommonParameters({
        Bind<vtkAliasFreeShadowPass, int>("light_samples", ValueType::Integer,
          Range::Between(32, 1024), "soft: light samples per view sample (rounded up to 32s)",
          &vtkAliasFreeShadowPass::SetNumberOfLightSamples,
          &vtkAliasFreeShadowPass::GetNumberOfLightSamples),
        Bind<vtkAliasFreeShadowPass, int>("light_shape", ValueType::Integer, Range::Between(0, 2),
          "soft, spot lights: 0 a sphere of the radius, 1 a disc, 2 a square of side 2 radius, "
          "facing along the light's axis",
          &vtkAliasFreeShadowPass::SetLightShape, &vtkAliasFreeShadowPass::GetLightShape),
        { "light_scale", ValueType::Vector3, Range::Any(),
          "soft, spot lights: the shape's scale across the axis (x: the world's x made "
          "perpendicular to the axis, y: the axis crossed with it) and along it (z): an "
          "ellipsoid, an ellipse, a rectangle",
          [](TechniqueInstance& t, const Json& v)
          {
            Get<vtkAliasFreeShadowPass>(t)->SetLightScale(
              v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
          },
          [](TechniqueInstance& t)
          {
            const double* s = Get<vtkAliasFreeShadowPass>(t)->GetLightScale();
            return Json::array({ s[0], s[1], s[2] });
          } },
        Bind<vtkAliasFreeShadowPass, bool>("fit_to_view_samples", ValueType::Boolean, Range::Any(),
          "fit each light's map to the view samples it sees",
          &vtkAliasFreeShadowPass::SetFitToViewSamples,
          &vtkAliasFreeShadowPass::GetFitToViewSamples),
        Bind<vtkAliasFreeShadowPass, bool>("restrict_to_silhouettes", ValueType::Boolean,
          Range::Any(),
          "soft: test light samples only where silhouette edges cast penumbrae; elsewhere the "
          "light's centre decides",
          &vtkAliasFreeShadowPass::SetRestrictToSilhouettes,
          &vtkAliasFreeShadowPass::GetRestrictToSilhouettes),
        Bind<vtkAliasFreeShadowPass, bool>("jitter", ValueType::Boolean, Range::Any(),
          "soft: while nothing moves, turn the light samples every frame and average the frames",
          &vtkAliasFreeShadowPass::SetJitter, &vtkAliasFreeShadowPass::GetJitter),
        Bind<vtkAliasFreeShadowPass, int>("max_frames_accumulated", ValueType::Integer,
          Range::Between(1, 1024), "soft, jitter: most frames averaged",
          &vtkAliasFreeShadowPass::SetMaximumFramesAccumulated,
          &vtkAliasFreeShadowPass::GetMaximumFramesAccumulated),
        Bind<vtkAliasFreeShadowPass, bool>("bent_normals", ValueType::Boolean, Range::Any(),
          "smooth shading without light leaks at shadow borders: surfaces' Phong normals bent "
          "towards their faces' so that they darken before the faces turned from the light",
          &vtkAliasFreeShadowPass::SetBentNormals, &vtkAliasFreeShadowPass::GetBentNormals),
        Bind<vtkAliasFreeShadowPass, double>("memory_limit", ValueType::Number,
          Range::Between(1.0, 65536.0),
          "MiB the lists, masks and tables may take; a frame needing more is drawn unshadowed",
          &vtkAliasFreeShadowPass::SetMemoryLimit, &vtkAliasFreeShadowPass::GetMemoryLimit),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkAliasFreeShadowPass>::New();
        if (variant == "hard")
        {
          pass->SetVariantToHard();
        }
        return Wrap(pass);
      } },
    { "vtk",
      "VTK 9.1's vtkShadowMapPass and vtkShadowMapBakerPass, the baseline: hard shadows, "
      "opaque geometry only, light radius ignored",
      {}, {}, [](const std::string&) { return MakeVtkShadowMapPass(); } },
  };
  return techniques;
}

//------------------------------------------------------------------------------
TechniqueSpec ParseTechniqueSpec(const std::string& text, const std::string& where)
{
  TechniqueSpec spec;
  const auto colon = text.find(':');
  spec.Name = text.substr(0, colon);
  const Technique& technique = RequireTechnique(spec.Name, where);
  if (colon != std::string::npos)
  {
    spec.Variant = text.substr(colon + 1);
    RequireVariant(technique, spec.Variant, where);
  }
  return spec;
}

//------------------------------------------------------------------------------
void CheckTechniqueParameters(
  const std::string& name, const Json& parameters, const std::string& path)
{
  const Technique& technique = RequireTechnique(name, path);
  if (!parameters.is_object())
  {
    throw InputError(path, "expected an object");
  }
  Json own = parameters;
  if (own.contains("variant"))
  {
    const std::string variantPath = FieldPath(path, "variant");
    RequireVariant(technique, ReadString(own["variant"], variantPath), variantPath);
    own.erase("variant");
  }
  CheckParameters(technique.Parameters, own, path);
}

//------------------------------------------------------------------------------
TechniqueInstance CreateTechnique(const TechniqueSpec& spec, int mapSize, const Json& parameters)
{
  const Technique& technique = RequireTechnique(spec.Name, "technique");
  std::string variant = spec.Variant;
  if (variant.empty() && parameters.contains("variant"))
  {
    variant = parameters["variant"].get<std::string>();
  }
  if (variant.empty() && !technique.Variants.empty())
  {
    variant = technique.Variants.front().Name;
  }

  TechniqueInstance instance = technique.Create(variant);
  instance.Spec = spec.ToString();
  if (instance.Shadows)
  {
    instance.Shadows->SetMapSize(mapSize);
  }
  if (instance.Baker)
  {
    instance.Baker->SetResolution(static_cast<unsigned int>(mapSize));
  }
  for (const TechniqueParameter& parameter : technique.Parameters)
  {
    if (parameters.contains(parameter.Key))
    {
      parameter.Apply(instance, parameters[parameter.Key]);
    }
  }
  return instance;
}

//------------------------------------------------------------------------------
void PrintTechniques(std::ostream& os)
{
  os << "Techniques, as --technique SPEC with SPEC = name[:variant]. Parameters go in the\n"
        "scene's \"shadows\" object under the technique's name, e.g.\n"
        "  \"shadows\": {\"technique\": \"hard\", \"map_size\": 2048, "
        "\"hard\": {\"pcf_radius\": 2}}\n"
        "and \"shadows.map_size\" (default 1024) sets every technique's shadow map size.\n";
  for (const Technique& technique : Techniques())
  {
    os << "\n" << technique.Name << "\n";
    PrintWrapped(os, technique.Summary, 2);
    for (std::size_t i = 0; i < technique.Variants.size(); ++i)
    {
      const TechniqueVariant& variant = technique.Variants[i];
      os << "  variant " << std::left << std::setw(12) << variant.Name;
      PrintWrapped(os, variant.Meaning + (i == 0 ? " (default)" : ""), 22, 22);
    }
    if (technique.Parameters.empty())
    {
      os << "  (no parameters)\n";
      continue;
    }
    TechniqueInstance defaults = technique.Create(
      technique.Variants.empty() ? std::string() : technique.Variants.front().Name);
    os << "  " << std::left << std::setw(20) << "parameter" << std::setw(9) << "type"
       << std::setw(9) << "default"
       << "meaning\n";
    for (const TechniqueParameter& parameter : technique.Parameters)
    {
      const std::string range = parameter.Allowed.Describe();
      os << "  " << std::left << std::setw(20) << parameter.Key << std::setw(9)
         << TypeName(parameter.Type) << std::setw(9) << parameter.Current(defaults).dump();
      PrintWrapped(os, parameter.Meaning + (range.empty() ? "" : "; " + range), 40, 40);
    }
  }
}

//------------------------------------------------------------------------------
std::vector<std::string> AllTechniqueSpecs()
{
  std::vector<std::string> specs;
  for (const Technique& technique : Techniques())
  {
    specs.push_back(technique.Name);
    for (std::size_t i = 1; i < technique.Variants.size(); ++i)
    {
      specs.push_back(technique.Name + ":" + technique.Variants[i].Name);
    }
  }
  return specs;
}
}
