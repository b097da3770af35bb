#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats::testing {

// The four MSH variants, named as the fixture names its files ("41_binary").
struct GmshVariant {
  std::string suffix;
  WriteOptions options;
};
std::vector<GmshVariant> AllGmshVariants();

// Files the fixture script writes (make_gmsh_inputs.py), and files for
// check_gmsh_reads_outputs.py: in $GETME_GMSH_OUTPUTS if set, else in a directory no check reads.
std::string GmshInput(const std::string& name);
std::string GmshOutputDirectory();
std::string GmshOutput(const std::string& name);
std::string ReadBytes(const std::string& path);
void WriteBytes(const std::string& path, const std::string& bytes);
absl::StatusOr<MeshDocument> ParseGmshFile(const std::string& path);

// A .expected sidecar: what Gmsh itself read back from the file (see make_gmsh_inputs.py).
struct ExpectedNode {
  std::int64_t tag = 0;
  double xyz[3] = {0, 0, 0};
};
struct ExpectedElement {
  std::int64_t tag = 0;
  int type = 0;
  int dim = 0;
  int entity = 0;
  std::vector<std::int64_t> nodes;  // node tags, Gmsh order
};
struct ExpectedPhysical {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;
};
struct ExpectedData {
  bool on_nodes = true;
  std::string name;
  int step = 0;
  double time = 0;
  int components = 0;
  std::int64_t tag = 0;
  std::vector<double> values;
};
struct GmshExpected {
  std::vector<ExpectedNode> nodes;
  std::vector<ExpectedElement> elements;
  std::vector<ExpectedPhysical> physicals;
  std::vector<ExpectedData> data;
};
GmshExpected ReadGmshExpected(const std::string& path);

// The tests' own statement of the node-order convention, independent of the reader's table:
// VTK code of a Gmsh type, and the Gmsh nodes of an element in VTK's order (the prism mirrored:
// VTK (v0..v5) = Gmsh (g0, g2, g1, g3, g5, g4), docs/node-orders.md).
int VtkCodeOfGmshType(int gmsh_type);
std::vector<std::int64_t> InVtkOrder(int gmsh_type, const std::vector<std::int64_t>& gmsh_nodes);

// Bitwise equality of doubles (NaN equal to the same NaN).
bool SameBits(double a, double b);

// Asserts (gtest) that two documents hold the same grid — points bit for bit, cells, point and
// cell arrays bit for bit — and, if `with_extras`, the same Gmsh extras.
void ExpectSameDocument(const MeshDocument& expected, const MeshDocument& actual, bool with_extras);

}  // namespace getme::formats::testing
