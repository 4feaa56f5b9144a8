/**
 * @class   vtkQuadCoverErrorObserver
 * @brief   collects the errors and warnings of VTK algorithms as plain one-line texts
 *
 * Attach it to the filters of a pipeline (and, through Attach, to their executives) before
 * Update(): instead of being printed by VTK's output window, the first error and every warning
 * are kept, with VTK's "ERROR: In file, line N / vtkClass (0x...):" prefix removed, for a
 * program, a test or a Python script to report as one line:
 * @code
 * vtkNew<vtkQuadCoverErrorObserver> errors;
 * errors->Attach(solver);
 * solver->Update();
 * if (!errors->GetError().empty()) { std::cerr << errors->GetError() << "\n"; }
 * @endcode
 * @sa vtkQuadCoverAlgorithm
 */
#ifndef vtkQuadCoverErrorObserver_h
#define vtkQuadCoverErrorObserver_h

#include "vtkCommand.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

#include <string> // for std::string
#include <vector> // for std::vector

class vtkAlgorithm;

class VTKQUADCOVERFILTERS_EXPORT vtkQuadCoverErrorObserver : public vtkCommand
{
public:
  static vtkQuadCoverErrorObserver* New();
  vtkTypeMacro(vtkQuadCoverErrorObserver, vtkCommand);

  void Execute(vtkObject* caller, unsigned long event, void* callData) override;

  /// Observe the ErrorEvent and WarningEvent of `algorithm` and of its executive.
  void Attach(vtkAlgorithm* algorithm);

  /// The first error's text without VTK's prefix ("" when there was none).
  std::string GetError() const { return this->FirstError; }
  /// The number of warnings so far, and warning i (prefix removed).
  int GetNumberOfWarnings() const { return static_cast<int>(this->Warnings.size()); }
  std::string GetWarning(int i) const;
  /// Forget what was collected.
  void Clear();

  /// Updates `algorithm` with an observer attached; its first error ("" when none).
  static std::string Run(vtkAlgorithm* algorithm);

  /// Strips "ERROR: In <file>, line <n>\n<class> (<address>): " and trailing white space from a
  /// VTK message, and joins its lines.
  static std::string Clean(const char* message);

protected:
  vtkQuadCoverErrorObserver() = default;
  ~vtkQuadCoverErrorObserver() override = default;

private:
  vtkQuadCoverErrorObserver(const vtkQuadCoverErrorObserver&) = delete;
  void operator=(const vtkQuadCoverErrorObserver&) = delete;

  std::string FirstError;
  std::vector<std::string> Warnings;
};

#endif
