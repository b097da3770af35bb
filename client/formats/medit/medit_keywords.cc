#include "formats/medit/medit_keywords.h"

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "formats/vtk_values.h"
#include "getme/elements/node_orders.h"

namespace getme::formats::medit {
namespace {

using enum KeywordRole;

// The element sections. The last two fields name the section's solution keyword and its GMF
// code (its index in libmeshb7.c's GmfKwdFmt), by which a .sol ReferenceStrings entry names it.
constexpr std::array<ElementKind, kElementKindCount> kElementKinds = {{
    {"Edges", 3, 2, Entity::kEdge, 63, "SolAtEdges"},
    {"Triangles", 5, 3, Entity::kTriangle, 64, "SolAtTriangles"},
    {"Quadrilaterals", 9, 4, Entity::kQuadrilateral, 65, "SolAtQuadrilaterals"},
    {"Tetrahedra", 10, 4, Entity::kTetrahedron, 66, "SolAtTetrahedra"},
    {"Prisms", 13, 6, Entity::kNone, 67, "SolAtPrisms"},
    {"Hexahedra", 12, 8, Entity::kNone, 68, "SolAtHexahedra"},
    {"Pyramids", 14, 5, Entity::kNone, 26, "SolAtPyramids"},
}};

constexpr const ElementKind* kEdges = &kElementKinds[0];
constexpr const ElementKind* kTriangles = &kElementKinds[1];
constexpr const ElementKind* kQuadrilaterals = &kElementKinds[2];
constexpr const ElementKind* kTetrahedra = &kElementKinds[3];
constexpr const ElementKind* kPrisms = &kElementKinds[4];
constexpr const ElementKind* kHexahedra = &kElementKinds[5];
constexpr const ElementKind* kPyramids = &kElementKinds[6];

// The keywords getme reads: libMeshb 7's GmfKwdFmt entries with fixed-size integer/real lines
// (the "d" of "dr" expanded for 3-D), and the sections MMG writes beyond the GMF table
// (Required/Parallel entities, MMG's inout_3d.c).
constexpr Keyword kKeywords[] = {
    {"MeshVersionFormatted", kVersion, false, "i", "-"},
    {"Dimension", kDimension, false, "i", "-"},
    {"Vertices", kVertices, true, "rrri", "----"},
    {"Edges", kElements, true, "iii", "vv-", kEdges},
    {"Triangles", kElements, true, "iiii", "vvv-", kTriangles},
    {"Quadrilaterals", kElements, true, "iiiii", "vvvv-", kQuadrilaterals},
    {"Tetrahedra", kElements, true, "iiiii", "vvvv-", kTetrahedra},
    {"Prisms", kElements, true, "iiiiiii", "vvvvvv-", kPrisms},
    {"Hexahedra", kElements, true, "iiiiiiiii", "vvvvvvvv-", kHexahedra},
    {"Pyramids", kElements, true, "iiiiii", "vvvvv-", kPyramids},
    {"RequiredVertices", kRequiredVertices, true, "i", "v"},
    {"Corners", kKept, true, "i", "v"},
    {"Ridges", kKept, true, "i", "e"},
    {"RequiredEdges", kKept, true, "i", "e"},
    {"RequiredTriangles", kKept, true, "i", "t"},
    {"RequiredQuadrilaterals", kKept, true, "i", "q"},
    // libMeshb7.pdf §4 and Medit read the integers of the Normal/TangentAt*Vertices lines
    // differently (element, local vertex, normal vs. one normal per element vertex), so only
    // the indices both agree on are checked.
    {"TangentAtEdgeVertices", kKept, true, "iii", "e--"},
    {"NormalAtVertices", kKept, true, "ii", "vn"},
    {"NormalAtTriangleVertices", kKept, true, "iii", "---"},
    {"NormalAtQuadrilateralVertices", kKept, true, "iiii", "----"},
    {"AngleOfCornerBound", kKept, false, "r", "-"},
    {"SubDomainFromGeom", kKept, true, "iii", "t--"},
    // The second index points into the geometric support mesh, another file.
    {"VerticesOnGeometricVertices", kKept, true, "ii", "v-"},
    {"VerticesOnGeometricEdges", kKept, true, "iirr", "v---"},
    {"VerticesOnGeometricTriangles", kKept, true, "iirrr", "v----"},
    {"VerticesOnGeometricQuadrilaterals", kKept, true, "iirrr", "v----"},
    {"EdgesOnGeometricEdges", kKept, true, "ii", "e-"},
    {"TrianglesOnGeometricTriangles", kKept, true, "ii", "t-"},
    {"TrianglesOnGeometricQuadrilaterals", kKept, true, "ii", "t-"},
    {"QuadrilateralsOnGeometricTriangles", kKept, true, "ii", "q-"},
    {"QuadrilateralsOnGeometricQuadrilaterals", kKept, true, "ii", "q-"},
    {"BoundingBox", kKept, false, "rrrrrr", "------"},
    {"Tangents", kKept, true, "rrr", "---"},
    {"Normals", kKept, true, "rrr", "---"},
    {"TangentAtVertices", kKept, true, "ii", "vg"},
    {"Iterations", kKept, false, "i", "-"},
    {"Time", kKept, false, "r", "-"},
    {"CoarseHexahedra", kKept, true, "i", "-"},
    {"PeriodicVertices", kKept, true, "ii", "vv"},
    {"PeriodicEdges", kKept, true, "ii", "ee"},
    {"PeriodicTriangles", kKept, true, "ii", "tt"},
    {"PeriodicQuadrilaterals", kKept, true, "ii", "qq"},
    {"FloatingPointPrecision", kKept, false, "i", "-"},
    {"BezierBasis", kKept, false, "i", "-"},
    {"RequiredTetrahedra", kKept, true, "i", "T"},
    {"ParallelVertices", kKept, true, "i", "v"},
    {"ParallelEdges", kKept, true, "i", "e"},
    {"ParallelTriangles", kKept, true, "i", "t"},
    {"ParallelQuadrilaterals", kKept, true, "i", "q"},
    {"ParallelTetrahedra", kKept, true, "i", "T"},
    {"End", kEnd, false, "", ""},
};

// GMF keywords whose lines are strings, variable-length lists or raw data.
constexpr absl::string_view kOtherGmfKeywords[] = {
    "Comments",       "ReferenceStrings",  "IRefGroups",      "DRefGroups",     "ByteFlow",
    "PrivateTable",   "Domains",           "BoundaryLayers",  "IterationsAll",  "TimesAll",
    "Prisms9",        "Hexahedra12",       "Quadrilaterals6", "VerticesGID",    "EdgesGID",
    "TrianglesGID",   "QuadrilateralsGID", "TetrahedraGID",   "PyramidsGID",    "PrismsGID",
    "HexahedraGID",   "Fault_NearTri",     "Fault_Inter",     "Fault_FreeEdge", "Fault_Overlap",
    "Fault_BadShape", "Fault_SmallTri",
};

bool ContainsIgnoreCase(absl::string_view text, absl::string_view part) {
  return absl::StrContains(absl::AsciiStrToLower(text), absl::AsciiStrToLower(part));
}

}  // namespace

absl::string_view EntityName(Entity entity) {
  switch (entity) {
    case Entity::kNone:
      return "entity";
    case Entity::kVertex:
      return "vertex";
    case Entity::kEdge:
      return "edge";
    case Entity::kTriangle:
      return "triangle";
    case Entity::kQuadrilateral:
      return "quadrilateral";
    case Entity::kTetrahedron:
      return "tetrahedron";
    case Entity::kNormal:
      return "normal";
    case Entity::kTangent:
      return "tangent";
  }
  return "entity";
}

Entity EntityOf(char refers) {
  switch (refers) {
    case 'v':
      return Entity::kVertex;
    case 'e':
      return Entity::kEdge;
    case 't':
      return Entity::kTriangle;
    case 'q':
      return Entity::kQuadrilateral;
    case 'T':
      return Entity::kTetrahedron;
    case 'n':
      return Entity::kNormal;
    case 'g':
      return Entity::kTangent;
    default:
      return Entity::kNone;
  }
}

std::optional<std::string> IndexError(Entity entity, std::int64_t index,
                                      const EntityCounts& counts) {
  if (entity == Entity::kNone) return std::nullopt;
  const std::int64_t count = counts[static_cast<int>(entity)];
  if (index >= 1 && index <= count) return std::nullopt;
  if (count == 0) {
    return absl::StrCat(EntityName(entity), " ", index, " out of range: the file has no ",
                        EntityName(entity), " entities");
  }
  return absl::StrCat(EntityName(entity), " ", index, " out of range 1..", count);
}

std::optional<std::int64_t> ParseInteger(absl::string_view token) {
  // ParseIntegerToken drops one leading '+' and lets from_chars read a '-': refuse "+-1".
  if (absl::StartsWith(token, "+-")) return std::nullopt;
  return ParseIntegerToken(token, VtkDataType::kInt64);
}

std::optional<double> ParseReal(absl::string_view token) {
  if (absl::StartsWith(token, "+-")) return std::nullopt;
  return ParseRealToken(token);
}

std::optional<std::string> FieldError(char field, absl::string_view token) {
  constexpr std::size_t kMaxShown = 40;
  const std::string shown =
      token.size() > kMaxShown ? absl::StrCat(token.substr(0, kMaxShown), "…") : std::string(token);
  if (field == 'i' && !ParseInteger(token)) {
    return absl::StrCat("expected an integer, found '", shown, "'");
  }
  if (field == 'r' && !ParseReal(token)) {
    return absl::StrCat("expected a real number, found '", shown, "'");
  }
  return std::nullopt;
}

const std::array<ElementKind, kElementKindCount>& ElementKinds() { return kElementKinds; }

const ElementKind* ElementKindOfCell(int vtk_type) {
  for (const ElementKind& kind : kElementKinds) {
    if (kind.vtk_type == vtk_type) return &kind;
  }
  return nullptr;
}

int MeditToVtkNode(const ElementKind& kind, int vtk_node) {
  // MEDIT's prism is the paper's and Gmsh's (medit_reader.h); VTK's wedge lists each triangle the
  // other way round.
  return &kind == kPrisms ? kVtkWedgeToPaperPrism[vtk_node] : vtk_node;
}

const Keyword* FindKeyword(absl::string_view name) {
  if (absl::EqualsIgnoreCase(name, "Hexaedra")) name = "Hexahedra";
  for (const Keyword& keyword : kKeywords) {
    if (absl::EqualsIgnoreCase(keyword.name, name)) return &keyword;
  }
  return nullptr;
}

std::optional<std::string> UnsupportedKeywordReason(absl::string_view name) {
  for (absl::string_view prefix : {"SolAt", "ISolAt", "DSolAt", "HOSolAt"}) {
    if (absl::StartsWithIgnoreCase(name, prefix)) {
      return "it holds solution data, which belongs in a .sol file";
    }
  }
  for (absl::string_view suffix : {"P2", "P3", "P4", "Q2", "Q3", "Q4"}) {
    if (absl::EndsWithIgnoreCase(name, suffix)) return "high-order elements are not supported";
  }
  if (ContainsIgnoreCase(name, "Ordering") || ContainsIgnoreCase(name, "NodesPositions") ||
      ContainsIgnoreCase(name, "ReferenceElement") ||
      absl::StartsWithIgnoreCase(name, "ExtraVerticesAt")) {
    return "high-order elements are not supported";
  }
  for (absl::string_view polyhedral :
       {"Polyhedra", "Polygons", "PolyhedraHeaders", "PolyhedraFaces", "BoundaryPolygonHeaders",
        "BoundaryPolygonVertices", "InnerPolygonHeaders", "InnerPolygonVertices"}) {
    if (absl::EqualsIgnoreCase(name, polyhedral)) return "polyhedral elements are not supported";
  }
  for (absl::string_view other : kOtherGmfKeywords) {
    if (absl::EqualsIgnoreCase(name, other)) {
      return "its data (strings, variable-length or raw lines) is not supported";
    }
  }
  return std::nullopt;
}

}  // namespace getme::formats::medit
