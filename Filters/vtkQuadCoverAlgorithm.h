/**
 * @class   vtkQuadCoverAlgorithm
 * @brief   what every QuadCover stage shares: input checks, errors, warnings and progress
 *
 * The base of vtkQuadCoverSurfaceRepair, vtkCurvatureFrames, vtkFrameSmoother,
 * vtkMatchingBuilder, vtkQuadCoverSolver and vtkQuadExtractor. RequestData checks the input
 * (point ids in range, finite coordinates; for the five stages also polygons and strips
 * triangulated, triangles that repeat a point dropped with a warning, and the connectivity the
 * stage needs), then runs the stage. Any failure becomes one error, "Cannot <what the stage
 * does>: <reason>.", through vtkErrorMacro, and RequestData returns 0. The long computations
 * (smoothing, the branch-point search, the map, the quads) report progress (ProgressEvent) from
 * inside and stop soon after AbortExecute is set (within a sparse factorization's time: several
 * seconds on a million triangles); the outputs are then left empty and no error is raised, so a
 * stage downstream of an aborted one reports an input without points. The repair and the
 * curvature estimate, linear and quick, only report their steps.
 *
 * A surface of a size out of the ordinary (the largest side of its bounding box outside
 * [2^-16, 2^16], e.g. a sphere of radius 1e-160 or 1e150) is computed on scaled by a power of two
 * to about unit size (that side in [1, 2)), where lengths, areas and curvatures stay well inside
 * double's range: the scaling is exact, and whatever has units (points, lengths, areas,
 * curvatures, and TargetEdgeLength) is converted back, so the outputs are in the input's units
 * and the input's own points pass through untouched.
 *
 * Subclasses implement Execute and name their action; they throw std::exception (a one-line
 * what(), without a final period) for anything wrong with their input.
 * @sa vtkQuadCoverErrorObserver
 */
#ifndef vtkQuadCoverAlgorithm_h
#define vtkQuadCoverAlgorithm_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

#include <string> // for std::string

struct vtkQuadCoverSurface;

class VTKQUADCOVERFILTERS_EXPORT vtkQuadCoverAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkQuadCoverAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What the input must be before Execute sees it.
  enum InputRequirement
  {
    /// points and cells as they are (ids in range, coordinates finite)
    ANY_POLYDATA,
    /// triangles only (polygons triangulated), at most two per edge, consistently oriented
    MANIFOLD_EDGES,
    /// and every point's triangles one fan (ordered one-rings)
    MANIFOLD_SURFACE
  };

protected:
  /// `requirement`: what the stage needs of its input (checked before Execute); `action`: what
  /// it does, for its errors ("smooth frames": "Cannot smooth frames: ...").
  vtkQuadCoverAlgorithm(InputRequirement requirement, const char* action);
  ~vtkQuadCoverAlgorithm() override = default;
  /// The stage's work on the checked input. Throws std::exception for a bad input.
  virtual void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) = 0;

  /// The cell array the stage reads as input array `index` (SetInputArrayToProcess), checked to
  /// have `components` components and one tuple per cell; otherwise throws "the input has no
  /// N-component cell array NAME (HINT)".
  vtkDataArray* RequireCellArray(
    int index, vtkPolyData* surface, int components, const char* name, const char* hint);

  /// One warning (vtkWarningMacro), a period added.
  void Warn(const std::string& text);

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The whole surface on every rank of a distributed pipeline, remeshed on the rank of piece 0
  /// (vtkQuadCoverPieces.h).
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkQuadCoverAlgorithm(const vtkQuadCoverAlgorithm&) = delete;
  void operator=(const vtkQuadCoverAlgorithm&) = delete;

  InputRequirement Requirement;
  const char* Action;
  /// This rank's piece is not piece 0 of a whole surface: its outputs stay empty.
  bool EmptyPiece = false;
};

#endif
