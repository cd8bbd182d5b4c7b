// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowTechniqueCatalog.h"

#include "vtkAliasFreeShadowPass.h"
#include "vtkContactHardeningShadowPass.h"
#include "vtkHardShadowPass.h"
#include "vtkObjectFactory.h"
#include "vtkOmnidirectionalShadowPass.h"
#include "vtkReferenceShadowPass.h"
#include "vtkSilhouetteShadowPass.h"
#include "vtkSmartPointer.h"
#include "vtkSmoothieShadowPass.h"
#include "vtkSoftShadowPass.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShadowTechniqueCatalog);

namespace
{
struct Bounds
{
  double Minimum;
  double Maximum;
};

Bounds Any()
{
  return { -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity() };
}

Bounds Between(double minimum, double maximum)
{
  return { minimum, maximum };
}

Bounds AtLeast(double minimum)
{
  return { minimum, std::numeric_limits<double>::infinity() };
}

struct Parameter
{
  const char* Key;
  int Type;
  Bounds Allowed;
  const char* Meaning;
  /// Whether a pass has this parameter (is of the class that declares it).
  std::function<bool(vtkSoftShadowPass*)> Accepts;
  std::function<void(vtkSoftShadowPass*, const double*)> Set;
  std::function<void(vtkSoftShadowPass*, double*)> Get;
  /// The class's own clamp (vtkSetClampMacro's Get<Name>MinValue() and
  /// MaxValue()), read into Allowed when the table is made; unset when the
  /// table gives Allowed.
  std::function<Bounds(vtkSoftShadowPass*)> Clamp;
};

struct Variant
{
  const char* Name;
  const char* Meaning;
};

struct Technique
{
  const char* Name;
  const char* Summary;
  std::vector<Variant> Variants; ///< the first is the default; may be empty
  std::vector<Parameter> Parameters;
  std::function<vtkSmartPointer<vtkSoftShadowPass>(const std::string& variant)> Create;
};

template <typename PassType>
bool IsPass(vtkSoftShadowPass* pass)
{
  return PassType::SafeDownCast(pass) != nullptr;
}

/// A parameter that reaches the pass through its Set/Get methods.
template <typename PassType, typename Value>
Parameter Bind(const char* key, int type, Bounds allowed, const char* meaning,
  void (PassType::*set)(Value), Value (PassType::*get)())
{
  return { key, type, type == vtkShadowTechniqueCatalog::Boolean ? Between(0, 1) : allowed, meaning,
    IsPass<PassType>,
    [set](vtkSoftShadowPass* pass, const double* v)
    { (PassType::SafeDownCast(pass)->*set)(static_cast<Value>(v[0])); },
    [get](vtkSoftShadowPass* pass, double* v)
    { v[0] = static_cast<double>((PassType::SafeDownCast(pass)->*get)()); },
    nullptr };
}

/// A parameter whose class clamps it (vtkSetClampMacro): its bounds are the
/// class's own. Getters by type: const or not, as each VTK release has them.
template <typename PassType, typename Value, typename MinGetter, typename MaxGetter>
Parameter BindClamped(const char* key, int type, const char* meaning, void (PassType::*set)(Value),
  Value (PassType::*get)(), MinGetter minimum, MaxGetter maximum)
{
  Parameter parameter = Bind<PassType, Value>(key, type, Any(), meaning, set, get);
  parameter.Clamp = [minimum, maximum](vtkSoftShadowPass* pass)
  {
    PassType* typed = PassType::SafeDownCast(pass);
    return Bounds{ static_cast<double>((typed->*minimum)()),
      static_cast<double>((typed->*maximum)()) };
  };
  return parameter;
}

/// The setter, getter and clamp of property Name of Class, for BindClamped().
#define VTK_SHADOW_CLAMPED(Class, Name)                                                            \
  &Class::Set##Name, &Class::Get##Name, &Class::Get##Name##MinValue, &Class::Get##Name##MaxValue

template <typename PassType>
Parameter BindVector3(const char* key, Bounds allowed, const char* meaning,
  void (PassType::*set)(double, double, double), double* (PassType::*get)())
{
  return { key, vtkShadowTechniqueCatalog::Vector3, allowed, meaning, IsPass<PassType>,
    [set](vtkSoftShadowPass* pass, const double* v)
    { (PassType::SafeDownCast(pass)->*set)(v[0], v[1], v[2]); },
    [get](vtkSoftShadowPass* pass, double* v)
    {
      const double* value = (PassType::SafeDownCast(pass)->*get)();
      std::copy(value, value + 3, v);
    },
    nullptr };
}

constexpr int Boolean = vtkShadowTechniqueCatalog::Boolean;
constexpr int Integer = vtkShadowTechniqueCatalog::Integer;
constexpr int Number = vtkShadowTechniqueCatalog::Number;

// Parameters every technique built on vtkSoftShadowPass shares.
std::vector<Parameter> WithCommonParameters(std::vector<Parameter> own)
{
  own.push_back(Bind<vtkSoftShadowPass, double>("slope_scaled_bias", Number, Any(),
    "depth offset per unit of depth slope while drawing shadow maps (glPolygonOffset factor)",
    &vtkSoftShadowPass::SetSlopeScaledBias, &vtkSoftShadowPass::GetSlopeScaledBias));
  own.push_back(Bind<vtkSoftShadowPass, double>("constant_bias", Number, Any(),
    "constant depth offset while drawing shadow maps (glPolygonOffset units)",
    &vtkSoftShadowPass::SetConstantBias, &vtkSoftShadowPass::GetConstantBias));
  own.push_back(BindClamped<vtkSoftShadowPass, double>("normal_bias", Number,
    "how far in front of its surface a receiver point is looked up, along the light's ray, in "
    "shadow-map texels",
    VTK_SHADOW_CLAMPED(vtkSoftShadowPass, NormalBias)));
  own.push_back(BindClamped<vtkSoftShadowPass, double>("distance_bias", Number,
    "point lights: factor on squared distances before comparing with the cube map",
    VTK_SHADOW_CLAMPED(vtkSoftShadowPass, DistanceBias)));
  own.push_back(Bind<vtkSoftShadowPass, bool>("packed_cube_maps", Boolean, Any(),
    "point lights: RGBA8 cube maps packing squared distances, not float ones",
    &vtkSoftShadowPass::SetPackedCubeMaps, &vtkSoftShadowPass::GetPackedCubeMaps));
  own.push_back(Bind<vtkSoftShadowPass, bool>("depth_pre_pass", Boolean, Any(),
    "draw opaque depth first so that shading and shadow lookups run on visible fragments only",
    &vtkSoftShadowPass::SetDepthPrePass, &vtkSoftShadowPass::GetDepthPrePass));
  return own;
}

std::vector<Technique> MakeTechniques();

/// The table, with every clamped parameter's bounds read from a pass of its
/// technique.
const std::vector<Technique>& Techniques()
{
  static const std::vector<Technique> techniques = []
  {
    std::vector<Technique> made = MakeTechniques();
    for (Technique& technique : made)
    {
      vtkSmartPointer<vtkSoftShadowPass> pass =
        technique.Create(technique.Variants.empty() ? "" : technique.Variants[0].Name);
      for (Parameter& parameter : technique.Parameters)
      {
        if (parameter.Clamp)
        {
          parameter.Allowed = parameter.Clamp(pass);
        }
      }
    }
    return made;
  }();
  return techniques;
}

std::vector<Technique> MakeTechniques()
{
  return {
    { "hard", "vtkHardShadowPass: one shadow map per light, percentage-closer filtering",
      { { "layered", "point lights' cube maps drawn in one layered pass" },
        { "sixpass", "point lights' cube maps drawn one face a pass, as in the paper" } },
      WithCommonParameters({
        BindClamped<vtkHardShadowPass, int>("pcf_radius", Integer,
          "radius in texels of the square PCF kernel: a (2r+1)^2-texel footprint; 0 is one tap",
          VTK_SHADOW_CLAMPED(vtkHardShadowPass, PCFRadius)),
        Bind<vtkHardShadowPass, bool>("hardware_filtering", Boolean, Any(),
          "bilinear depth-comparison filtering of every tap; off gives binary taps",
          &vtkHardShadowPass::SetHardwareFiltering, &vtkHardShadowPass::GetHardwareFiltering),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkHardShadowPass>::New();
        pass->SetSinglePassCubeMaps(variant != "sixpass");
        return pass;
      } },
    { "reference",
      "vtkReferenceShadowPass: ground truth, the average of many hard shadow maps drawn from "
      "points sampled over each light (slow)",
      { { "disc", "points on a disc across the light's axis (SPEC's reference)" },
        { "sphere",
          "points in the light's sphere, uniform over its disc from every side, as the "
          "ray-cast truth" } },
      WithCommonParameters({
        BindClamped<vtkReferenceShadowPass, int>("samples", Integer,
          "light samples (shadow maps) per light, rounded down to a square",
          VTK_SHADOW_CLAMPED(vtkReferenceShadowPass, NumberOfSamples)),
        Bind<vtkReferenceShadowPass, unsigned int>("seed", Integer, Between(0.0, 2147483647.0),
          "seed of the light sample jitter", &vtkReferenceShadowPass::SetSeed,
          &vtkReferenceShadowPass::GetSeed),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkReferenceShadowPass>::New();
        pass->SetSampling(
          variant == "sphere" ? vtkReferenceShadowPass::Sphere : vtkReferenceShadowPass::Disc);
        return pass;
      } },
    { "contact",
      "vtkContactHardeningShadowPass: contact-hardening soft shadows in screen space (Cherry & "
      "Kooima): a distance map of S and D, then S softened with a D-sized filter",
      { { "pcf", "the mean over a disc of D pixels on the receiver" },
        { "gaussian", "one separable Gaussian blur of D pixels" },
        { "multipass", "up to pass_limit Poisson-disk Gaussian blurs, D counting them down" } },
      WithCommonParameters({
        Bind<vtkContactHardeningShadowPass, bool>("use_light_size", Boolean, Any(),
          "size kernels from the light's radius, w = (d_receiver - d_blocker) * w_light / "
          "d_blocker; off uses dp and dm",
          &vtkContactHardeningShadowPass::SetUseLightSize,
          &vtkContactHardeningShadowPass::GetUseLightSize),
        BindClamped<vtkContactHardeningShadowPass, double>("dp", Number,
          "distance power Dp in D = (occluder distance)^Dp * Dm",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, DistancePower)),
        BindClamped<vtkContactHardeningShadowPass, double>("dm", Number,
          "distance multiplier Dm in D = (occluder distance)^Dp * Dm",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, DistanceMultiplier)),
        BindClamped<vtkContactHardeningShadowPass, int>("pass_limit", Integer,
          "most blur passes (multipass)",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, PassLimit)),
        BindClamped<vtkContactHardeningShadowPass, int>("min_kernel", Integer,
          "first kernel size in pixels when the kernel grows (multipass)",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, MinimumKernelSize)),
        BindClamped<vtkContactHardeningShadowPass, int>("max_kernel", Integer,
          "largest kernel size in pixels",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, MaximumKernelSize)),
        Bind<vtkContactHardeningShadowPass, bool>("growing_kernel", Boolean, Any(),
          "grow the kernel by 2 pixels a pass from min_kernel (multipass)",
          &vtkContactHardeningShadowPass::SetGrowingKernel,
          &vtkContactHardeningShadowPass::GetGrowingKernel),
        BindClamped<vtkContactHardeningShadowPass, int>("taps", Integer,
          "Poisson-disk taps per blur (multipass)",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, PoissonTaps)),
        Bind<vtkContactHardeningShadowPass, bool>("dilation", Boolean, Any(),
          "spread D to lit pixels near shadows: the outer penumbra (pass 3)",
          &vtkContactHardeningShadowPass::SetDilation, &vtkContactHardeningShadowPass::GetDilation),
        BindClamped<vtkContactHardeningShadowPass, int>("dilation_size", Integer,
          "dilation kernel size in pixels",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, DilationSize)),
        Bind<vtkContactHardeningShadowPass, bool>("early_out", Boolean, Any(),
          "D = 0 deep inside the umbra, so blurs skip it",
          &vtkContactHardeningShadowPass::SetUmbraEarlyOut,
          &vtkContactHardeningShadowPass::GetUmbraEarlyOut),
        BindClamped<vtkContactHardeningShadowPass, int>("early_out_size", Integer,
          "early-out neighbourhood in pixels (above max_kernel)",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, EarlyOutKernelSize)),
        BindClamped<vtkContactHardeningShadowPass, int>("resolution_divisor", Integer,
          "screen-space passes on buffers this many times smaller than the window on each axis; "
          "kernel sizes count their pixels",
          VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, ResolutionDivisor)),
        Bind<vtkContactHardeningShadowPass, bool>("refine_unresolved", Boolean, Any(),
          "where the buffers cannot hold a penumbra (floors seen nearly edge-on), receivers "
          "filter their hard shadow again in light space over the penumbra's width",
          &vtkContactHardeningShadowPass::SetRefineUnresolved,
          &vtkContactHardeningShadowPass::GetRefineUnresolved),
        Bind<vtkContactHardeningShadowPass, bool>("debug_view", Boolean, Any(),
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
        return pass;
      } },
    { "omni",
      "vtkOmnidirectionalShadowPass: point lights' cube maps of squared distances (Gerasimov, "
      "GPU Gems ch. 12), filtered; spot and directional lights as hard with 4-tap PCF",
      { { "poisson", "blocker search and rotated Poisson-disk PCF sized by the light's radius" },
        { "pcf4", "the chapter's 4-tap PCF" }, { "hard", "one tap" } },
      WithCommonParameters({
        BindClamped<vtkOmnidirectionalShadowPass, int>("pcf_radius", Integer,
          "pcf4: distance between the taps, in texels",
          VTK_SHADOW_CLAMPED(vtkOmnidirectionalShadowPass, PCFRadius)),
        BindClamped<vtkOmnidirectionalShadowPass, int>("taps", Integer,
          "poisson: taps of the blocker search and of the filter",
          VTK_SHADOW_CLAMPED(vtkOmnidirectionalShadowPass, PoissonTaps)),
        Bind<vtkSoftShadowPass, bool>("single_pass_cube_maps", Boolean, Any(),
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
        return pass;
      } },
    { "silhouette",
      "vtkSilhouetteShadowPass: silhouette-distance shadow maps (Valient & Bujnak): the signed "
      "distance to the nearest silhouette, drawn from topology aware meshes, anti-aliases the "
      "shadow map's edges and sizes penumbrae from the light's radius",
      { { "soft", "four samples, penumbrae from the light's radius" },
        { "hard", "one sample: anti-aliased hard shadows" } },
      WithCommonParameters({
        BindClamped<vtkSilhouetteShadowPass, double>("expected_width", Number,
          "expected silhouette width in shadow-map texels; 0 sizes it from the light (twice the "
          "widest penumbra; 2 for hard shadows)",
          VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, ExpectedWidth)),
        BindClamped<vtkSilhouetteShadowPass, double>("edge_width", Number,
          "texels over which a hard edge goes from lit to shadowed (its anti-aliasing)",
          VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, EdgeWidth)),
        BindClamped<vtkSilhouetteShadowPass, double>("max_penumbra", Number,
          "soft: widest penumbra half-width kept, in texels (wider ones are clamped)",
          VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, MaximumPenumbra)),
        BindClamped<vtkSilhouetteShadowPass, double>("sample_spread", Number,
          "soft: distance of the three outer samples from the point, in penumbra half-widths",
          VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, SampleSpread)),
        BindClamped<vtkSilhouetteShadowPass, int>("lookup_texels", Integer,
          "lookup texture texels per segment of eq. 4",
          VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, LookupTexels)),
        BindClamped<vtkSilhouetteShadowPass, int>("lookup_rows", Integer,
          "soft: lookup texture rows, one penumbra width each",
          VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, LookupRows)),
        BindClamped<vtkSilhouetteShadowPass, int>("silhouette_geometry", Integer,
          "how pass 2 covers the thick silhouette: 1 a rectangle around each silhouette edge "
          "(geometry shader), 0 each silhouette face grown about its incenter (the paper's eq. 2); "
          "the same map",
          VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, SilhouetteGeometry)),
        Bind<vtkSilhouetteShadowPass, bool>("per_face_attributes", Boolean, Any(),
          "topology aware meshes once a face (instanced), not once a corner: a third of the "
          "memory (always so with silhouette_geometry 1)",
          &vtkSilhouetteShadowPass::SetPerFaceAttributes,
          &vtkSilhouetteShadowPass::GetPerFaceAttributes),
        Bind<vtkSilhouetteShadowPass, bool>("half_precision", Boolean, Any(),
          "topology aware meshes in 16-bit floats: half the memory, corners rounded",
          &vtkSilhouetteShadowPass::SetHalfPrecision, &vtkSilhouetteShadowPass::GetHalfPrecision),
        Bind<vtkSilhouetteShadowPass, bool>("drop_non_silhouette_faces", Boolean, Any(),
          "for casters that do not change shape: leave faces that can never be on a silhouette "
          "out of their topology aware meshes",
          &vtkSilhouetteShadowPass::SetDropNonSilhouetteFaces,
          &vtkSilhouetteShadowPass::GetDropNonSilhouetteFaces),
        Bind<vtkSilhouetteShadowPass, bool>("debug_view", Boolean, Any(),
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
        return pass;
      } },
    { "smoothies",
      "vtkSmoothieShadowPass: smoothies (Chan & Durand, as Volokh implements them): soft shadow "
      "edges from geometry extruded along the casters' silhouettes as seen from the light, "
      "outside a hard shadow-map umbra",
      {},
      WithCommonParameters({
        BindClamped<vtkSmoothieShadowPass, double>("thickness", Number,
          "fixed smoothie thickness in shadow-map texels, with the report's alpha / (1 - b/r); "
          "0 sizes it from the light's radius (the outer half of its penumbra)",
          VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, Thickness)),
        BindClamped<vtkSmoothieShadowPass, double>("penumbra_scale", Number,
          "sized from the radius: the soft edge's width over the outer half of the light's "
          "penumbra",
          VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, PenumbraScale)),
        BindClamped<vtkSmoothieShadowPass, int>("falloff", Integer,
          "how the shadow rises across a smoothie: 0 linearly (the report's alpha'), 1 as its "
          "square root, steepest at the umbra",
          VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, Falloff)),
        BindClamped<vtkSmoothieShadowPass, double>("max_thickness", Number,
          "widest smoothie, in shadow-map texels",
          VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, MaximumThickness)),
        BindClamped<vtkSmoothieShadowPass, int>("silhouette_search", Integer,
          "how silhouette edges are found: 1 the normal-cone tree, 0 brute force (the same edges)",
          VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, SilhouetteSearch)),
        Bind<vtkSmoothieShadowPass, bool>("build_on_gpu", Boolean, Any(),
          "build smoothie edges and corners in a geometry shader (true) or, per frustum, on the "
          "CPU",
          &vtkSmoothieShadowPass::SetBuildOnGPU, &vtkSmoothieShadowPass::GetBuildOnGPU),
      }),
      [](const std::string&) { return vtkSmartPointer<vtkSmoothieShadowPass>::New(); } },
    { "aliasfree",
      "vtkAliasFreeShadowPass: alias-free shadow maps (Sintorn, Eisemann & Assarsson): shadows "
      "tested for exactly the points the camera sees, in OpenGL 4.3 compute; soft shadows as the "
      "fraction of light samples each triangle hides",
      { { "soft", "sample-based visibility of the light's sphere (or disc, rectangle, cone)" },
        { "hard", "alias-free hard shadows from the light's centre" } },
      WithCommonParameters({
        Bind<vtkAliasFreeShadowPass, int>("light_samples", Integer, Between(32, 1024),
          "soft: light samples per view sample (rounded up to 32s)",
          &vtkAliasFreeShadowPass::SetNumberOfLightSamples,
          &vtkAliasFreeShadowPass::GetNumberOfLightSamples),
        BindClamped<vtkAliasFreeShadowPass, int>("light_shape", Integer,
          "soft, spot lights: 0 a sphere of the radius, 1 a disc, 2 a square of side 2 radius, "
          "facing along the light's axis",
          VTK_SHADOW_CLAMPED(vtkAliasFreeShadowPass, LightShape)),
        BindVector3<vtkAliasFreeShadowPass>("light_scale", AtLeast(1.0e-3),
          "soft, spot lights: the shape's scale across the axis (x: the world's x made "
          "perpendicular to the axis, y: the axis crossed with it) and along it (z): an "
          "ellipsoid, an ellipse, a rectangle",
          &vtkAliasFreeShadowPass::SetLightScale, &vtkAliasFreeShadowPass::GetLightScale),
        Bind<vtkAliasFreeShadowPass, bool>("fit_to_view_samples", Boolean, Any(),
          "fit each light's map to the view samples it sees",
          &vtkAliasFreeShadowPass::SetFitToViewSamples,
          &vtkAliasFreeShadowPass::GetFitToViewSamples),
        Bind<vtkAliasFreeShadowPass, bool>("restrict_to_silhouettes", Boolean, Any(),
          "soft: test light samples only where silhouette edges cast penumbrae; elsewhere the "
          "light's centre decides",
          &vtkAliasFreeShadowPass::SetRestrictToSilhouettes,
          &vtkAliasFreeShadowPass::GetRestrictToSilhouettes),
        Bind<vtkAliasFreeShadowPass, bool>("jitter", Boolean, Any(),
          "soft: while nothing moves, turn the light samples every frame and average the frames",
          &vtkAliasFreeShadowPass::SetJitter, &vtkAliasFreeShadowPass::GetJitter),
        BindClamped<vtkAliasFreeShadowPass, int>("max_frames_accumulated", Integer,
          "soft, jitter: most frames averaged",
          VTK_SHADOW_CLAMPED(vtkAliasFreeShadowPass, MaximumFramesAccumulated)),
        Bind<vtkAliasFreeShadowPass, bool>("bent_normals", Boolean, Any(),
          "smooth shading without light leaks at shadow borders: surfaces' Phong normals bent "
          "towards their faces' so that they darken before the faces turned from the light",
          &vtkAliasFreeShadowPass::SetBentNormals, &vtkAliasFreeShadowPass::GetBentNormals),
        BindClamped<vtkAliasFreeShadowPass, double>("memory_limit", Number,
          "MiB the lists, masks and tables may take; a frame needing more is drawn unshadowed",
          VTK_SHADOW_CLAMPED(vtkAliasFreeShadowPass, MemoryLimit)),
      }),
      [](const std::string& variant)
      {
        auto pass = vtkSmartPointer<vtkAliasFreeShadowPass>::New();
        if (variant == "hard")
        {
          pass->SetVariantToHard();
        }
        return pass;
      } },
  };
}

