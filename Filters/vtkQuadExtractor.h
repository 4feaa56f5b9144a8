/**
 * @class   vtkQuadExtractor
 * @brief   the quad mesh of an integer-grid map (QuadCover stage 5), with its quality figures
 *
 * Every unit cell of the grid that the map covers becomes one quad: its centre lies in exactly
 * one triangle, and its four corners are found by walking in the (u, v) plane from there, across
 * edges and seams (through the transition functions read off the map), to the triangles that
 * hold them. Corners found from different cells get one identity, so quads share vertices
 * across seams, and a branch point of index k/4 becomes a vertex of valence 4 - k. Quad vertices
 * lie on the input surface (barycentric in their triangle).
 *
 * Robustness: triangles with a flipped (u, v) image hold no quad centre and stop walks; cells
 * with a corner beyond the boundary or two corners at one grid point are skipped; quads that
 * still overlap (folded maps) are removed so that the output stays manifold. These are counted
 * in DroppedCells (zero on a seamless, flip-free map); a cell whose centre lies only in flipped
 * triangles is not found at all, so it is not counted (the solver's FlippedTriangles tells).
 *
 * Input: a triangle surface with the cell array CornerUV (6 components, SetInputArrayToProcess(0,
 * ...)), as vtkQuadCoverSolver writes it; also its SplitSeams output (points are merged back
 * through SurfacePointId).
 *
 * Output: vtkQuad cells; point data Valence; cell data ScaledJacobian (the smallest over the
 * quad's corners); field data with the figures of the paper's Table 1 and more: QuadShare,
 * IrregularVertices (inner, boundary), EdgeLengthRSD, AngleRSD, ScaledJacobianStatistics (min,
 * mean), NonManifoldEdges, EulerCharacteristic, BoundaryLoops, HausdorffDistance (two-sided, and
 * each way, in % of the input's bounding-box diagonal), InvertedQuads (before and after
 * RepairInvertedQuads), DroppedCells, FilledHoles, TurnedQuads (before and after it) and
 * SplitQuadVertices (copies of a vertex where separate fans of quads touched: the output is
 * manifold at its vertices), FragmentQuads (quads removed that hung off their component's
 * quads by a corner, or lay against them as a disk cut off), SnappedVertices (quad vertices moved
 * onto creases, or beside one where a quad lay folded across it; SnapToCreases), LiftedVertices
 * (quad vertices lifted off the input where a quad's centre lay nearer another component's surface
 * than its own), RemovedTurnedQuads (quads facing against the input or inside out that were cut off
 * as ears or collapsed along a diagonal; RepairInvertedQuads) and EmptyComponents (components of
 * the input on which no quad lies, with a warning; 0 on a valid remesh).
 * @sa vtkQuadCoverSolver
 */
#ifndef vtkQuadExtractor_h
#define vtkQuadExtractor_h

#include "vtkQuadCoverAlgorithm.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

class vtkAlgorithmOutput;
class vtkPolyData;

class VTKQUADCOVERFILTERS_EXPORT vtkQuadExtractor : public vtkQuadCoverAlgorithm
{
public:
  static vtkQuadExtractor* New();
  vtkTypeMacro(vtkQuadExtractor, vtkQuadCoverAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** An optional second input (port 1), the surface the quads are put onto: each quad vertex
   * moves to its closest point on it, and the Hausdorff distance is measured against it. For a
   * surface that vtkQuadCoverSurfaceRepair simplified (MaximumTriangleCount), connect the
   * surface as it was before; the quads then lie on it, not on the simplified one. Any
   * polygons (triangulated here); none connected (the default): the quads stay on the input. */
  void SetSourceConnection(vtkAlgorithmOutput* source);
  void SetSourceData(vtkPolyData* source);
  ///@}

  ///@{
  /** Compute the two-sided Hausdorff distance to the input (default on; it costs about as much
   * as the extraction). */
  vtkSetMacro(ComputeHausdorffDistance, bool);
  vtkGetMacro(ComputeHausdorffDistance, bool);
  vtkBooleanMacro(ComputeHausdorffDistance, bool);
  ///@}

  ///@{
  /** Relax the quads around any quad with a corner turned inside out (scaled Jacobian <= 0),
   * which the map leaves at some branch points on coarse or strongly curved parts, or facing
   * against the input (default on): their vertices and those within two quad rings, as
   * RelaxationIterations does, until none is left or a round repairs nothing. Then the corners of
   * those left (a quad across a sharp crease, or wrapped around a part thinner than itself), and
   * of the quads around them, are moved one at a time to the point of the input nearby that makes
   * the worst of their quads best (quadcover::repairFacing). Quads still inside out then get a
   * last round in which their vertices also try short steps around them, kept when fewer stay
   * inside out and none more faces against the input. Far from them nothing moves. A quad that
   * no move mends is removed at the end by a change of the connectivity that keeps the output
   * all quads, manifold, of the same Euler characteristic and boundary loops: an ear (three edges
   * on the boundary) is cut off, another quad collapsed along a diagonal where that leaves its
   * neighbours facing right (quadcover::removeTurnedQuads; also after the quads are put onto the
   * source). InvertedQuads and TurnedQuads report how many there were and are,
   * RemovedTurnedQuads how many were removed so. */
  vtkSetMacro(RepairInvertedQuads, bool);
  vtkGetMacro(RepairInvertedQuads, bool);
  vtkBooleanMacro(RepairInvertedQuads, bool);
  ///@}

  ///@{
  /** Fill the holes that grid cells without a quad leave inside the surface with quads (default
   * on): a loop of four edges with one quad, a longer even loop (up to sqrt(quads) + 64 edges)
   * with a fan of quads around a new point on the surface (quadcover::patchQuadMesh), so the
   * output keeps the input's Euler characteristic where the map could not be repaired. The
   * holes are filled before RepairInvertedQuads, which then repairs their quads with the others.
   * FilledHoles reports what it did. */
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);
  ///@}

