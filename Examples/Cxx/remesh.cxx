// remesh: a surface file in, a quad mesh out, with QuadCover's filters chained in C++.
//
//   remesh INPUT OUTPUT [QUADS]
//
// Reads any format vtkQuadCoverReader takes (.obj .off .ply .stl .vtp .vtk), repairs it, runs
// the five stages with their defaults at about QUADS quads (default 3000) and writes the quad
// mesh (.obj .ply .vtp .vtk); prints the quad mesh's figures.
#include "vtkCurvatureFrames.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFrameSmoother.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverReader.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadCoverSurfaceRepair.h"
#include "vtkQuadCoverWriter.h"
#include "vtkQuadExtractor.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: remesh INPUT OUTPUT [QUADS]\n";
    return 2;
  }
  vtkNew<vtkQuadCoverReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkQuadCoverSurfaceRepair> repair;
  repair->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkCurvatureFrames> curvature;
  curvature->SetInputConnection(repair->GetOutputPort());
  vtkNew<vtkFrameSmoother> smoother;
  smoother->SetInputConnection(curvature->GetOutputPort());
  vtkNew<vtkMatchingBuilder> matching;
  matching->SetInputConnection(smoother->GetOutputPort());
  vtkNew<vtkQuadCoverSolver> solver;
  solver->SetInputConnection(matching->GetOutputPort());
  solver->SetTargetQuadCount(argc > 3 ? std::atoi(argv[3]) : 3000);
  vtkNew<vtkQuadExtractor> quads;
  quads->SetInputConnection(solver->GetOutputPort());
  vtkNew<vtkQuadCoverWriter> writer;
  writer->SetInputConnection(quads->GetOutputPort());
  writer->SetFileName(argv[2]);

  // One observer on every stage: the first error is the one to report.
  vtkNew<vtkQuadCoverErrorObserver> errors;
  for (vtkAlgorithm* a : std::initializer_list<vtkAlgorithm*>{
         reader, repair, curvature, smoother, matching, solver, quads, writer })
  {
    errors->Attach(a);
  }
  writer->Write();
  if (!errors->GetError().empty())
  {
    std::cerr << "remesh: " << errors->GetError() << "\n";
    return 1;
  }

  namespace names = vtkQuadCoverArrayNames;
  vtkFieldData* fd = quads->GetOutput()->GetFieldData();
  auto value = [fd](const char* name, int i) { return fd->GetArray(name)->GetComponent(i, 0); };
  std::cout << quads->GetOutput()->GetNumberOfCells() << " quads, "
            << value(names::IrregularVertices, 0) << " irregular inner vertices, edge-length RSD "
            << value(names::EdgeLengthRSD, 0) << ", Euler characteristic "
            << value(names::EulerCharacteristic, 0) << "\n";
  return 0;
}
