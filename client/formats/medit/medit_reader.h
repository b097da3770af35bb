#pragma once

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Parses an ASCII MEDIT .mesh file (INRIA Gamma Mesh Format, libMeshb 7's keyword set; the binary
// .meshb is not read) into a MeshDocument:
// - MeshVersionFormatted (1..4) must come first and Dimension right after it; only Dimension 3
//   is accepted (getme smooths volume meshes). Version 1 means single-precision reals: the points
//   array is then typed float, but keeps the parsed doubles.
// - Vertices → grid points in file order, their refs → "medit:ref" point data (Int32).
// - Edges, Triangles, Quadrilaterals, Tetrahedra, Prisms, Hexahedra, Pyramids → grid cells
//   (VTK line 3, triangle 5, quad 9, tetra 10, wedge 13, hexahedron 12, pyramid 14) in the order
//   of the sections in the file, with VTK's node order (below); their refs → "medit:ref" cell
//   data (Int32).
// - RequiredVertices → point data "fixed" (Int32, 1 = required), the list itself also in
//   MeditExtras so that it is written back in its order.
// - Every other readable section (Corners, Ridges, RequiredEdges, Normals, NormalAtVertices,
//   Tangents, TangentAtVertices, BoundingBox, MMG's Parallel* sections, …; medit_keywords.cc)
//   → MeditExtras, token for token.
// - End must close the file; only comments may follow it.
//
// The format is free: tokens may wrap lines, a token starting with '#' comments out the rest of
// its line, keywords are matched ignoring case (libMeshb, gmsh and meshio match them exactly;
// every writer uses libMeshb's spelling). An unknown keyword is an error: MEDIT sections carry
// no size or end marker, so its data cannot be skipped. Every index is 1-based and checked
// against the number of entities it refers to (vertices, edges, …), wherever the sections are.
//
// Errors (InvalidArgument) name the line, the section and the entry, e.g.
// "line 17: Tetrahedra entry 5: vertex 120 out of range 1..100". The parser never reads out of
// bounds and never reserves more entries than the remaining bytes could hold.
//
// Node order. MEDIT's tetrahedron, hexahedron and pyramid have VTK's order (= Gmsh's = the
// paper's, docs/node-orders.md); its prism has Gmsh's order — bottom triangle 0, 1, 2
// counter-clockwise seen from the top, 3 above 0 — so VTK's wedge (v0..v5) =
// MEDIT (m0, m2, m1, m3, m5, m4).
// Evidence (tests/formats/medit, a regular element of each type must read back valid with mean
// ratio 1):
// - gmsh 4.8's own MEDIT writer (GModelIO_MESH.cpp) writes tetrahedra and hexahedra without
//   permutation, both read back regular. It writes no prisms or pyramids at all: it drops them
//   silently (and its reader reads none).
// - meshio 5 writes its tetra/hexahedron/pyramid/wedge cells (Gmsh order) to the MEDIT sections
//   without permutation and reads them back the same way; all four read back regular.
// - libMeshb's documentation (libMeshb7.pdf §4) and Frey's Medit give no node order for prisms
//   or pyramids. MMG copies both Gmsh prisms and VTK wedges into its prisms unpermuted
//   (inout.c, vtkparser.cpp), so it settles nothing. The one tool that writes MEDIT prisms,
//   meshio, is followed; a prism written in VTK's order reads back inverted (tested).
absl::StatusOr<MeshDocument> ParseMedit(absl::string_view bytes);

}  // namespace getme::formats
