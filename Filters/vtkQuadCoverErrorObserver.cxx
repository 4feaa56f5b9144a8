#include "vtkQuadCoverErrorObserver.h"

#include "vtkAlgorithm.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cctype>

vtkStandardNewMacro(vtkQuadCoverErrorObserver);

//------------------------------------------------------------------------------
void vtkQuadCoverErrorObserver::Execute(vtkObject*, unsigned long event, void* callData)
{
  const std::string text = Clean(static_cast<const char*>(callData));
  if (event == vtkCommand::ErrorEvent && this->FirstError.empty())
  {
    this->FirstError = text.empty() ? "unknown error" : text;
  }
  else if (event == vtkCommand::WarningEvent)
  {
    this->Warnings.push_back(text);
  }
}

//------------------------------------------------------------------------------
void vtkQuadCoverErrorObserver::Attach(vtkAlgorithm* algorithm)
{
  for (vtkObject* o :
    { static_cast<vtkObject*>(algorithm), static_cast<vtkObject*>(algorithm->GetExecutive()) })
  {
    o->AddObserver(vtkCommand::ErrorEvent, this);
    o->AddObserver(vtkCommand::WarningEvent, this);
  }
}

//------------------------------------------------------------------------------
std::string vtkQuadCoverErrorObserver::GetWarning(int i) const
{
  return i >= 0 && i < this->GetNumberOfWarnings() ? this->Warnings[i] : std::string();
}

//------------------------------------------------------------------------------
void vtkQuadCoverErrorObserver::Clear()
{
  this->FirstError.clear();
  this->Warnings.clear();
}

//------------------------------------------------------------------------------
std::string vtkQuadCoverErrorObserver::Run(vtkAlgorithm* algorithm)
{
  vtkNew<vtkQuadCoverErrorObserver> errors;
  errors->Attach(algorithm);
  algorithm->Update();
  return errors->GetError();
}

//------------------------------------------------------------------------------
std::string vtkQuadCoverErrorObserver::Clean(const char* message)
{
  std::string s = message ? message : "";
  // VTK formats "ERROR: In <file>, line <n>\n<class> (<address>): <text>\n\n".
  const auto header = s.find("line ");
  if (header != std::string::npos)
  {
    const auto newline = s.find('\n', header);
    if (newline != std::string::npos)
    {
      s = s.substr(newline + 1);
      const auto colon = s.find("): ");
      if (colon != std::string::npos && colon < 80)
      {
        s = s.substr(colon + 3);
      }
    }
  }
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
  {
    s.pop_back();
  }
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}
