#include "VtpFiles.h"

#include <vtkDataArray.h>
#include <vtkObjectFactory.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cstring>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>

namespace softshadows
{
namespace
{
constexpr double MaximumExpansion = 8192;
constexpr long long Most = std::numeric_limits<long long>::max();

class CheckedPolyDataReader : public vtkXMLPolyDataReader
{
public:
  static CheckedPolyDataReader* New();
  vtkTypeMacro(CheckedPolyDataReader, vtkXMLPolyDataReader);

protected:
  CheckedPolyDataReader() = default;

  // The claims are checked between reading the XML structure and reading
  // the data, which is where the reader allocates for them.
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override
  {
    this->FileBytes = 0;
    std::error_code error;
    const auto bytes = std::filesystem::file_size(this->GetFileName(), error);
    if (!error)
    {
      this->FileBytes = static_cast<double>(bytes);
    }
    vtkXMLDataElement* root = this->XMLParser ? this->XMLParser->GetRootElement() : nullptr;
    if (root && !error)
    {
      const char* compressor = root->GetAttribute("compressor");
      this->Expansion = compressor && *compressor ? MaximumExpansion : 1;
      const std::string problem = this->FindClaimProblem(root);
      if (!problem.empty())
      {
        vtkErrorMacro(<< problem);
        return 0;
      }
    }
    return this->Superclass::RequestData(request, inputs, outputs);
  }

  // The connectivity the reader allocates next has as many values as the
  // last offset says.
  int ReadArrayValues(vtkXMLDataElement* element, vtkIdType arrayIndex, vtkAbstractArray* array,
    vtkIdType startIndex, vtkIdType numValues, FieldType type) override
  {
    if (!this->Superclass::ReadArrayValues(element, arrayIndex, array, startIndex, numValues, type))
    {
      return 0;
    }
    const char* name = element->GetAttribute("Name");
    auto* offsets = vtkDataArray::SafeDownCast(array);
    if (name && std::strcmp(name, "offsets") == 0 && offsets && numValues > 0 &&
      arrayIndex + numValues <= offsets->GetNumberOfValues())
    {
      const double last = offsets->GetComponent(arrayIndex + numValues - 1, 0);
      if (last > this->FileBytes * this->Expansion)
      {
        std::ostringstream problem;
        problem << "its last cell offset, " << std::fixed << std::setprecision(0) << last
                << ", asks for more connectivity than its " << this->FileBytes << " bytes can hold";
        vtkErrorMacro(<< problem.str());
        return 0;
      }
    }
    return 1;
  }

private:
  // The least number of file bytes the DataArray `array` needs for `tuples`
  // tuples; 0 for what is not a DataArray the reader knows.
  double NeedBytes(vtkXMLDataElement* array, double tuples) const
  {
    int dataType = 0;
    if (std::strcmp(array->GetName(), "DataArray") != 0 ||
      !array->GetWordTypeAttribute("type", dataType))
    {
      return 0;
    }
    int components = 1;
    array->GetScalarAttribute("NumberOfComponents", components);
    const double values = tuples * std::max(components, 1);
    const char* format = array->GetAttribute("format");
    if (format && std::strcmp(format, "ascii") == 0)
    {
      return values;
    }
    const double size =
      dataType == VTK_BIT ? 0.125 : std::max(vtkAbstractArray::GetDataTypeSize(dataType), 1);
    return values * size / this->Expansion;
  }

  // The same for the arrays nested in `element`, only those named `name`
  // when one is given.
  double NeedBytesOfAll(vtkXMLDataElement* element, double tuples, const char* name = nullptr) const
  {
    double need = 0;
    for (int i = 0; element && i < element->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* array = element->GetNestedElement(i);
      const char* arrayName = array->GetAttribute("Name");
      if (!name || (arrayName && std::strcmp(arrayName, name) == 0))
      {
        need += this->NeedBytes(array, tuples);
      }
    }
    return need;
  }

  std::string FindClaimProblem(vtkXMLDataElement* root) const
  {
    vtkXMLDataElement* polyData = root->FindNestedElementWithName("PolyData");
    if (!polyData)
    {
      return {};
    }
    long long points = 0;
    long long cells = 0;
    double need = 0;
    for (int i = 0; i < polyData->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* element = polyData->GetNestedElement(i);
      if (std::strcmp(element->GetName(), "FieldData") == 0)
      {
        for (int a = 0; a < element->GetNumberOfNestedElements(); ++a)
        {
          vtkXMLDataElement* array = element->GetNestedElement(a);
          long long tuples = 0;
          array->GetScalarAttribute("NumberOfTuples", tuples);
          need += this->NeedBytes(array, static_cast<double>(std::max(tuples, 0LL)));
        }
        continue;
      }
      if (std::strcmp(element->GetName(), "Piece") != 0)
      {
        continue;
      }
      long long piecePoints = 0;
      element->GetScalarAttribute("NumberOfPoints", piecePoints);
      piecePoints = std::max(piecePoints, 0LL);
      points += std::min(piecePoints, Most - points);
      need += this->NeedBytesOfAll(element->FindNestedElementWithName("Points"), piecePoints);
      need += this->NeedBytesOfAll(element->FindNestedElementWithName("PointData"), piecePoints);
      long long pieceCells = 0;
      for (const char* kind : { "Verts", "Lines", "Strips", "Polys" })
      {
        long long count = 0;
        element->GetScalarAttribute((std::string("NumberOf") + kind).c_str(), count);
        count = std::max(count, 0LL);
        pieceCells += std::min(count, Most - pieceCells);
        need += this->NeedBytesOfAll(element->FindNestedElementWithName(kind), count, "offsets");
      }
      cells += std::min(pieceCells, Most - cells);
      need += this->NeedBytesOfAll(element->FindNestedElementWithName("CellData"), pieceCells);
    }
    if (need <= this->FileBytes)
    {
      return {};
    }
    std::ostringstream problem;
    problem << "it claims " << points << " points and " << cells
            << " cells, whose arrays need more than its " << this->FileBytes << " bytes";
    return problem.str();
  }

  double FileBytes = 0;
  double Expansion = 1;
};
vtkStandardNewMacro(CheckedPolyDataReader);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkAlgorithm> MakeVtpReader(const std::filesystem::path& file)
{
  auto reader = vtkSmartPointer<CheckedPolyDataReader>::New();
  reader->SetFileName(file.string().c_str());
  return reader;
}
}