  ///@{
  /** Move the quad vertices beside the input's sharp edges onto them before the relaxation
   * (default on; quadcover::snapToCreases), so that quad edges follow the creases: where a quad
   * edge crosses a sharp edge, its end nearer the crease moves to the closest point of it. The
   * frames are held along the sharp edges, so the map's grid lines run beside them and the ends
   * moved form rows of quad edges on the creases; the quads beside a crease grow or shrink by the
   * grid line's distance from it (at most half a quad). Where a grid line crosses a crease, a
   * quad lying folded along its diagonal across it gets a third corner moved beside the crease
   * (quadcover::straightenCreaseSteps), so that two of its edges follow it. A move that turns a
   * quad against the input or leaves it a corner's scaled Jacobian below 0.05 is undone.
   * SnappedVertices counts the vertices moved. Sharp: as vtkFrameSmoother's, FeatureAngle and
   * MinimumFeatureLength. */
  vtkSetMacro(SnapToCreases, bool);
  vtkGetMacro(SnapToCreases, bool);
  vtkBooleanMacro(SnapToCreases, bool);
  ///@}

  ///@{
  /** Sharp edges for SnapToCreases: the normals more than this many degrees apart, in [0, 180]
   * (default 60), whose sides are smooth; the same as vtkFrameSmoother's FeatureAngle. */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /** Sharp edges count for SnapToCreases only in chains of at least this many, in [1, 10000]
   * (default 3); the same as vtkFrameSmoother's MinimumFeatureLength. */
  vtkSetClampMacro(MinimumFeatureLength, int, 1, 10000);
  vtkGetMacro(MinimumFeatureLength, int);
  ///@}

  ///@{
  /** Sweeps of tangential relaxation after extraction, in [0, 1000] (default 3; 0: the quads as
   * the map cuts them). Each free vertex moves halfway towards the area-weighted mean of its
   * quads' centres, in the input's tangent plane, and back onto the input surface; vertices on
   * the boundary or on input creases (dihedral angle above 60 degrees) stay, and so do those
   * whose quads span a bend that sharp (moved, they would pull the quads' chords across it: the
   * rim of a thin ear), and no move turns a quad corner inside out. It evens out uneven spacing
   * (a jittered mesh returns to about its original figures) but it cannot change how many quads
   * a region has, which is where most of a map's distortion shows: on the shared meshes three
   * sweeps lower the edge-length RSD by 0.3-0.9 points and the angle RSD by 0.2-0.7 points, and
   * the grid lines follow the frame field a little less exactly (Documentation/Algorithms.md,
   * "How the quads are cut out"). */
  vtkSetClampMacro(RelaxationIterations, int, 0, 1000);
  vtkGetMacro(RelaxationIterations, int);
  ///@}

protected:
  vtkQuadExtractor();
  ~vtkQuadExtractor() override = default;

  void Execute(vtkQuadCoverSurface& input, vtkInformationVector* outputVector) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // defaults: quadcover::QuadMeshOptions
  bool ComputeHausdorffDistance;
  int RelaxationIterations;
  bool RepairInvertedQuads;
  bool FillHoles;
  bool SnapToCreases;
  double FeatureAngle;
  int MinimumFeatureLength;

private:
  vtkQuadExtractor(const vtkQuadExtractor&) = delete;
  void operator=(const vtkQuadExtractor&) = delete;
};

#endif
