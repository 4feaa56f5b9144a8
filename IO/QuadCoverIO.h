// QuadCoverIO.h: reading, repairing and writing surfaces for the command line, the tests and
// the benchmarks. Everything a stage needs checked is checked by the filters themselves; this
// only reads by extension and applies the documented repairs.
#ifndef QuadCoverIO_h
#define QuadCoverIO_h

#include "vtkCommand.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkAlgorithm;

namespace QuadCoverIO
{
/**
 * Collects the errors and warnings of the algorithms it is attached to (and their executives)
 * instead of letting VTK print them, so that a program can report one clean line.
 */
class ErrorObserver : public vtkCommand
{
public:
  static ErrorObserver* New() { return new ErrorObserver; }
  void Execute(vtkObject*, unsigned long event, void* callData) override;
  /// Observe ErrorEvent and WarningEvent of `algorithm` and of its executive.
  void Attach(vtkAlgorithm* algorithm);
  /// The first error's text without VTK's file/line/class prefix ("" when none).
  const std::string& Error() const { return this->FirstError; }
  /// The warnings so far, one per entry, prefix removed.
  const std::vector<std::string>& Warnings() const { return this->WarningList; }

  /// Strips "ERROR: In file, line N\nvtkClass (0x...): " and trailing blanks from a message.
  static std::string Clean(const char* message);

private:
  std::string FirstError;
  std::vector<std::string> WarningList;
};

/// What PrepareSurface changed.
struct Repairs
{
  long long mergedPoints = 0;         ///< duplicate points merged into one
  long long removedCells = 0;         ///< degenerate or non-surface cells removed
  long long triangulatedPolygons = 0; ///< polygons with more than three sides, and strips
  long long flippedTriangles = 0;     ///< triangles reoriented to agree with their neighbours
  long long splitVertices = 0;        ///< copies added where fans touched at one vertex
};

/// True when `path` ends in an extension ReadSurface understands (.obj .ply .stl .vtp .vtk).
bool CanRead(const std::string& path);
/// True when `path` ends in an extension WriteSurface understands (.vtp .vtk .obj .ply).
bool CanWrite(const std::string& path);

/// Reads a surface by extension. Returns null and sets `error` to one line on failure
/// (missing or unreadable file, unknown extension, reader error, not a surface).
vtkSmartPointer<vtkPolyData> ReadSurface(const std::string& path, std::string& error);

/**
 * The command line's documented repairs: merge exactly coincident points (vtkCleanPolyData,
 * which also drops unused points and degenerate cells), drop vertex and line cells, triangulate
 * polygons and strips, orient the triangles consistently (vtkPolyDataNormals, Consistency),
 * and give each fan of triangles at a non-manifold vertex its own copy of the vertex.
 * Refuses (null, `error` set): no points, non-finite coordinates, no polygons, non-manifold
 * edges.
 */
vtkSmartPointer<vtkPolyData> PrepareSurface(
  vtkPolyData* input, Repairs& repairs, std::string& error);

/// Writes by extension; returns false and sets `error` on failure.
bool WriteSurface(vtkPolyData* surface, const std::string& path, std::string& error);
}

#endif
