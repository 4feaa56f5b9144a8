// Stats.h: the --stats JSON summary of a run.
#ifndef quadcover_app_Stats_h
#define quadcover_app_Stats_h

#include "Options.h"
#include "Pipeline.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace quadcover_app
{
/**
 * The summary as JSON: the input file and its size, the repaired surface's size, the last
 * stage, seconds per step, every option's value, and for each stage run, the field-data arrays
 * it added to its output, under the array's name in snake_case (EdgeLength: "edge_length"; a
 * number, a list of a one-component array's tuples, or a list of tuples), plus the seconds of
 * each of the solver's sparse solves (solve_seconds) and the quad mesh's vertices and faces.
 */
std::string StatsJson(const Request& request, vtkPolyData* input, const Pipeline& pipeline,
  int lastStage, const std::vector<Timing>& timings, const std::vector<Option>& options);
}

#endif
