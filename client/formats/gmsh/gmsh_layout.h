#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "formats/gmsh/gmsh_extras.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Everything about a document's MSH structure the writer needs beyond the grid's points and
// cells: tags, entities and their physical groups, for one MSH version.
struct GmshLayout {
  std::vector<std::int64_t> node_tags;     // point index → node tag
  std::vector<std::int64_t> element_tags;  // cell index → element tag
  // The document's own node and element tags (so raw sections referring to them stay valid).
  bool keeps_tags = false;
  std::vector<GmshPhysicalName> physical_names;

  // 4.1
  bool write_entities = true;
  std::vector<GmshEntity> entities;  // ordered by dimension
  std::vector<GmshNodeBlock> node_blocks;
  std::vector<GmshDimTag> element_entities;

  // 2.2
  GmshTagLists element_tag_lists;
};

// With gmsh extras that match the grid (same point and cell counts), their tags are kept, and so
// is the rest of the structure when `version` is the version they were read in. Otherwise:
// node tags 1..n, element tags 1..m, and each cell's entity derived from cell data — the entity
// tag from "gmsh:geometrical" (else "medit:ref", else "gmsh:physical"), the physical group from
// "gmsh:physical" (else "medit:ref"), one entity per dimension when there is none of those. Cells
// of one dimension sharing both values share an entity; entity tags are those values when they
// are positive and unambiguous, else 1..k per dimension. A 4.1 layout classifies every node on
// the first entity of the highest dimension (one node block keeps the grid's point order).
// What cannot be carried over (several physical groups of one 4.1 entity in a 2.2 file, 2.2
// partition tags in a 4.1 file, tags that no longer match the grid) is named in a warning.
//
// InvalidArgument for a cell type MSH cannot hold here (naming the cell and its type).
absl::StatusOr<GmshLayout> BuildGmshLayout(const MeshDocument& document, GmshVersion version);

}  // namespace getme::formats
