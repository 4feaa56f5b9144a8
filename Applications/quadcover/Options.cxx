#include "Options.h"

#include "Pipeline.h"

#include "vtkQuadCoverWriter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <ostream>
#include <type_traits>

namespace quadcover_app
{
namespace
{
/// SmoothingWeight -> smoothing-weight.
std::string Kebab(const std::string& property)
{
  std::string flag;
  for (std::size_t i = 0; i < property.size(); ++i)
  {
    const unsigned char c = property[i];
    if (std::isupper(c) && i > 0)
    {
      flag += '-';
    }
    flag += static_cast<char>(std::tolower(c));
  }
  return flag;
}

Option Bind(const char* stage, const char* property, const char* meaning, Option::Kind kind,
  std::function<double()> get, std::function<void(double)> set)
{
  Option o;
  o.stage = stage;
  o.property = property;
  o.flag = Kebab(property);
  o.meaning = meaning;
  o.kind = kind;
  o.get = std::move(get);
  o.set = std::move(set);
  return o;
}

Option Ranged(Option o, double low, double high)
{
  o.low = low;
  o.high = high;
  return o;
}

// Each option is bound by the property's own name, so its flag, its setter, its range and its
// default cannot drift apart. Options of two filters (one concept both need) set both and take
// the first one's range; their value is NaN while the filters disagree (three: the same).
#define QC_KIND(f, Property)                                                                       \
  (std::is_same<decltype(f->Get##Property()), bool>::value                                         \
      ? Option::Kind::Switch                                                                       \
      : (std::is_integral<decltype(f->Get##Property())>::value ? Option::Kind::Whole               \
                                                               : Option::Kind::Number))
#define QC_SET(f, Property, x) f->Set##Property(static_cast<decltype(f->Get##Property())>(x))
#define QC_SWITCH(stage, f, Property, meaning)                                                     \
  Bind(                                                                                            \
    stage, #Property, meaning, Option::Kind::Switch, [f]() { return double(f->Get##Property()); }, \
    [f](double x) { QC_SET(f, Property, x); })
#define QC_BOTH(f, g, Property)                                                                    \
  [f, g]() {                                                                                       \
    return f->Get##Property() == g->Get##Property() ? double(f->Get##Property())                   \
                                                    : std::numeric_limits<double>::quiet_NaN();    \
  }
#define QC_SWITCH2(stage, f, g, Property, meaning)                                                 \
  Bind(                                                                                            \
    stage, #Property, meaning, Option::Kind::Switch, QC_BOTH(f, g, Property), [f, g](double x) {   \
      QC_SET(f, Property, x);                                                                      \
      QC_SET(g, Property, x);                                                                      \
    })
#define QC_NUMBER(stage, f, Property, meaning)                                                     \
  Ranged(                                                                                          \
    Bind(                                                                                          \
      stage, #Property, meaning, QC_KIND(f, Property),                                             \
      [f]() { return double(f->Get##Property()); }, [f](double x) { QC_SET(f, Property, x); }),    \
    double(f->Get##Property##MinValue()), double(f->Get##Property##MaxValue()))
#define QC_NUMBER2(stage, f, g, Property, meaning)                                                 \
  Ranged(Bind(stage, #Property, meaning, QC_KIND(f, Property), QC_BOTH(f, g, Property),            \
           [f, g](double x) {                                                                      \
             QC_SET(f, Property, x);                                                               \
             QC_SET(g, Property, x);                                                               \
           }),                                                                                     \
    double(f->Get##Property##MinValue()), double(f->Get##Property##MaxValue()))
#define QC_NUMBER3(stage, f, g, h, Property, meaning)                                              \
  Ranged(Bind(                                                                                     \
           stage, #Property, meaning, QC_KIND(f, Property),                                        \
           [f, g, h]() {                                                                           \
             return f->Get##Property() == g->Get##Property() &&                                    \
                 f->Get##Property() == h->Get##Property()                                          \
               ? double(f->Get##Property())                                                        \
               : std::numeric_limits<double>::quiet_NaN();                                         \
           },                                                                                      \
           [f, g, h](double x) {                                                                   \
             QC_SET(f, Property, x);                                                               \
             QC_SET(g, Property, x);                                                               \
             QC_SET(h, Property, x);                                                               \
           }),                                                                                     \
    double(f->Get##Property##MinValue()), double(f->Get##Property##MaxValue()))

const Option* Find(const std::vector<Option>& options, const std::string& flag)
{
  for (const Option& o : options)
  {
    if (o.flag == flag)
    {
      return &o;
    }
  }
  return nullptr;
}

/// Reads `text` as a value of `o`; false when it is not one.
bool ReadValue(const Option& o, const std::string& text, double& value)
{
  if (o.kind == Option::Kind::Choice)
  {
    for (std::size_t i = 0; i < o.choices.size(); ++i)
    {
      if (o.choices[i] == text)
      {
        value = static_cast<double>(i);
        return true;
      }
    }
    return false;
  }
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  // the range first: converting an out-of-range double to int is undefined
  return !text.empty() && *end == '\0' && value >= o.low && value <= o.high &&
    (o.kind != Option::Kind::Whole || value == std::floor(value));
}

/// A "--name" or "--name=value" argument: its name and the value after its '=', if any.
struct Argument
{
  std::string name;
  std::string value;
  bool inlineValue = false;
};

Argument Split(const std::string& a)
{
  Argument arg;
  arg.name = a.substr(2);
  const auto equals = arg.name.find('=');
  if (equals != std::string::npos)
  {
    arg.value = arg.name.substr(equals + 1);
    arg.name = arg.name.substr(0, equals);
    arg.inlineValue = true;
  }
  return arg;
}

/// The argument's value: after its '=', or the next argument (i moves past it); "" and false
/// when there is none.
bool TakeValue(int argc, char* argv[], int& i, Argument& arg)
{
  if (!arg.inlineValue && i + 1 < argc)
  {
    arg.value = argv[++i];
    arg.inlineValue = true;
  }
  return arg.inlineValue;
}

/// A stage option (i moves past a value that follows it).
std::string ParseOption(
  int argc, char* argv[], int& i, Argument arg, const std::vector<Option>& options)
{
  const Option* o = Find(options, arg.name);
  const Option* negated =
    arg.name.compare(0, 3, "no-") == 0 ? Find(options, arg.name.substr(3)) : nullptr;
  if (!o && !(negated && negated->kind == Option::Kind::Switch))
  {
    return "unknown option --" + arg.name;
  }
  const Option* target = o ? o : negated;
  if (target->kind == Option::Kind::Switch)
  {
    if (arg.inlineValue)
    {
      return "--" + arg.name + " takes no value (use --" + target->flag + " or --no-" +
        target->flag + ")";
    }
    target->set(o ? 1.0 : 0.0);
    return "";
  }
  double x = 0.0;
  if (!TakeValue(argc, argv, i, arg))
  {
    return "--" + arg.name + " needs a value";
  }
  if (!ReadValue(*o, arg.value, x))
  {
    std::string allowed;
    for (const std::string& c : o->choices)
    {
      allowed += (allowed.empty() ? " (" : ", ") + c;
    }
    return "invalid value '" + arg.value + "' for --" + arg.name +
      (allowed.empty() ? "" : allowed + ")");
  }
  o->set(x);
  return "";
}

/// A "--" argument: one of the command line's own, or a stage option.
std::string ParseLong(
  int argc, char* argv[], int& i, const std::vector<Option>& options, Request& request)
{
  Argument arg = Split(argv[i]);
  std::string* text = arg.name == "output" ? &request.output
    : arg.name == "stage"                  ? &request.stage
    : arg.name == "stats"                  ? &request.stats
                                           : nullptr;
  if (text)
  {
    if (!TakeValue(argc, argv, i, arg))
    {
      return "--" + arg.name + " needs a value";
    }
    *text = arg.value;
    return "";
  }
  if (arg.name == "help" || arg.name == "verbose")
  {
    (arg.name == "help" ? request.help : request.verbose) = true;
    return arg.inlineValue ? "--" + arg.name + " takes no value" : "";
  }
  request.given.push_back(arg.name);
  return ParseOption(argc, argv, i, arg, options);
}

/// The checks once every argument is read.
std::string CheckRequest(const Request& request, const std::vector<Option>& options)
{
  const bool count = std::find(request.given.begin(), request.given.end(), "target-quad-count") !=
    request.given.end();
  const Option* length = Find(options, "target-edge-length");
  // A nonzero edge length decides the number of quads; a count beside it would be ignored.
  if (count && length && length->get() != 0.0)
  {
    return "--target-quad-count and a nonzero --target-edge-length cannot both be given (the edge "
           "length sets the number of quads)";
  }
  if (request.input.empty())
  {
    return "no input file given";
  }
  if (request.output.empty())
  {
    return "no output file given (-o OUTPUT)";
  }
  if (!vtkQuadCoverWriter::CanWriteFile(request.output.c_str()))
  {
    return "cannot write '" + request.output + "': unknown extension (use .vtp .vtk .obj .ply)";
  }
  if (Pipeline::StageIndex(request.stage) < 0)
  {
    std::string stages;
    for (const std::string& s : Pipeline::StageNames())
    {
      stages += (stages.empty() ? "" : ", ") + s;
    }
    return "unknown stage '" + request.stage + "' (stages: " + stages + ")";
  }
  return "";
}
}

std::string Option::Text(double value) const
{
  if (std::isnan(value))
  {
    return "(the filters disagree)";
  }
  if (this->kind == Kind::Switch)
  {
    return value != 0.0 ? "on" : "off";
  }
  if (this->kind == Kind::Choice)
  {
    const int i = static_cast<int>(value);
    return i >= 0 && i < static_cast<int>(this->choices.size()) ? this->choices[i] : "?";
  }
  char text[64];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

namespace
{
/// --maximum-triangle-count: the repair's property, which the command line sets from the quads
/// asked unless it is given (Pipeline::AutomaticTriangleCount).
Option MaximumTriangleCountOption(vtkQuadCoverSurfaceRepair* repair)
{
  Option o = QC_NUMBER("repair", repair, MaximumTriangleCount,
    "simplify a surface of more triangles to about this many first (the quads are put back "
    "onto it unless it was smoothed), 0: never");
  o.defaultText = "16 a quad asked, at least 100000";
  return o;
}
}

std::vector<Option> StageOptions(Pipeline& p)
{
  vtkQuadCoverSurfaceRepair* repair = p.Repair;
  vtkCurvatureFrames* curvature = p.Curvature;
  vtkFrameSmoother* smoother = p.Smoother;
  vtkMatchingBuilder* matching = p.Matching;
  vtkQuadCoverSolver* solver = p.Solver;
  vtkQuadExtractor* extractor = p.Extractor;
  Option rounding = QC_NUMBER("param", solver, RoundingMode, "how the integers are rounded");
  rounding.kind = Option::Kind::Choice;
  rounding.choices = { "none", "simple", "greedy" }; // vtkQuadCoverSolver::ROUNDING_*
  return {
    QC_NUMBER("repair", repair, MinimumComponentTriangleCount,
      "refine components with fewer triangles (the surface stays), 0: none"),
    MaximumTriangleCountOption(repair),
    QC_SWITCH("repair", repair, SmoothRoughSurfaces,
      "smooth components rough at the triangle scale (noise: curvature that a little smoothing "
      "takes away); the quads lie on the smoothed surface"),
    QC_NUMBER("curvature", curvature, NeighborhoodRadius,
      "radius of the curvature neighbourhood, in median edge lengths"),
    // three stages: written out
    Ranged(Bind(
             "curvature", "NumberOfThreads",
             "worker threads (curvature, smoothing, maps of components, untangling), 0 for all "
             "cores",
             Option::Kind::Whole,
             [curvature, smoother, solver]() {
               const int n = curvature->GetNumberOfThreads();
               return n == smoother->GetNumberOfThreads() && n == solver->GetNumberOfThreads()
                 ? double(n)
                 : std::numeric_limits<double>::quiet_NaN();
             },
             [curvature, smoother, solver](double x) {
               QC_SET(curvature, NumberOfThreads, x);
               QC_SET(smoother, NumberOfThreads, x);
               QC_SET(solver, NumberOfThreads, x);
             }),
      double(curvature->GetNumberOfThreadsMinValue()),
      double(curvature->GetNumberOfThreadsMaxValue())),
    QC_SWITCH("curvature", curvature, UseInputFrames,
      "use a FrameU cell array of the input as the guidance field"),
    QC_NUMBER(
      "smooth", smoother, SmoothingWeight, "lambda: smoothness against curvature alignment"),
    QC_NUMBER("smooth", smoother, MaximumNumberOfIterations, "iterations at most per run"),
    QC_NUMBER("smooth", smoother, ConvergenceTolerance,
      "stop when an iteration lowers the energy by less than this fraction"),
    QC_NUMBER3("smooth", smoother, solver, extractor, FeatureAngle,
      "edges sharper than this (degrees) are features (held frames, feature lines, quad vertices "
      "snapped onto them)"),
    QC_NUMBER3("smooth", smoother, solver, extractor, MinimumFeatureLength,
      "shortest chain of sharp edges that is a feature"),
    QC_SWITCH("smooth", smoother, AlignToFeatures, "hold frames along sharp edges"),
    QC_SWITCH2("smooth", smoother, solver, AlignToBoundary,
      "quads follow the boundary: frames held along it, boundary edges on grid lines"),
    QC_SWITCH("smooth", smoother, GlobalStart, "also start from the globally smoothest fields"),
    QC_NUMBER("smooth", smoother, CoherenceRadius,
      "align to curvature only where its directions are nearly parallel over this radius (a "
      "fraction of the surface's size)"),
    QC_SWITCH("matching", matching, OptimizeBranchPoints,
      "merge pairs of singularities that cancel (Sect. 4.2)"),
    QC_NUMBER("matching", matching, BranchPointWeight,
      "cost of one singular point, in radians of matching angle"),
    QC_SWITCH("matching", matching, LengthScaledCost,
      "count each edge by its length in merge costs and split distances (off: once)"),
    QC_NUMBER("matching", matching, MaximumSearchSize, "points one merge search may visit"),
    QC_SWITCH("matching", matching, FitFramesToMatchings,
      "turn the frames to agree with changed matchings"),
    QC_NUMBER2("matching", matching, solver, BoundaryTolerance,
      "degrees a boundary edge may turn from its frame and still follow it"),
    QC_NUMBER("param", solver, TargetQuadCount,
      "about this many quads (at most 2000000, or 50 a triangle)"),
    QC_NUMBER("param", solver, TargetEdgeLength,
      "quad edge length in world units, 0 for --target-quad-count"),
    QC_SWITCH("param", solver, PureQuads, "branch points on grid points, so only quads"),
    QC_SWITCH("param", solver, FeatureLines,
      "features along a frame direction on grid lines: quad edges along the creases"),
    rounding,
    QC_NUMBER("param", solver, MaximumUntangleRounds,
      "rounds of untangling per neighbourhood of flipped triangles"),
    QC_NUMBER("param", solver, UntangleWork,
      "the untangling's budget per repair, in energy evaluations per triangle (of at most 20,000 "
      "triangles); all of a map's repairs together spend at most twice that"),
    QC_NUMBER("param", solver, MinimumComponentQuadCount,
      "quads at least on each connected component, per hole and handle (its own grid where "
      "needed)"),
    QC_NUMBER("param", solver, CurvatureEdgeLength,
      "edge length at most this over the mean curvature (4 quads around a tube), 0: no limit"),
    QC_NUMBER("param", solver, MinimumQuadsPerSingularity,
      "grid cells at least per singular point of the field (more quads than asked where the "
      "field has more singularities than the grid holds), 0: no limit"),
    QC_NUMBER("param", solver, MaximumRegrids,
      "other grids (2, 1/2, 4, 1/4, 8, 16 times the quads) tried for a map left with defects or "
      "whose quads lose the surface's topology"),
    QC_NUMBER("param", solver, MaximumRegridQuadCount,
      "only maps of at most this many quads are tried on other grids"),
    QC_NUMBER("param", solver, MinimumSingularitySeparation,
      "opposite singularities closer than this many grid edges cancel, like ones at a third of it "
      "move apart, 0: keep all"),
    QC_NUMBER("param", solver, MaximumTriangleEdge,
      "triangles with a longer edge (in grid edges) are split before the map, 0: none"),
    QC_NUMBER("param", solver, ConePairGain,
      "a cone pair is added where it lowers the modelled log scale's variance, summed over the "
      "quads, by this, a singularity moved where by twice this, 0: neither"),
    QC_NUMBER("param", solver, MaximumThinStripRefinement,
      "around a strip between two boundary lines narrower than a grid edge, or a wall between two "
      "creases lower than one, the grid is finer, down to the strip's width but at most this many "
      "times (and around a handle or neck shorter around than about four grid edges near a "
      "singular point), 1: uniform"),
    QC_NUMBER("param", solver, AdaptiveCurvature,
      "adaptive density: the grid edge about this many times the radius of curvature (thin "
      "parts keep their shape; 0.5: about 12 quads around a thin tube), 0: uniform"),
    QC_NUMBER("param", solver, DefectGridRefinement,
      "where the repaired map keeps defects the grid is this many times finer and the map made "
      "again, kept with fewer defects; the same between two boundary loops the quads would join, "
      "kept when its quads keep the surface's topology, 1: not"),
    QC_NUMBER("param", solver, DefectAdaptiveCurvature,
      "where the repaired map keeps defects, first the adaptive grid of --adaptive-curvature X "
      "is tried, kept with fewer defects, 0: not"),
    QC_NUMBER("param", solver, MaximumFinerGridRetries,
      "a component whose map keeps defects and whose quads would lose its topology is mapped "
      "again on a grid sqrt(2) times finer, at most this many times, 0: never"),
    QC_SWITCH("param", solver, SplitSeams,
      "write the surface cut open along the seams, with UV texture coordinates"),
    QC_SWITCH("quads", extractor, RepairInvertedQuads,
      "move the corners of quads turned inside out or facing against the input"),
    QC_SWITCH(
      "quads", extractor, FillHoles, "fill holes the map leaves inside the surface with quads"),
    QC_SWITCH("quads", extractor, SnapToCreases,
      "move the quad vertices beside sharp edges onto them, so that quad edges follow creases"),
    QC_NUMBER(
      "quads", extractor, RelaxationIterations, "sweeps of tangential relaxation of all quads"),
    QC_SWITCH(
      "quads", extractor, ComputeHausdorffDistance, "measure the Hausdorff distance to the input"),
  };
}

std::string Parse(int argc, char* argv[], const std::vector<Option>& options, Request& request)
{
  for (int i = 1; i < argc && !request.help; ++i)
  {
    const std::string a = argv[i];
    std::string problem;
    if (a == "-h")
      request.help = true;
    else if (a == "-v")
      request.verbose = true;
    else if (a == "-o" && i + 1 < argc)
      request.output = argv[++i];
    else if (a == "-o")
      problem = "-o needs a value";
    else if (a.compare(0, 2, "--") == 0 && a.size() > 2)
      problem = ParseLong(argc, argv, i, options, request);
    else if (!a.empty() && a[0] == '-' && a != "-")
      problem = "unknown option " + a;
    else if (request.input.empty())
      request.input = a;
    else
      problem = "more than one input file given ('" + request.input + "', '" + a + "')";
    if (!problem.empty())
    {
      return problem;
    }
  }
  return request.help ? "" : CheckRequest(request, options);
}

void PrintUsage(std::ostream& os, const std::vector<Option>& options)
{
  os << "usage: quadcover INPUT -o OUTPUT [--stage STAGE] [--stats FILE.json] [-v] [options]\n"
        "\n"
        "Runs the QuadCover pipeline on a surface up to STAGE and writes the result.\n"
        "  INPUT            .obj .off .ply .stl .vtp or .vtk surface\n"
        "  -o OUTPUT        .vtp or .vtk (every array kept), .obj or .ply (geometry only)\n"
        "  --stage STAGE    repair|curvature|smooth|matching|param|quads (default quads)\n"
        "  --stats FILE     write a JSON summary: sizes, seconds per stage, the options used\n"
        "                   and every figure the stages write\n"
        "  -v, --verbose    seconds per stage, and VTK's own messages (progress shows\n"
        "                   whenever stderr is a terminal)\n"
        "\n"
        "Stage options: each is the filter property of the same name (--smoothing-weight sets\n"
        "vtkFrameSmoother's SmoothingWeight); a switch takes --name or --no-name, a value\n"
        "--name VALUE or --name=VALUE.\n";
  std::string stage;
  for (const Option& o : options)
  {
    if (o.stage != stage)
    {
      stage = o.stage;
      os << stage << ":\n";
    }
    std::string range;
    const bool whole = o.kind == Option::Kind::Whole;
    if (o.kind == Option::Kind::Number || whole)
    {
      char text[96];
      if (o.high > 1e100)
        std::snprintf(text, sizeof text, ", at least %g", o.low);
      else
        std::snprintf(text, sizeof text, whole ? ", %.0f..%.0f" : ", %g..%g", o.low, o.high);
      range = text;
    }
    else if (o.kind == Option::Kind::Choice)
    {
      for (const std::string& c : o.choices)
      {
        range += (range.empty() ? ", " : "|") + c;
      }
    }
    const std::string flag = o.kind == Option::Kind::Switch
      ? "--[no-]" + o.flag
      : "--" + o.flag + (o.kind == Option::Kind::Choice ? " MODE" : (whole ? " N" : " X"));
    os << "  " << flag << "\n      " << o.meaning << range << " (default "
       << (o.defaultText.empty() ? o.Text(o.get()) : o.defaultText) << ")\n";
  }
  os << "\n"
        "Repaired silently (stage repair, counted in --stats): polygons and strips\n"
        "triangulated, vertex and line cells dropped, coincident points merged (to round-off),\n"
        "triangles with a repeated point removed, T-junctions closed (a boundary point on\n"
        "another boundary edge), edges of more than two triangles cut apart\n"
        "into manifold sheets, a point where separate fans of triangles touch split into one\n"
        "copy per fan, triangles reoriented to agree with their neighbours (each\n"
        "component keeping the orientation of most of its area), flat triangles with a\n"
        "corner on the opposite edge flipped away, components rough at the\n"
        "triangle scale (noise) smoothed, and the triangles of components too coarse for a\n"
        "map split at their edges' midpoints.\n"
        "Refused: missing, unreadable or empty files, unknown extensions, no polygons, point\n"
        "ids out of range, NaN or infinite coordinates, surfaces whose triangles all have\n"
        "zero area, non-orientable components (a Moebius strip).\n"
        "Exit status: 0 done, 1 the input or a stage failed (one line on stderr), 2 bad usage.\n";
}
}
