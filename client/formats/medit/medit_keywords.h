#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "absl/strings/string_view.h"

namespace getme::formats::medit {

// The ASCII MEDIT / Gamma Mesh Format (GMF) as libMeshb 7 defines it (libmeshb7.c, GmfKwdFmt;
// libMeshb7.pdf §4): a stream of whitespace-separated tokens in which a keyword is followed by a
// line count (for most keywords) and that many data lines. Nothing marks where a keyword's data
// ends, so a reader must know every keyword's line layout to skip it: unknown keywords cannot be
// skipped and are errors.

// What getme does with a keyword's data.
enum class KeywordRole : std::uint8_t {
  kVersion,           // MeshVersionFormatted v
  kDimension,         // Dimension d
  kVertices,          // Vertices: x y z ref → grid points, "medit:ref" point data
  kElements,          // Edges … Pyramids: vertex indices and a ref → grid cells
  kRequiredVertices,  // → "fixed" point data
  kKept,              // kept verbatim in MeditExtras
  kEnd,
};

// The entities a 1-based index in a data line can refer to; the reader and the writer check every
// index against the number of such entities in the file.
enum class Entity : std::uint8_t {
  kNone,
  kVertex,
  kEdge,
  kTriangle,
  kQuadrilateral,
  kTetrahedron,
  kNormal,
  kTangent,
};
inline constexpr int kEntityCount = 8;

absl::string_view EntityName(Entity entity);  // "vertex", "edge", …

// Mesh elements: their keyword, VTK cell type and the entity they number.
struct ElementKind {
  absl::string_view keyword;  // "Tetrahedra"
  int vtk_type;               // 10
  int node_count;             // 4
  Entity entity;              // kTetrahedron; kNone for kinds nothing refers to
  int gmf_solution_code;      // GMF keyword code of SolAt<kind> (a .sol ReferenceStrings entry)
  absl::string_view solution_keyword;  // "SolAtTetrahedra"
};

// In the order getme writes them (the order of libMeshb's keyword table, pyramids last).
inline constexpr int kElementKindCount = 7;
const std::array<ElementKind, kElementKindCount>& ElementKinds();
// The kind holding VTK cell type `vtk_type`, or null (vertex cells and unsupported types).
const ElementKind* ElementKindOfCell(int vtk_type);

// MEDIT → VTK node order of an element: VTK node k is MEDIT node order[k]. Only the prism
// differs (see medit_reader.h); the permutation is its own inverse, so it maps back as well.
int MeditToVtkNode(const ElementKind& kind, int vtk_node);

struct Keyword {
  absl::string_view name;  // GMF spelling
  KeywordRole role;
  bool has_count;  // a line count follows the keyword; otherwise exactly one data line
  // One character per token of a data line: 'i' integer, 'r' real (3-D: libMeshb's "dr" is
  // "rrr").
  absl::string_view fields;
  // Per token, what an integer refers to: 'v' vertex, 'e' edge, 't' triangle, 'q' quadrilateral,
  // 'T' tetrahedron, 'n' normal, 'g' tangent, '-' nothing (a ref, a value).
  absl::string_view refers;
  const ElementKind* element = nullptr;  // kElements only
};

Entity EntityOf(char refers);

// Number of entities of each kind in a file (indexed by Entity), for checking 1-based indices.
using EntityCounts = std::array<std::int64_t, kEntityCount>;

// What is wrong with `index` as a 1-based index of `entity` ("vertex 120 out of range 1..100"),
// or nullopt if it is valid. Indices of Entity::kNone are not checked.
std::optional<std::string> IndexError(Entity entity, std::int64_t index,
                                      const EntityCounts& counts);

// Number tokens of data lines. Integers: optional sign, digits, within int64. Reals: what strtod
// reads in the C locale ("1", "-2.5e-3", "nan", "inf"); denormal and overflowing literals are
// refused rather than silently read as 0 or inf.
std::optional<std::int64_t> ParseInteger(absl::string_view token);
std::optional<double> ParseReal(absl::string_view token);
// What is wrong with `token` as a field of type `field` ('i' or 'r'), or nullopt if it is one.
std::optional<std::string> FieldError(char field, absl::string_view token);

// Looks a keyword up by name, ignoring case (libMeshb, gmsh and meshio compare case-sensitively;
// accepting "vertices" costs nothing since no data token starts with a letter other than
// nan/inf, which only appear where a real is expected). Also accepts "Hexaedra", the spelling of
// older INRIA tools that meshio reads too. Null if the name is not a keyword getme can read.
const Keyword* FindKeyword(absl::string_view name);

// Why a known GMF keyword that getme cannot read is refused ("high-order elements", "solution
// data, which belongs in a .sol file", …), or nullopt for names that are not GMF keywords.
std::optional<std::string> UnsupportedKeywordReason(absl::string_view name);

}  // namespace getme::formats::medit
