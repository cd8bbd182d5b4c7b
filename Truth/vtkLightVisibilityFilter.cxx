// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightVisibilityFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolygon.h"
#include "vtkRayCastScene.h"
#include "vtkSMPTools.h"
#include "vtkSolarPosition.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightVisibilityFilter);

namespace
{
// Where a point (or a cell's centre) receives light from: its position and
// the unit normal of its surface's lit side, or zero where it has none (a
// vertex or line), which sees every direction.
struct Receiver
{
  std::vector<glm::dvec3> Positions;
  std::vector<glm::dvec3> Normals;
};

glm::dvec3 Unit(const glm::dvec3& n)
{
  const double length = glm::length(n);
  return length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0);
}

// A point's key for its rays' jitter: its position as floats, hashed, so
// that it draws the same rays whichever process's piece holds it.
unsigned int PositionKey(const glm::dvec3& p)
{
  const float f[3] = { static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z) };
  uint32_t u[3];
  std::memcpy(u, f, sizeof(u));
  return u[0] * 73856093U ^ u[1] * 19349663U ^ u[2] * 83492791U;
}

// Only what casts, to send to the other processes: the surfaces' points,
// polygons and strips, as one mesh.
vtkSmartPointer<vtkPolyData> Shapes(const std::vector<vtkPolyData*>& surfaces)
{
  vtkNew<vtkAppendPolyData> shapes;
  for (vtkPolyData* data : surfaces)
  {
    vtkNew<vtkPolyData> shape;
    shape->SetPoints(data->GetPoints());
    shape->SetPolys(data->GetPolys());
    shape->SetStrips(data->GetStrips());
    shapes->AddInputData(shape);
  }
  if (surfaces.empty())
  {
    return vtkSmartPointer<vtkPolyData>::New();
  }
  shapes->Update();
  return shapes->GetOutput();
}

// The points and their normals: the receiver's own, else computed without
// splitting (so that point ids stay); none without polygons.
bool PointReceivers(vtkPolyData* surface, Receiver& receiver)
{
  const vtkIdType n = surface->GetNumberOfPoints();
  vtkDataArray* normals = surface->GetPointData()->GetNormals();
  if (!normals)
  {
    normals = surface->GetPointData()->GetArray("Normals");
  }
  vtkNew<vtkPolyDataNormals> computed;
  const bool faces = surface->GetNumberOfPolys() + surface->GetNumberOfStrips() > 0;
  if (faces &&
    (!normals || normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != n))
  {
    computed->SetInputData(surface);
    computed->SplittingOff();
    computed->Update();
    normals = computed->GetOutput()->GetPointData()->GetNormals();
    if (!normals || normals->GetNumberOfTuples() != n)
    {
      return false;
    }
  }
  receiver.Positions.resize(static_cast<size_t>(n));
  receiver.Normals.resize(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], m[3] = { 0.0, 0.0, 0.0 };
    surface->GetPoint(i, p);
    if (faces)
    {
      normals->GetTuple(i, m);
    }
    receiver.Positions[i] = glm::dvec3(p[0], p[1], p[2]);
    receiver.Normals[i] = Unit(glm::dvec3(m[0], m[1], m[2]));
  }
  return true;
}

// Each cell's centre (the mean of its points) and its polygon's normal; a
// strip's is its triangles' (each wound as the strip alternates).
void CellReceivers(vtkPolyData* surface, Receiver& receiver)
{
  const vtkIdType cells = surface->GetNumberOfCells();
  receiver.Positions.assign(static_cast<size_t>(cells), glm::dvec3(0.0));
  receiver.Normals.assign(static_cast<size_t>(cells), glm::dvec3(0.0));
  vtkNew<vtkIdList> ids;
  vtkPoints* points = surface->GetPoints();
  auto point = [&](vtkIdType k)
  {
    double p[3];
    points->GetPoint(ids->GetId(k), p);
    return glm::dvec3(p[0], p[1], p[2]);
  };
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const int type = surface->GetCellType(c);
    surface->GetCellPoints(c, ids);
    const vtkIdType count = ids->GetNumberOfIds();
    glm::dvec3 centre(0.0);
    for (vtkIdType k = 0; k < count; ++k)
    {
      centre += point(k);
    }
    centre = count > 0 ? centre / static_cast<double>(count) : centre;
    glm::dvec3 normal(0.0);
    if (type == VTK_TRIANGLE_STRIP)
    {
      // A strip bends: its triangles' centres weighted by their areas, so
      // that the centre lies on it where it is flat.
      glm::dvec3 weighted(0.0);
      double area = 0.0;
      for (vtkIdType k = 0; k + 2 < count; ++k)
      {
        const glm::dvec3 face = glm::cross(point(k + 1) - point(k), point(k + 2) - point(k));
        const double size = glm::length(face);
        normal += k % 2 == 0 ? face : -face;
        weighted += size * (point(k) + point(k + 1) + point(k + 2)) / 3.0;
        area += size;
      }
      centre = area > 0.0 ? weighted / area : centre;
    }
    else if (type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_POLYGON)
    {
      double n[3];
      vtkPolygon::ComputeNormal(points, static_cast<int>(count), ids->GetPointer(0), n);
      normal = glm::dvec3(n[0], n[1], n[2]);
    }
    receiver.Positions[c] = centre;
    receiver.Normals[c] = Unit(normal);
  }
}