const Technique* At(int technique)
{
  const auto& all = Techniques();
  return technique >= 0 && technique < static_cast<int>(all.size()) ? &all[technique] : nullptr;
}

const Parameter* ParameterAt(int technique, int parameter)
{
  const Technique* t = At(technique);
  return t && parameter >= 0 && parameter < static_cast<int>(t->Parameters.size())
    ? &t->Parameters[parameter]
    : nullptr;
}

const Variant* VariantAt(int technique, int variant)
{
  const Technique* t = At(technique);
  return t && variant >= 0 && variant < static_cast<int>(t->Variants.size()) ? &t->Variants[variant]
                                                                             : nullptr;
}

template <typename Items>
int FindNamed(const Items& items, const char* name, const char* Items::value_type::*field)
{
  for (std::size_t i = 0; name && i < items.size(); ++i)
  {
    if (std::strcmp(items[i].*field, name) == 0)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetNumberOfTechniques()
{
  return static_cast<int>(Techniques().size());
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::FindTechnique(const char* name)
{
  return FindNamed(Techniques(), name, &Technique::Name);
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetTechniqueName(int technique)
{
  const Technique* t = At(technique);
  return t ? t->Name : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetTechniqueSummary(int technique)
{
  const Technique* t = At(technique);
  return t ? t->Summary : nullptr;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetNumberOfVariants(int technique)
{
  const Technique* t = At(technique);
  return t ? static_cast<int>(t->Variants.size()) : 0;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::FindVariant(int technique, const char* name)
{
  const Technique* t = At(technique);
  return t ? FindNamed(t->Variants, name, &Variant::Name) : -1;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetVariantName(int technique, int variant)
{
  const Variant* v = VariantAt(technique, variant);
  return v ? v->Name : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetVariantMeaning(int technique, int variant)
{
  const Variant* v = VariantAt(technique, variant);
  return v ? v->Meaning : nullptr;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetNumberOfParameters(int technique)
{
  const Technique* t = At(technique);
  return t ? static_cast<int>(t->Parameters.size()) : 0;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::FindParameter(int technique, const char* key)
{
  const Technique* t = At(technique);
  return t ? FindNamed(t->Parameters, key, &Parameter::Key) : -1;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetParameterKey(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Key : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetParameterMeaning(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Meaning : nullptr;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetParameterType(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Type : -1;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetParameterSize(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? (p->Type == Vector3 ? 3 : 1) : 0;
}

//------------------------------------------------------------------------------
double vtkShadowTechniqueCatalog::GetParameterMinimum(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Allowed.Minimum : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
double vtkShadowTechniqueCatalog::GetParameterMaximum(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Allowed.Maximum : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
vtkSoftShadowPass* vtkShadowTechniqueCatalog::NewPass(int technique, int variant)
{
  const Technique* t = At(technique);
  const int variants = GetNumberOfVariants(technique);
  if (!t || variant < -1 || variant >= std::max(variants, 1))
  {
    std::ostringstream problem;
    problem << "vtkShadowTechniqueCatalog: no technique " << technique << " with variant "
            << variant << " (there are " << GetNumberOfTechniques() << " techniques)";
    vtkOutputWindowDisplayErrorText(problem.str().c_str());
    return nullptr;
  }
  const std::string name = variants ? t->Variants[std::max(variant, 0)].Name : "";
  vtkSmartPointer<vtkSoftShadowPass> pass = t->Create(name);
  pass->Register(nullptr);
  return pass;
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::SetParameter(
  vtkSoftShadowPass* pass, int technique, int parameter, const double values[3])
{
  const Parameter* p = ParameterAt(technique, parameter);
  if (!pass)
  {
    vtkOutputWindowDisplayErrorText("vtkShadowTechniqueCatalog: SetParameter() without a pass");
    return false;
  }
  if (!p || !p->Accepts(pass))
  {
    vtkErrorWithObjectMacro(
      pass, << "no parameter " << parameter << " of technique " << technique << " for this pass");
    return false;
  }
  if (!IsAllowed(technique, parameter, values))
  {
    std::ostringstream shown;
    for (int i = 0; i < GetParameterSize(technique, parameter); ++i)
    {
      shown << (i ? " " : "") << values[i];
    }
    vtkErrorWithObjectMacro(pass, << Techniques()[technique].Name << "." << p->Key << ": "
                                  << shown.str() << " is not allowed ("
                                  << (p->Type == Boolean      ? "0 or 1"
                                         : p->Type == Integer ? "a whole number"
                                                              : "a finite number")
                                  << " from " << p->Allowed.Minimum << " to " << p->Allowed.Maximum
                                  << ")");
    return false;
  }
  p->Set(pass, values);
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::IsAllowed(int technique, int parameter, const double values[3])
{
  const Parameter* p = ParameterAt(technique, parameter);
  if (!p || !values)
  {
    return false;
  }
  for (int i = 0; i < GetParameterSize(technique, parameter); ++i)
  {
    const double v = values[i];
    if (!std::isfinite(v) || v < p->Allowed.Minimum || v > p->Allowed.Maximum ||
      (p->Type != Number && p->Type != Vector3 && v != std::floor(v)))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::GetParameter(
  vtkSoftShadowPass* pass, int technique, int parameter, double values[3])
{
  const Parameter* p = ParameterAt(technique, parameter);
  if (!p || !pass || !p->Accepts(pass))
  {
    return false;
  }
  p->Get(pass, values);
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowTechniqueCatalog::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (int t = 0; t < GetNumberOfTechniques(); ++t)
  {
    os << indent << GetTechniqueName(t) << ":";
    for (int v = 0; v < GetNumberOfVariants(t); ++v)
    {
      os << (v ? ", " : " variants ") << GetVariantName(t, v);
    }
    os << "\n";
    vtkSmartPointer<vtkSoftShadowPass> pass = vtk::TakeSmartPointer(NewPass(t, 0));
    for (int p = 0; p < GetNumberOfParameters(t); ++p)
    {
      double values[3] = { 0, 0, 0 };
      GetParameter(pass, t, p, values);
      os << indent.GetNextIndent() << GetParameterKey(t, p) << ": " << values[0];
      if (GetParameterSize(t, p) == 3)
      {
        os << " " << values[1] << " " << values[2];
      }
      os << "\n";
    }
  }
}
