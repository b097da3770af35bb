#pragma once

#include <cstdint>
#include <string>

#include "getme/elements/element_type.h"

namespace getme {

// How MeshBuilder::Build words the errors it finds in the caller's input. The builder does every
// check once; whoever hands it the mesh decides how nodes, elements and their positions are named
// (a file's cells, or the wire's fields, ids and VTK node positions). Positions are given in the
// paper's node order (Fig. 1). The defaults name insertion indices. Called on error paths only.
class MeshErrorNames {
 public:
  virtual ~MeshErrorNames() = default;

  virtual std::string EmptyMesh(std::int64_t nodes, std::int64_t elements) const;
  virtual std::string NonFiniteCoordinate(std::int64_t node, double x, double y, double z) const;
  // `entry` counts the builder's SetFixed calls from 0.
  virtual std::string FixedNodeOutOfRange(std::int64_t entry, std::int64_t node,
                                          std::int64_t node_count) const;
  virtual std::string NodeOutOfRange(std::int64_t element, ElementType type, int position,
                                     std::int64_t node, std::int64_t node_count) const;
  // first < second.
  virtual std::string RepeatedNode(std::int64_t element, ElementType type, std::int64_t node,
                                   int first, int second) const;
};

}  // namespace getme