// What VTK's shading makes of a light at a point, besides its visibility
// and the cosine: read once, before the threads.
struct Shading
{
  bool On = false;
  double Intensity = 0.0;
  double Attenuation[3] = { 1.0, 0.0, 0.0 }; // constant, linear, quadratic
  double Exponent = 0.0;

  explicit Shading(vtkLight* light)
    : On(light->GetSwitch() != 0)
    , Intensity(light->GetIntensity())
    , Exponent(light->GetExponent())
  {
    light->GetAttenuationValues(this->Attenuation);
  }

  // A positional light's attenuation and a spot light's cone at `at`.
  double Falloff(const vtkRayCastScene::Light& shape, const glm::dvec3& at) const
  {
    if (shape.Directional)
    {
      return 1.0;
    }
    const glm::dvec3 offset = at - shape.Position;
    const double distance = glm::length(offset);
    const double* k = this->Attenuation;
    const double denominator = k[0] + k[1] * distance + k[2] * distance * distance;
    double falloff = denominator > 0.0 ? 1.0 / denominator : 0.0;
    if (shape.Spot && distance > 0.0)
    {
      const double coneDot = glm::dot(offset / distance, shape.Axis);
      falloff *= coneDot >= std::cos(shape.ConeAngle) ? std::pow(coneDot, this->Exponent) : 0.0;
    }
    return falloff;
  }
};
}

// The sun as a directional light from each of its directions, and the
// hours each stands for.
struct vtkLightVisibilitySunStep
{
  vtkRayCastScene::Light Shape;
  double Hours = 0.0;
};
using SunStep = vtkLightVisibilitySunStep;

//------------------------------------------------------------------------------
vtkLightVisibilityFilter::vtkLightVisibilityFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkLightVisibilityFilter::~vtkLightVisibilityFilter() = default;

//------------------------------------------------------------------------------
int vtkLightVisibilityFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightVisibilityFilter::AddCasterConnection(vtkAlgorithmOutput* caster)
{
  this->AddInputConnection(1, caster);
}

void vtkLightVisibilityFilter::AddCasterData(vtkDataObject* caster)
{
  this->AddInputDataInternal(1, caster);
}

void vtkLightVisibilityFilter::RemoveAllCasters()
{
  this->SetInputConnection(1, nullptr);
}

//------------------------------------------------------------------------------
void vtkLightVisibilityFilter::SetLights(vtkLightCollection* lights)
{
  if (this->Lights != lights)
  {
    this->Lights = lights;
    this->Modified();
  }
}

vtkLightCollection* vtkLightVisibilityFilter::GetLights() const
{
  return this->Lights;
}

//------------------------------------------------------------------------------
void vtkLightVisibilityFilter::SetController(vtkMultiProcessController* controller)
{
  if (this->Controller != controller)
  {
    this->Controller = controller;
    this->Modified();
  }
}

vtkMultiProcessController* vtkLightVisibilityFilter::GetController() const
{
  return this->Controller;
}

//------------------------------------------------------------------------------
void vtkLightVisibilityFilter::AddSunDirection(double x, double y, double z, double hours)
{
  this->SunDirections.push_back({ x, y, z, hours });
  this->Modified();
}

