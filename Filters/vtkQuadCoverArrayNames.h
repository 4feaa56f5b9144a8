/**
 * @file   vtkQuadCoverArrayNames.h
 * @brief  The names of every array passed down the QuadCover pipeline: the public contract.
 *
 * Each stage reads the arrays the previous stage wrote and adds its own. The table in
 * Documentation/Arrays.md lists, for every name here, its association, components, type, the
 * filter that writes it and the filters that read it (a test checks that the two agree). The
 * command line's --stats JSON names each field-data array in snake_case (EdgeLength:
 * "edge_length"). Change a name here and there, never elsewhere.
 */
#ifndef vtkQuadCoverArrayNames_h
#define vtkQuadCoverArrayNames_h

namespace vtkQuadCoverArrayNames
{
// ---- vtkQuadCoverSurfaceRepair (field data, 1 x int each: what the repair changed) ----
/// duplicate points merged into one (coincident to round-off: 1e-12 of the bounding-box diagonal)
constexpr const char* MergedPoints = "MergedPoints";
/// vertex and line cells, and triangles left with a repeated point, removed
constexpr const char* RemovedCells = "RemovedCells";
/// polygons with more than three sides, and strips, triangulated
constexpr const char* TriangulatedPolygons = "TriangulatedPolygons";
/// triangles turned over to agree with their neighbours
constexpr const char* ReorientedTriangles = "ReorientedTriangles";
/// boundary points that lay on another boundary edge (T-junctions) put into that edge
constexpr const char* ClosedTJunctions = "ClosedTJunctions";
/// edges of more than two triangles cut apart into manifold sheets
constexpr const char* CutEdges = "CutEdges";
/// copies of a point added where separate fans of triangles touched at it
constexpr const char* SplitVertices = "SplitVertices";
/// edges flipped to remove degenerate triangles whose corner lay on the opposite edge (caps)
constexpr const char* FlippedEdges = "FlippedEdges";
/// triangles of components too coarse for a map (MinimumComponentTriangleCount), split into four
/// at their edges' midpoints, again until the component had enough
constexpr const char* RefinedTriangles = "RefinedTriangles";
/// edges collapsed (points removed) to bring a surface finer than the quads need down to
/// MaximumTriangleCount triangles
constexpr const char* CollapsedEdges = "CollapsedEdges";
/// points of rough components (noise at the triangle scale) moved by smoothing
/// (SmoothRoughSurfaces)
constexpr const char* SmoothedPoints = "SmoothedPoints";

// ---- vtkCurvatureFrames (cell data, one tuple per triangle) ----
/// 2 x double: kappa1 >= kappa2. Positive where the surface bends away from its normal
/// (a sphere with outward normals has +1/R).
constexpr const char* PrincipalCurvatures = "PrincipalCurvatures";
/// 3 x double: unit vector in the triangle's plane, direction of kappa1.
constexpr const char* PrincipalDirection1 = "PrincipalDirection1";
/// 3 x double: unit vector in the triangle's plane, direction of kappa2.
constexpr const char* PrincipalDirection2 = "PrincipalDirection2";
/// 3 x double: first guidance frame vector (along kappa2 for curvature frames).
constexpr const char* FrameU = "FrameU";
/// 3 x double: second guidance frame vector (n x FrameU for curvature frames).
constexpr const char* FrameV = "FrameV";
/// 1 x double: omega = |k1 - k2| / sqrt(k1^2 + k2^2) in [0, sqrt(2)], 0 where both vanish.
constexpr const char* FrameWeight = "FrameWeight";

// ---- field data written by vtkCurvatureFrames ----
/// 1 x double: the neighbourhood radius used, in world units.
constexpr const char* CurvatureRadius = "CurvatureRadius";

// ---- vtkFrameSmoother (rewrites FrameU and FrameV, adds these) ----
/// cell, 1 x double: the angle (radians) each frame was turned about its normal.
constexpr const char* FrameRotation = "FrameRotation";
/// cell, 1 x double: how far the input frames agree with those around them (CoherenceRadius),
/// in [0, 1]; FrameWeight is multiplied by its 8th power.
constexpr const char* FrameCoherence = "FrameCoherence";
/// cell, 1 x unsigned char: 1 where the frame is held along a boundary or sharp edge.
constexpr const char* FrameConstrained = "FrameConstrained";
/// field, 1 x double, 2 tuples: the energy at the start of the descent (held frames already on
/// their edges) and at its end.
constexpr const char* SmoothingEnergy = "SmoothingEnergy";
/// field, 1 x int: iterations of the chosen run.
constexpr const char* SmoothingIterations = "SmoothingIterations";
/// field, 1 x int: triangles whose frame is held (FrameConstrained).
constexpr const char* ConstrainedFrameCount = "ConstrainedFrameCount";

// ---- vtkMatchingBuilder ----
/// cell, 3 x int: for edge k = (point k, point k+1) of the triangle, the matching r in {0..3} to
/// the triangle across it, X_{neighbour,m} = X_{this,(m - r) mod 4} (QuadCover Def. 5), with
/// X_0 = FrameU, X_1 = n x FrameU, X_2 = -FrameU, X_3 = -n x FrameU; -1 on boundary edges.
constexpr const char* Matching = "Matching";
/// point, 1 x int: layer shift (Def. 4) in {0..3}; 0 on the boundary. The solver's output has its
/// map's: from the Matching it read, 0 at the points of the pairs it cancelled
/// (CancelledSingularityPairs).
constexpr const char* LayerShift = "LayerShift";
/// point, 1 x double: the frame field's index at the point (a multiple of 1/4 inside); the
/// solver's output, its map's, as LayerShift.
constexpr const char* SingularityIndex = "SingularityIndex";
/// field, 1 x int: inner points with a non-zero index.
constexpr const char* SingularityCount = "SingularityCount";
/// field, 2 x double per tuple (index, number of inner points with it), one tuple per non-zero
/// index, ascending.
constexpr const char* SingularityHistogram = "SingularityHistogram";
/// field, 1 x double: the sum of every point's SingularityIndex, inner and boundary: the Euler
/// characteristic (Poincare-Hopf).
constexpr const char* SingularityIndexSum = "SingularityIndexSum";
/// field, 1 x int, 2 tuples: branch points (non-zero layer shift) before and after the
/// optimization.
constexpr const char* BranchPointCount = "BranchPointCount";
/// field, 1 x double, 2 tuples: sum over inner edges of the matched frames' angle (C_ij), before
/// and after the optimization.
constexpr const char* MatchingCost = "MatchingCost";
/// field, 1 x double, 2 tuples: what the branch-point optimization lowers, BranchPointWeight *
/// singular points + the matching cost with each edge scaled by its length (LengthScaledCost),
/// before and after.
constexpr const char* BranchPointObjective = "BranchPointObjective";
/// point data of the branch-point output (and of vtkQuadCoverSolver's SplitSeams output): the
/// point's id in the surface.
constexpr const char* SurfacePointId = "SurfacePointId";

// ---- vtkQuadCoverSolver ----
/// cell, 6 x double: the map (u0, v0, u1, v1, u2, v2) at the triangle's points, in grid units.
constexpr const char* CornerUV = "CornerUV";
/// cell, 3 x unsigned char: 1 where edge k (point k to point k+1) is on the cut graph.
constexpr const char* Seam = "Seam";
/// point, 2 x double, SplitSeams output only: (u, v) of each point of the cut-open surface, the
/// active texture coordinates.
constexpr const char* UV = "UV";
/// field, 1 x double: the edge length of the grid, the world length of one grid unit that the
/// frames are fitted to: TargetEdgeLength, or the length TargetQuadCount chose (where the map is
/// stretched or compressed the quads' edges are longer or shorter; their mean is a few per cent
/// above it when TargetQuadCount chose it).
constexpr const char* EdgeLength = "EdgeLength";
/// field, 1 x int, 3 tuples: triangles with a flipped or degenerate (u, v) image in the
/// continuous minimizer, after rounding, and in the output map (after untangling).
constexpr const char* FlippedTriangles = "FlippedTriangles";
/// field, 1 x int: inner points around which the map's angles do not add up to 2 pi (1 - index)
/// (the map winds around them unlike the frame field; 0 unless untangling failed there).
constexpr const char* WindingErrors = "WindingErrors";
/// field, 1 x double: the untangling's work, in triangle energy evaluations per triangle of the
/// surface (a Newton step's Hessian counts as 12; bounded by UntangleWork; 0 when no triangle
/// was flipped).
constexpr const char* UntangleWorkSpent = "UntangleWorkSpent";
/// field, 1 x double, 3 tuples: sum_f A_f |grad phi - K|^2 / (A |K|^2) of the continuous
/// minimizer, after rounding, and of the output map (0 is a perfect fit, 1 a constant map).
constexpr const char* ParameterizationEnergy = "ParameterizationEnergy";
/// field, 1 x int: edges on the cut graph.
constexpr const char* SeamEdgeCount = "SeamEdgeCount";
/// field, 1 x int: boundary edges put on integer grid lines (AlignToBoundary).
constexpr const char* AlignedBoundaryEdges = "AlignedBoundaryEdges";
/// field, 1 x int: sharp edges put on integer grid lines (FeatureLines).
constexpr const char* AlignedFeatureEdges = "AlignedFeatureEdges";
/// field, 1 x int: triangles of the solver's input that it split because an edge was longer than
/// MaximumTriangleEdge grid edges (its output is then the refined surface).
constexpr const char* GridRefinedTriangles = "GridRefinedTriangles";
/// field, 1 x int: pairs of opposite singularities closer than MinimumSingularitySeparation grid
/// edges that the solver cancelled (their branch points are gone from its map).
constexpr const char* CancelledSingularityPairs = "CancelledSingularityPairs";
/// field, 1 x int: quarter singularities closer than a third of MinimumSingularitySeparation grid
/// edges to one of the same index that the solver moved apart, and those it moved where the
/// quads' size varies less (ConePairGain).
constexpr const char* MovedSingularities = "MovedSingularities";
/// field, 1 x int: pairs of opposite quarter cones the solver added for quads of even size
/// (ConePairGain).
constexpr const char* AddedConePairs = "AddedConePairs";
/// field, 1 x int: cone pairs the solver dropped again on a surface between two or more boundary
/// loops, because the map kept more defects (flipped triangles, wrong windings) with them than
/// without.
constexpr const char* DroppedConePairs = "DroppedConePairs";
/// field, 1 x int: per component whose map the solver made again on a uniformly finer grid because
/// its quads would not have kept the component's topology (MaximumFinerGridRetries), i for the
/// grid sqrt(2)^i times finer that it kept (0 when it kept none); summed over the components.
constexpr const char* FinerGridRetries = "FinerGridRetries";
/// Field data of the solver's output: triangles where the map's grid is finer than EdgeLength,
/// around strips of the surface and walls between creases narrower than a grid edge and around
/// handles and necks narrower than about four (MaximumThinStripRefinement), where the surface
/// curves sharply against the grid (AdaptiveCurvature), around the defects of a first map and
/// between boundary loops its quads would join (DefectGridRefinement).
constexpr const char* FinerGridTriangles = "FinerGridTriangles";
/// field, 1 x int, 2 tuples: branch points, and those mapped to a grid point.
constexpr const char* BranchPointsOnGrid = "BranchPointsOnGrid";
/// field, 1 x double: largest distance of a seam translation from Z^2 (grid units).
constexpr const char* SeamTranslationError = "SeamTranslationError";

// ---- vtkQuadExtractor (output: the quad mesh) ----
/// point, 1 x int: number of edges at the quad vertex.
constexpr const char* Valence = "Valence";
/// cell, 1 x double: the quad's scaled Jacobian, the smallest over its corners (1 for a square).
constexpr const char* ScaledJacobian = "ScaledJacobian";
/// field, 1 x double: share of faces with four distinct corners (1 = all quads).
constexpr const char* QuadShare = "QuadShare";
/// field, 1 x int, 2 tuples: inner vertices of valence other than 4, boundary vertices of valence
/// other than 2 or 3.
constexpr const char* IrregularVertices = "IrregularVertices";
/// field, 1 x double: relative standard deviation (std / mean) of the edge lengths.
constexpr const char* EdgeLengthRSD = "EdgeLengthRSD";
/// field, 1 x double: relative standard deviation of the quads' corner angles.
constexpr const char* AngleRSD = "AngleRSD";
/// field, 1 x double, 2 tuples: smallest and mean ScaledJacobian.
constexpr const char* ScaledJacobianStatistics = "ScaledJacobianStatistics";
/// field, 1 x int: edges of more than two faces or used twice in one direction.
constexpr const char* NonManifoldEdges = "NonManifoldEdges";
/// field, 1 x int: V - E + F of the quad mesh.
constexpr const char* EulerCharacteristic = "EulerCharacteristic";
/// field, 1 x int: boundary loops of the quad mesh.
constexpr const char* BoundaryLoops = "BoundaryLoops";
/// field, 1 x double, 3 tuples: two-sided Hausdorff distance between the quad mesh and the
/// input, then input to quads and quads to input, in % of the input's bounding-box diagonal.
constexpr const char* HausdorffDistance = "HausdorffDistance";
/// field, 1 x int, 2 tuples: quads with a corner turned inside out (scaled Jacobian <= 0) as
/// extracted (the quads of filled holes included), and in the output (after RepairInvertedQuads
/// and RelaxationIterations).
constexpr const char* InvertedQuads = "InvertedQuads";
/// field, 1 x int, 3 tuples: grid cells that gave no quad: a corner off the surface, two corners
/// at one grid point, overlapping others.
constexpr const char* DroppedCells = "DroppedCells";
/// field, 1 x int, 3 tuples: holes inside the surface filled with quads (FillHoles), holes left,
/// quads added
constexpr const char* FilledHoles = "FilledHoles";
/// field, 1 x int, 2 tuples: quads that face against the input triangle closest to their centre
/// (or the nearly closest ones, where there are ties), as extracted, and in the output (after
/// RepairInvertedQuads).
constexpr const char* TurnedQuads = "TurnedQuads";
/// field, 1 x int: copies of a quad vertex added where separate fans of quads touched at it (two
/// pieces of the mesh, or two of its boundary loops), so that the output is manifold at its
/// vertices; 0 on a valid remesh.
constexpr const char* SplitQuadVertices = "SplitQuadVertices";
/// field, 1 x int: quads removed as fragments of a component's quads (a quad or two that touched
/// the rest of their component's quads, four times as many or more, at a corner only; or a disk
/// cut off the component's largest piece, every corner within a quarter of its median edge).
constexpr const char* FragmentQuads = "FragmentQuads";
/// field, 1 x int, 2 tuples: quads facing against the input or turned inside out after the
/// vertex moves that were removed as ears (three of their edges on the boundary) and that were
/// collapsed along a diagonal (RepairInvertedQuads).
constexpr const char* RemovedTurnedQuads = "RemovedTurnedQuads";
/// field, 1 x int: quad vertices moved onto a sharp edge of the input (SnapToCreases).
constexpr const char* SnappedVertices = "SnappedVertices";
/// field, 1 x int: quad vertices lifted off the input, where a quad's centre lay nearer another
/// component's surface than its own (two sheets closer than the quad bulges).
constexpr const char* LiftedVertices = "LiftedVertices";
/// field, 1 x int: components of the input on which no quad lies (no cell of the map on them
/// became a quad), with a warning; 0 on a valid remesh.
constexpr const char* EmptyComponents = "EmptyComponents";
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverArrayNames.h
