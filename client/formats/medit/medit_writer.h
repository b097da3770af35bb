#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Serializes `document` as an ASCII MEDIT .mesh file (libMeshb's layout: a keyword, its entry
// count, one entry per line), readable by libMeshb, gmsh, meshio and MMG:
// - MeshVersionFormatted: the document's MEDIT version (2 for documents from other formats);
//   a version 1 document whose coordinates are no longer all exact floats (smoothed) is written
//   as version 2, so readers do not round them to single precision.
// - Vertices: grid points as the shortest decimals that read back bit-identical, with their
//   refs from the point array "medit:ref" (0 without one).
// - Element sections: grid cells grouped by kind (medit_layout.h), VTK's wedge written back in
//   MEDIT's prism order (medit_reader.h); refs from the cell array "medit:ref", else
//   "gmsh:physical", else 0.
// - RequiredVertices: the vertices the point array "fixed" marks (any component nonzero), in the
//   order of the MEDIT file they came from while they are the same set, ascending otherwise.
// - The document's MeditExtras sections verbatim (checked: known keyword, entry layout, indices
//   against the vertices and elements written), then End.
//
// What a .mesh cannot hold is named in a spdlog warning: vertex cells, point arrays other than
// "medit:ref" and "fixed", dataset field data. Cell arrays other than the refs are left to
// SerializeMeditSolution (the .sol beside the .mesh); the warning also says when cells had to be
// regrouped, which changes cell numbering.
//
// InvalidArgument for options.encoding == kBinary (the binary .meshb needs libMeshb, which no
// Debian package provides), for cells MEDIT cannot hold (voxels, quadratic cells, polyhedra, …)
// and for an inconsistent document (wrong array lengths, ids out of range, refs that are not
// 32-bit integers, malformed extras).
absl::StatusOr<std::string> SerializeMedit(const MeshDocument& document,
                                           const WriteOptions& options);

// The grid's numeric cell arrays (all but the one SerializeMedit writes as refs) as a GMF .sol
// text for the .mesh that SerializeMedit writes from the same document: one SolAt<kind> section
// per element section (SolAtEdges, SolAtTriangles, SolAtQuadrilaterals, SolAtTetrahedra,
// SolAtPrisms, SolAtHexahedra, SolAtPyramids), in the same order and with the same elements.
// Each array is one field: 1 component → GmfSca (1), 3 → GmfVec (2), 9 → GmfMat (4); other
// component counts become that many scalars (named array[c], with a warning). Integer arrays are
// written as reals, as GMF solutions are. A ReferenceStrings section names each field
// ("66 1 mean_ratio": keyword code of SolAtTetrahedra, field 1). Empty string when there is no
// cell array or no element to store. InvalidArgument as SerializeMedit for inconsistent grids.
absl::StatusOr<std::string> SerializeMeditSolution(const MeshDocument& document);

}  // namespace getme::formats
