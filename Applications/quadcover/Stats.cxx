#include "Stats.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace quadcover_app
{
namespace
{
std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

/// A number in JSON (null when it is not finite); integers without a decimal point.
std::string JsonNumber(double x)
{
  if (!std::isfinite(x))
  {
    return "null";
  }
  char text[40];
  std::snprintf(text, sizeof text, "%.10g", x);
  return text;
}

/// EdgeLengthRSD -> edge_length_rsd.
std::string Snake(const std::string& name)
{
  std::string key;
  for (std::size_t i = 0; i < name.size(); ++i)
  {
    const unsigned char c = name[i];
    const bool boundary = std::isupper(c) && i > 0 &&
      (std::islower(static_cast<unsigned char>(name[i - 1])) ||
        (i + 1 < name.size() && std::islower(static_cast<unsigned char>(name[i + 1]))));
    key += boundary ? "_" : "";
    key += static_cast<char>(std::tolower(c));
  }
  return key;
}

/// A field array's value: a number (one value), a list of values (one component) or a list
/// of tuples. Arrays with a tuple per item (an index) are lists however many there are.
std::string JsonArray(vtkDataArray* a)
{
  namespace names = vtkQuadCoverArrayNames;
  const vtkIdType n = a->GetNumberOfTuples();
  const int comps = a->GetNumberOfComponents();
  const std::string name = a->GetName() ? a->GetName() : "";
  const bool list = name == names::SingularityHistogram;
  if (n == 1 && comps == 1 && !list)
  {
    return JsonNumber(a->GetComponent(0, 0));
  }
  std::string out = "[";
  for (vtkIdType i = 0; i < n; ++i)
  {
    out += i ? ", " : "";
    out += comps > 1 ? "[" : "";
    for (int c = 0; c < comps; ++c)
    {
      out += (c ? ", " : "") + JsonNumber(a->GetComponent(i, c));
    }
    out += comps > 1 ? "]" : "";
  }
  return out + "]";
}

/// The field arrays the stage from `input` to `output` wrote (arrays passed through unchanged
/// are the same objects), as JSON members.
std::string AddedFields(vtkPolyData* output, vtkPolyData* input)
{
  std::string out;
  vtkFieldData* fd = output->GetFieldData();
  for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* a = fd->GetArray(i);
    if (!a || !a->GetName() ||
      (input && input->GetFieldData()->GetAbstractArray(a->GetName()) == a))
    {
      continue;
    }
    out += (out.empty() ? "" : ", ") + JsonString(Snake(a->GetName())) + ": " + JsonArray(a);
  }
  return out;
}
}

std::string StatsJson(const Request& request, vtkPolyData* input, const Pipeline& pipeline,
  int lastStage, const std::vector<Timing>& timings, const std::vector<Option>& options)
{
  std::ostringstream js;
  vtkPolyData* surface = vtkPolyData::SafeDownCast(pipeline.Repair->GetOutputDataObject(0));
  js << "{\n  \"input\": {\"file\": " << JsonString(request.input)
     << ", \"points\": " << input->GetNumberOfPoints()
     << ", \"cells\": " << input->GetNumberOfCells() << "},\n";
  js << "  \"surface\": {\"points\": " << surface->GetNumberOfPoints()
     << ", \"triangles\": " << surface->GetNumberOfPolys() << "},\n";
  js << "  \"stage\": " << JsonString(Pipeline::StageNames()[lastStage]) << ",\n";
  js << "  \"seconds\": {";
  for (std::size_t i = 0; i < timings.size(); ++i)
  {
    js << (i ? ", " : "") << JsonString(timings[i].name) << ": " << JsonNumber(timings[i].seconds);
  }
  js << "},\n  \"options\": {";
  for (std::size_t i = 0; i < options.size(); ++i)
  {
    const Option& o = options[i];
    const double x = o.get();
    const std::string value = std::isnan(x) ? "null"
      : o.kind == Option::Kind::Switch      ? (x != 0.0 ? "true" : "false")
      : o.kind == Option::Kind::Choice      ? JsonString(o.Text(x))
                                            : JsonNumber(x);
    js << (i ? ", " : "") << JsonString(Snake(o.property)) << ": " << value;
  }
  js << "}";
  vtkPolyData* previous = input;
  for (int s = 0; s <= lastStage; ++s)
  {
    vtkPolyData* out = vtkPolyData::SafeDownCast(pipeline.Filter(s)->GetOutputDataObject(0));
    std::string members = AddedFields(out, previous);
    if (Pipeline::StageNames()[s] == "param")
    {
      // the solves' seconds, which the solver keeps out of its output (a list however many)
      std::string seconds;
      for (int i = 0; i < pipeline.Solver->GetNumberOfSolves(); ++i)
      {
        seconds += (i ? ", " : "") + JsonNumber(pipeline.Solver->GetSolveSeconds(i));
      }
      members +=
        (members.empty() ? "" : ", ") + std::string("\"solve_seconds\": [") + seconds + "]";
    }
    if (Pipeline::StageNames()[s] == "quads")
    {
      members = "\"vertices\": " + std::to_string(out->GetNumberOfPoints()) +
        ", \"faces\": " + std::to_string(out->GetNumberOfPolys()) + (members.empty() ? "" : ", ") +
        members;
    }
    js << ",\n  " << JsonString(Pipeline::StageNames()[s]) << ": {" << members << "}";
    previous = out;
  }
  js << "\n}\n";
  return js.str();
}
}
