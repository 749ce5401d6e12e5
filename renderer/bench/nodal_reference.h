#pragma once
// The reference at the mesh's nodes: eq. 9.9 evaluated at each node, as the final gather
// evaluates it at each pixel (C&W §9.3.1: the last bounce taken from the solution), or the path
// tracer's true B there, in the reference's independent runs. It splits a bench row's error in two: the solution's nodal values
// against these (what the solver brings), and the method drawing these values against the
// reference image (what the interpolant adds between the nodes, the part a choice of method
// trades; bench/bench_reference.h).
#include "gather/final_gather.h"
#include "gather/path_tracer.h"
#include "mesh/radiosity_mesh.h"

#include <vector>

namespace radview {

struct NodalReference {
  int runs = 0;
  std::vector<Rgb> B;  // [node * runs + run]: that run's mean; a node of no element keeps its own B

  // A copy of `mesh` whose nodes hold run `run`'s values.
  RadiosityMesh withRun(const RadiosityMesh& mesh, int run) const;
};

// `samplesPerRun` samples of eq. 9.9 at each node `wanted` says (all when it is empty), in each
// of the gather's runs, on all cores; the others keep their own B. A node is gathered at a
// point just inside the first element that uses it, from that element's front: on a
// discontinuity edge (C-1) the node of each side then takes its own side's limit, not the
// average of both.
NodalReference gatherAtNodes(const RadiosityMesh& mesh, const FinalGather& gather, int samplesPerRun,
                             const std::vector<char>& wanted = {});
// The same with the truth at each node: the path tracer's estimate of B there (path_tracer.h),
// which splits a row's error into the solution's and the reconstruction's against the true
// image rather than against eq. 9.9 over the solution.
NodalReference pathTraceAtNodes(const RadiosityMesh& mesh, const PathTracer& tracer, int samplesPerRun,
                                const std::vector<char>& wanted = {});

// The nodes a view's picture depends on: those of the elements seen (elementAt, as
// visibleElements gives it) and of every element that shares a node with one of those, whose
// values the C1 methods' vertex gradients read.
std::vector<char> nodesOfTheView(const RadiosityMesh& mesh, const std::vector<int32_t>& elementAt);

}  // namespace radview
