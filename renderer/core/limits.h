#pragma once
// Every limit radview puts on what its input can ask for, in one place. Each bounds a number
// that a file or an option controls and that decides an allocation or a loop's length, so that
// no input, however hostile, makes radview allocate more than a 128 GiB machine has or run a
// loop for days (what scales with an image is also checked against the memory available:
// core/memory_budget.h). Each value is far above what real data needs (core/README.md lists them
// with the memory they imply); past one, radview refuses with an Error naming the file or the
// option and the limit (checkLimit below), never truncates silently.
#include <cstddef>
#include <cstdint>
#include <string>

namespace radview {

// --- files ---------------------------------------------------------------------------------

// Bytes of a glTF file or of a buffer it names. tinygltf takes lengths as unsigned int and
// indexes with int in places; 2 GiB keeps clear of both.
inline constexpr uint64_t kMaxFileBytes = uint64_t(1) << 31;
// Elements of one glTF accessor (2^26 = 67,108,864). radview decodes an accessor into doubles
// before checking it: at most 2 GiB for a VEC4 accessor, 1.5 GiB for the positions of 67 M
// vertices, 30 times the largest mesh radview meshes or solves.
inline constexpr uint64_t kMaxAccessorElements = uint64_t(1) << 26;
// Elements of an accessor without a bufferView (all zeros, possibly overridden by sparse
// values): its count costs memory but no file bytes, so it is the one count a small file could
// inflate at will. 2^24 elements is at most 512 MiB.
inline constexpr uint64_t kMaxZeroFilledCount = uint64_t(1) << 24;
// Depth of a glTF node hierarchy: no modelling tool makes deeper chains, and a generated file
// that does is more likely an attack than a scene.
inline constexpr int kMaxNodeDepth = 1024;

// --- scenes and meshes ---------------------------------------------------------------------

// Triangles a scene imports, instances counted (a small file can instance one mesh many times).
// Every triangle becomes at least one element, and more elements than kMaxMeshElements are
// refused anyway; refusing at import keeps a small file from exhausting memory first.
inline constexpr size_t kMaxSceneTriangles = 2'000'000;
// Elements radview's meshers and its solver make (uniform mesh, discontinuity mesh,
// solve --max-elements): the solver's memory and time grow with them, and 2 M is 300 times the
// elements of the Cornell box's solution.
inline constexpr size_t kMaxMeshElements = 2'000'000;
// Elements and nodes of a solution file, read or written. Four times kMaxMeshElements, because
// triangulating T-vertices (solve --triangulate-t-vertices) cuts elements into several; nodes
// twice that (quadratic elements add a node per edge, C-1 edges duplicate nodes). radview
// refuses to write a solution it would refuse to read.
inline constexpr size_t kMaxSolutionElements = 4 * kMaxMeshElements;
inline constexpr size_t kMaxSolutionNodes = 2 * kMaxSolutionElements;
// Vertices the primitives of a solution file store in all: a node bordering elements of k
// materials is stored k times, and primitives may share accessors, so that a small file could
// otherwise list the same data over and over.
inline constexpr size_t kMaxStoredVertices = 2 * kMaxSolutionNodes;
// Corners of one element: a polygon's triangulation is at worst quadratic in its corners, and
// radview's meshers never make more than a few dozen (T-vertex repair inserts a neighbour's
// nodes into the boundary).
inline constexpr size_t kMaxElementCorners = 1024;
// Discontinuity edges of a solution file: each is two nodes; a mesh at kMaxSolutionNodes with
// every node on one edge has fewer.
inline constexpr size_t kMaxDiscontinuityEdges = kMaxSolutionNodes;
// Entries of one element of a PLY file (its vertices, faces, edges, or any other element, all of
// which are read): the solution file's node limit, so that what radview reads it can write.
inline constexpr size_t kMaxPlyEntries = kMaxSolutionNodes;
// Items of one PLY list property over all its entries (the corners of every face): the corners
// of kMaxSolutionElements quads, 256 MiB as doubles. A file's bytes bound them too, but a
// 2 GiB file of one-byte items would decode into 16 GiB.
inline constexpr size_t kMaxPlyListItems = 4 * kMaxSolutionElements;
// Merged discontinuity segments per polygon in discontinuity meshing: the arrangement is
// quadratic in them and each adds elements. Past it the strongest orders are kept (C-1, then
// C0, then C1), longer first within an order; the rest are dropped and counted.
inline constexpr size_t kMaxSegmentsPerPolygon = 1000;

// Every file radview writes it can read: the solver and meshers make at most kMaxMeshElements,
// T-vertex triangulation may multiply them, and the solution file's limits leave room for that;
// every accessor of a solution at the limits fits the accessor limit.
static_assert(kMaxSolutionElements >= kMaxMeshElements);
static_assert(kMaxSolutionNodes >= kMaxSolutionElements);
static_assert(kMaxStoredVertices >= kMaxSolutionNodes);
static_assert(kMaxAccessorElements >= kMaxStoredVertices);
static_assert(kMaxSceneTriangles <= kMaxAccessorElements);

// --- images ----------------------------------------------------------------------------------

// Width and height of a render, a bench view or a window (--size). 16384 is the largest
// texture of Mesa's llvmpipe and half of a current GPU's. The context's own GL_MAX_TEXTURE_SIZE
// and GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT apply on top (gl/render_targets.cpp), and the memory an
// image that size needs (10 to 48 GiB) is checked against what is available
// (core/memory_budget.h).
inline constexpr int kMaxImageSide = 16384;

// --- samples and repetitions -------------------------------------------------------------------

// Final-gather samples per pixel (render --spp, bench --spp, the viewer's stopping point). The
// gather's memory does not grow with them; its time does, linearly: 65536 spp at 512x512 is 17 G
// rays, hours on a CPU. Its error falls at least as 1/sqrt(spp) (faster where the integrand is
// smooth: the passes are stratified, gather_sequence.h), so more would not be seen on 8 bits.
inline constexpr int kMaxGatherSpp = 65536;
// Independent runs of the final gather (bench --runs): each keeps an image of sums, so memory
// grows with them (64 x 32 bytes a pixel); the error estimate's interval needs no more.
inline constexpr int kMaxGatherRuns = 64;
// Final-gather shadow rays per pixel per pass (--emitter-samples): time, linearly.
inline constexpr int kMaxEmitterSamples = 1024;
// Solver samples per shooter and node (solve --samples): time, linearly; the form factor's
// noise at 4096 is 1.6 % of that at 1.
inline constexpr int kMaxSolverSamples = 4096;
// Solver shots (solve --max-shots): each costs a pass over every node.
inline constexpr size_t kMaxSolverShots = 100'000'000;
// Timed frames per bench row (bench --frames); the median of 1000 is as good as of more.
inline constexpr int kMaxBenchFrames = 1000;

// --- tessellation ------------------------------------------------------------------------------

// Tessellation level of a Bezier piece (--tessellation, bench --levels, adaptive levels):
// OpenGL guarantees 64 (GL_MAX_TESS_GEN_LEVEL).
inline constexpr int kMaxTessellationLevel = 64;
// Triangles the GPU may generate for one frame of a tessellated method: pieces x about L^2. The
// Cornell box's 48,732 Powell-Sabin pieces at level 64 make 209 M; a billion takes about 2.5
// minutes a frame on llvmpipe and a second on a GPU, while a mesh of 2 M elements at level 64
// would make 50 billion or more and hang the machine for hours. Nothing is allocated for them: this
// bounds time, and is checked before anything is drawn.
inline constexpr uint64_t kMaxTessellatedTriangles = 1'000'000'000;

// Throws Error(where, "<value> <what>, more than radview's limit of <limit>") when value > limit.
// `where` is the file or the option ("--size 20000x10"), `what` the counted thing ("nodes").
void checkLimit(const std::string& where, uint64_t value, uint64_t limit, const std::string& what);

}  // namespace radview
