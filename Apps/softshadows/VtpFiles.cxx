// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
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
    this->Checked = false;
    std::error_code error;
    const auto bytes = std::filesystem::file_size(this->GetFileName(), error);
    vtkXMLDataElement* root = this->XMLParser ? this->XMLParser->GetRootElement() : nullptr;
    if (root && !error)
    {
      this->Checked = true;
      this->FileBytes = static_cast<double>(bytes);
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
    vtkXMLDataElement* cells = element->GetParent();
    const char* name = element->GetAttribute("Name");
    auto* offsets = vtkDataArray::SafeDownCast(array);
    if (this->Checked && cells && IsCellArray(cells->GetName()) && name &&
      std::strcmp(name, "offsets") == 0 && offsets && numValues > 0 &&
      arrayIndex + numValues <= offsets->GetNumberOfValues())
    {
      const double last = offsets->GetComponent(arrayIndex + numValues - 1, 0);
      vtkXMLDataElement* connectivity = nullptr;
      for (int i = 0; i < cells->GetNumberOfNestedElements(); ++i)
      {
        const char* other = cells->GetNestedElement(i)->GetAttribute("Name");
        if (other && std::strcmp(other, "connectivity") == 0)
        {
          connectivity = cells->GetNestedElement(i);
        }
      }
      if (connectivity && this->NeedBytes(connectivity, last) > this->FileBytes)
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
  static bool IsCellArray(const char* name)
  {
    for (const char* kind : { "Verts", "Lines", "Strips", "Polys" })
    {
      if (std::strcmp(name, kind) == 0)
      {
        return true;
      }
    }
    return false;
  }

  // The least number of file bytes the array element `array` (any element
  // with a type, as the reader takes it) needs for `tuples` tuples.
  double NeedBytes(vtkXMLDataElement* array, double tuples) const
  {
    int dataType = 0;
    if (!array->GetWordTypeAttribute("type", dataType))
    {
      return 0;
    }
    int components = 1;
    array->GetScalarAttribute("NumberOfComponents", components);
    const double values = tuples * std::max(components, 1);
    // Bits are packed in every format; the reader takes ASCII when no format is given.
    const double bits = dataType == VTK_BIT ? 0.125 : 1;
    const char* format = array->GetAttribute("format");
    if (!format || std::strcmp(format, "ascii") == 0)
    {
      return values * bits;
    }
    const double size =
      dataType == VTK_BIT ? bits : std::max(vtkAbstractArray::GetDataTypeSize(dataType), 1);
    return values * size / this->Expansion;
  }

  // The same for the arrays of `element`: all of them, its first only
  // (Points), or those named `name` (a cell array's offsets).
  double NeedBytesOfAll(
    vtkXMLDataElement* element, double tuples, bool first = false, const char* name = nullptr) const
  {
    double need = 0;
    for (int i = 0; element && i < element->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* array = element->GetNestedElement(i);
      const char* arrayName = array->GetAttribute("Name");
      if (!name || (arrayName && std::strcmp(arrayName, name) == 0))
      {
        need += this->NeedBytes(array, tuples);
        if (first)
        {
          break;
        }
      }
    }
    return need;
  }

  // Each piece's arrays must be in the file; and the output's, which the
  // reader sizes from the first piece's arrays for the points and cells of
  // all pieces, could be only if every piece's were like the first's.
  std::string FindClaimProblem(vtkXMLDataElement* root) const
  {
    vtkXMLDataElement* polyData = root->FindNestedElementWithName("PolyData");
    if (!polyData)
    {
      return {};
    }
    double points = 0;
    double cells = 0;
    double need = 0;
    vtkXMLDataElement* first = nullptr;
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
          if (tuples < 0)
          {
            return "its field data claims a negative number of tuples";
          }
          need += this->NeedBytes(array, static_cast<double>(tuples));
        }
        continue;
      }
      if (std::strcmp(element->GetName(), "Piece") != 0)
      {
        continue;
      }
      first = first ? first : element;
      long long piecePoints = 0;
      element->GetScalarAttribute("NumberOfPoints", piecePoints);
      if (piecePoints < 0)
      {
        return "a piece claims a negative number of points";
      }
      points += static_cast<double>(piecePoints);
      need += this->NeedBytesOfAll(element->FindNestedElementWithName("Points"), piecePoints, true);
      need += this->NeedBytesOfAll(element->FindNestedElementWithName("PointData"), piecePoints);
      double pieceCells = 0;
      for (const char* kind : { "Verts", "Lines", "Strips", "Polys" })
      {
        long long count = 0;
        element->GetScalarAttribute((std::string("NumberOf") + kind).c_str(), count);
        if (count < 0)
        {
          return std::string("a piece claims a negative number of ") + kind;
        }
        pieceCells += static_cast<double>(count);
        need += this->NeedBytesOfAll(
          element->FindNestedElementWithName(kind), static_cast<double>(count), false, "offsets");
      }
      cells += pieceCells;
      need += this->NeedBytesOfAll(element->FindNestedElementWithName("CellData"), pieceCells);
    }
    double output = 0;
    if (first)
    {
      output += this->NeedBytesOfAll(first->FindNestedElementWithName("Points"), points, true);
      output += this->NeedBytesOfAll(first->FindNestedElementWithName("PointData"), points);
      output += this->NeedBytesOfAll(first->FindNestedElementWithName("CellData"), cells);
    }
    if (std::max(need, output) <= this->FileBytes)
    {
      return {};
    }
    std::ostringstream problem;
    problem << std::fixed << std::setprecision(0) << "it claims " << points << " points and "
            << cells << " cells, whose arrays need more than its " << this->FileBytes << " bytes";
    return problem.str();
  }

  bool Checked = false;
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