void vtkLightVisibilityFilter::RemoveAllSunDirections()
{
  if (!this->SunDirections.empty())
  {
    this->SunDirections.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightVisibilityFilter::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Lights)
  {
    time = std::max(time, this->Lights->GetMTime());
    vtkCollectionSimpleIterator it;
    this->Lights->InitTraversal(it);
    while (vtkLight* light = this->Lights->GetNextLight(it))
    {
      // The light's size lives in its information (vtkShadowLightSize).
      time = std::max({ time, light->GetMTime(), light->GetInformation()->GetMTime() });
    }
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkLightVisibilityFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  std::vector<vtkRayCastScene::Light> lights;
  std::vector<Shading> shading;
  std::vector<SunStep> sun;
  auto check = [&]() -> bool
  {
    if (!surface)
    {
      vtkErrorMacro(<< "no receiver: input 0 must be a vtkPolyData.");
      return false;
    }
    std::vector<vtkLight*> sources;
    if (this->Lights)
    {
      vtkCollectionSimpleIterator it;
      this->Lights->InitTraversal(it);
      while (vtkLight* light = this->Lights->GetNextLight(it))
      {
        sources.push_back(light);
      }
    }
    if (sources.empty() && !this->SunHours)
    {
      vtkErrorMacro(<< "no lights: SetLights() with at least one light, or SunHoursOn().");
      return false;
    }
    lights.resize(sources.size());
    for (size_t l = 0; l < sources.size(); ++l)
    {
      shading.emplace_back(sources[l]);
      std::string error;
      if (!vtkRayCastScene::MakeLight(sources[l], lights[l], error))
      {
        vtkErrorMacro(<< "light " << l << " " << error);
        return false;
      }
    }
    if (this->SunHours && !this->SunSteps(sun))
    {
      return false;
    }
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    {
      double p[3];
      surface->GetPoint(i, p);
      if (!vtkRayCastScene::Castable(glm::dvec3(p[0], p[1], p[2])))
      {
        vtkErrorMacro(<< "receiver point " << i << " (" << p[0] << ", " << p[1] << ", " << p[2]
                      << ") is not finite or lies beyond float range.");
        return false;
      }
    }
    return true;
  };
  bool valid = check();
  // Split among processes, all stop when one refuses its input (rather
  // than wait for it in the exchange below).
  vtkMultiProcessController* controller = this->Controller;
  const bool shared = controller && controller->GetNumberOfProcesses() > 1;
  if (shared)
  {
    const int mine = valid ? 1 : 0;
    int all = 0;
    controller->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
    if (valid && !all)
    {
      vtkErrorMacro(<< "another process refused its input.");
    }
    valid = all != 0;
  }
  if (!valid)
  {
    return 0;
  }

  // The receiver and every caster, opaque; the extent of all of them sets
  // how far off its surface a shadow ray starts (above float rounding of the
  // points, far below any gap a scene means).
  vtkRayCastScene scene;
  const glm::dmat4 world(1.0);
  glm::dvec3 low(std::numeric_limits<double>::infinity());
  glm::dvec3 high = -low;
  auto extend = [&](vtkPolyData* data)
  {
    if (data->GetNumberOfPoints() > 0)
    {
      double b[6];
      data->GetBounds(b);
      low = glm::min(low, glm::dvec3(b[0], b[2], b[4]));
      high = glm::max(high, glm::dvec3(b[1], b[3], b[5]));
    }
  };
  std::vector<vtkPolyData*> casting; // this process's, for the others
  scene.AddPolyData(surface, world, this->ReceiverCasts);
  extend(surface);
  if (this->ReceiverCasts)
  {
    casting.push_back(surface);
  }
  const int casters = this->GetNumberOfInputConnections(1);
  for (int c = 0; c < casters; ++c)
  {
    vtkPolyData* caster = vtkPolyData::GetData(inputVector[1], c);
    if (!caster || caster->GetNumberOfPoints() == 0)
    {
      continue;
    }
    scene.AddPolyData(caster, world, true);
    extend(caster);
    casting.push_back(caster);
  }
  if (shared)
  {
    // Every other process's receiver (when it casts) and casters cast here.
    std::vector<vtkSmartPointer<vtkDataObject>> gathered;
    controller->AllGather(Shapes(casting), gathered);
    const int me = controller->GetLocalProcessId();
    for (size_t p = 0; p < gathered.size(); ++p)
    {
      if (static_cast<int>(p) != me)
      {
        scene.AddPolyData(vtkPolyData::SafeDownCast(gathered[p]), world, true);
      }
    }
    const glm::dvec3 ownLow = low;
    const glm::dvec3 ownHigh = high;
    controller->AllReduce(&ownLow.x, &low.x, 3, vtkCommunicator::MIN_OP);
    controller->AllReduce(&ownHigh.x, &high.x, 3, vtkCommunicator::MAX_OP);
  }
  double extent = glm::length(high - low);
  extent = std::isfinite(extent) && extent > 0.0 ? extent : 1.0;
  const double offset = 1.0e-5 * extent;
  std::string error;
  if (!scene.Commit(error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }

  output->ShallowCopy(surface);
  const int strata = std::max(1, static_cast<int>(std::lround(std::sqrt(this->Samples))));
  const unsigned int seed = this->Seed;
  const int count = static_cast<int>(lights.size());
  const bool sunOn = this->SunHours; // arrays of zeros where the sun never rises
  const bool twoSided = this->TwoSided;
  double daylight = 0.0;
  for (const SunStep& step : sun)
  {
    daylight += step.Hours;
  }

  // Both attributes, each in bands of 16 so that progress is reported from
  // this thread, as VTK's observers expect; each band runs on every core.
  const bool both = this->PointVisibility && this->CellVisibility;
  int band = 0;
  auto compute = [&](const Receiver& receiver, vtkDataSetAttributes* attributes)
  {
    const vtkIdType n = static_cast<vtkIdType>(receiver.Positions.size());
    vtkNew<vtkFloatArray> visibility;
    visibility->SetName("LightVisibility");
    visibility->SetNumberOfComponents(count);
    visibility->SetNumberOfTuples(n);
    vtkNew<vtkFloatArray> irradiance;
    irradiance->SetName("Irradiance");
    irradiance->SetNumberOfTuples(n);
    vtkNew<vtkFloatArray> sunHours;
    sunHours->SetName("SunHours");
    sunHours->SetNumberOfTuples(sunOn ? n : 0);
    vtkNew<vtkFloatArray> sunFraction;
    sunFraction->SetName("SunFraction");
    sunFraction->SetNumberOfTuples(sunOn ? n : 0);
    const int bands = both ? 16 : 32;
    for (int b = 0; b < bands; ++b, ++band)
    {
      vtkSMPTools::For(n * b / bands, n * (b + 1) / bands,
        [&](vtkIdType first, vtkIdType last)
        {
          for (vtkIdType i = first; i < last; ++i)
          {
            const glm::dvec3& at = receiver.Positions[i];
            const glm::dvec3& normal = receiver.Normals[i];
            const glm::dvec2 jitter = vtkRayCastScene::Jitter(PositionKey(at), seed);
            double sum = 0.0;
            for (int l = 0; l < count; ++l)
            {
              const vtkRayCastScene::Sight sight =
                scene.See(lights[l], at, normal, strata, jitter, offset, twoSided);
              visibility->SetTypedComponent(i, l, static_cast<float>(sight.Visible));
              if (shading[l].On)
              {
                const double cosine = normal == glm::dvec3(0.0) ? 1.0 : std::max(sight.Facing, 0.0);
                sum +=
                  sight.Visible * cosine * shading[l].Intensity * shading[l].Falloff(lights[l], at);
              }
            }
            irradiance->SetValue(i, static_cast<float>(sum));
            if (sunOn)
            {
              double hours = 0.0;
              for (const SunStep& step : sun)
              {
                hours += step.Hours *
                  scene.See(step.Shape, at, normal, strata, jitter, offset, twoSided).Visible;
              }
              sunHours->SetValue(i, static_cast<float>(hours));
              sunFraction->SetValue(
                i, daylight > 0.0 ? static_cast<float>(hours / daylight) : 0.0f);
            }
          }
        });
      this->UpdateProgress(static_cast<double>(band + 1) / 32.0);
    }
    if (count > 0)
    {
      attributes->AddArray(visibility);
      attributes->AddArray(irradiance);
    }
    if (sunOn)
    {
      attributes->AddArray(sunHours);
      attributes->AddArray(sunFraction);
    }
  };

  if (!this->PointVisibility && !this->CellVisibility)
  {
    vtkWarningMacro(<< "PointVisibility and CellVisibility are both off: no arrays computed.");
  }
  this->UpdateProgress(0.0);
  if (this->PointVisibility)
  {
    Receiver receiver;
    if (!PointReceivers(surface, receiver))
    {
      vtkErrorMacro(<< "the receiver's point normals could not be computed.");
      return 0;
    }
    compute(receiver, output->GetPointData());
  }
  if (this->CellVisibility)
  {
    Receiver receiver;
    CellReceivers(surface, receiver);
    compute(receiver, output->GetCellData());
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLightVisibilityFilter::SunSteps(std::vector<SunStep>& steps)
{
  // The clamping setters let NaN through.
  if (!std::isfinite(this->SunRadius) || !std::isfinite(this->SunLatitude) ||
    !std::isfinite(this->SunTimeStep))
  {
    vtkErrorMacro(<< "SunRadius (" << this->SunRadius << "), SunLatitude (" << this->SunLatitude
                  << ") and SunTimeStep (" << this->SunTimeStep << ") must be finite.");
    return false;
  }
  vtkRayCastScene::Light shape;
  shape.Directional = true;
  shape.Radius = glm::radians(this->SunRadius);
  if (!this->SunDirections.empty())
  {
    for (const auto& given : this->SunDirections)
    {
      const glm::dvec3 toSun(given[0], given[1], given[2]);
      if (!(glm::length(toSun) > 0.0) || !std::isfinite(glm::length(toSun)) || !(given[3] >= 0.0))
      {
        vtkErrorMacro(<< "sun direction (" << given[0] << ", " << given[1] << ", " << given[2]
                      << ") with " << given[3]
                      << " hours: a direction needs a length and the hours must not be negative.");
        return false;
      }
      shape.ToLight = glm::normalize(toSun);
      steps.push_back({ shape, given[3] });
    }
    return true;
  }
  // The world's east, north and up, north made square to up.
  const glm::dvec3 up = glm::normalize(glm::dvec3(this->SunUp[0], this->SunUp[1], this->SunUp[2]));
  glm::dvec3 north(this->SunNorth[0], this->SunNorth[1], this->SunNorth[2]);
  north -= glm::dot(north, up) * up;
  if (!(glm::length(north) > 1.0e-9 *
          glm::length(glm::dvec3(this->SunNorth[0], this->SunNorth[1], this->SunNorth[2]))) ||
    !std::isfinite(glm::length(north)) || !std::isfinite(glm::length(up)))
  {
    vtkErrorMacro(<< "SunUp (" << this->SunUp[0] << ", " << this->SunUp[1] << ", " << this->SunUp[2]
                  << ") and SunNorth (" << this->SunNorth[0] << ", " << this->SunNorth[1] << ", "
                  << this->SunNorth[2] << ") must be two directions that are not parallel.");
    return false;
  }
  north = glm::normalize(north);
  const glm::dvec3 east = glm::cross(north, up);
  // Each step's direction at its middle.
  const int count = std::max(1, static_cast<int>(std::lround(24.0 / this->SunTimeStep)));
  const double hours = 24.0 / count;
  for (int k = 0; k < count; ++k)
  {
    double enu[3];
    vtkSolarPosition::GetDirection(this->SunLatitude, this->SunDayOfYear, (k + 0.5) * hours, enu);
    if (enu[2] > 0.0)
    {
      shape.ToLight = enu[0] * east + enu[1] * north + enu[2] * up;
      steps.push_back({ shape, hours });
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLightVisibilityFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Lights: " << this->Lights.Get() << "\n";
  os << indent << "Controller: " << this->Controller.Get() << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "PointVisibility: " << this->PointVisibility << "\n";
  os << indent << "CellVisibility: " << this->CellVisibility << "\n";
  os << indent << "ReceiverCasts: " << this->ReceiverCasts << "\n";
  os << indent << "TwoSided: " << this->TwoSided << "\n";
  os << indent << "SunHours: " << this->SunHours << "\n";
  os << indent << "SunLatitude: " << this->SunLatitude << "\n";
  os << indent << "SunDayOfYear: " << this->SunDayOfYear << "\n";
  os << indent << "SunTimeStep: " << this->SunTimeStep << "\n";
  os << indent << "SunUp: " << this->SunUp[0] << ", " << this->SunUp[1] << ", " << this->SunUp[2]
     << "\n";
  os << indent << "SunNorth: " << this->SunNorth[0] << ", " << this->SunNorth[1] << ", "
     << this->SunNorth[2] << "\n";
  os << indent << "SunRadius: " << this->SunRadius << "\n";
  os << indent << "SunDirections: " << this->SunDirections.size() << "\n";
}
