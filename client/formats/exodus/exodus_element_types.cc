#include "formats/exodus/exodus_element_types.h"

#include <algorithm>
#include <string>

#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "formats/vtk_cell_type.h"
#include "getme/elements/node_orders.h"

namespace getme::formats {
namespace {

constexpr int kVtkVertex = 1;
constexpr int kVtkLine = 3;

struct NamedTopology {
  absl::string_view letters;
  ExodusTopology topology;
};

// The Exodus II manual's element type names (its "Element Types" section), with the spellings
// other writers use (meshio, Cubit, IOSS).
constexpr std::array<NamedTopology, 18> kTopologies = {{
    {"TETRA", {kVtkTetra, 4, "TETRA"}},
    {"TET", {kVtkTetra, 4, "TETRA"}},
    {"PYRAMID", {kVtkPyramid, 5, "PYRAMID"}},
    {"PYRA", {kVtkPyramid, 5, "PYRAMID"}},
    {"WEDGE", {kVtkWedge, 6, "WEDGE"}},
    {"HEX", {kVtkHexahedron, 8, "HEX8"}},
    {"HEXAHEDRON", {kVtkHexahedron, 8, "HEX8"}},
    {"TRI", {kVtkTriangle, 3, "TRI3"}},
    {"TRIANGLE", {kVtkTriangle, 3, "TRI3"}},
    {"TRISHELL", {kVtkTriangle, 3, "TRI3"}},
    {"SHELL", {kVtkQuad, 4, "SHELL4"}},
    {"QUAD", {kVtkQuad, 4, "SHELL4"}},
    {"BAR", {kVtkLine, 2, "BAR2"}},
    {"BEAM", {kVtkLine, 2, "BAR2"}},
    {"TRUSS", {kVtkLine, 2, "BAR2"}},
    {"EDGE", {kVtkLine, 2, "BAR2"}},
    {"SPHERE", {kVtkVertex, 1, "SPHERE"}},
    {"CIRCLE", {kVtkVertex, 1, "SPHERE"}},
}};

constexpr char kSupported[] =
    "getme reads linear TETRA, PYRAMID, WEDGE and HEX blocks and passes SHELL/QUAD, TRI, "
    "BAR/BEAM/TRUSS and SPHERE blocks through";

// Exodus II manual, "Side Set Node Ordering" (1-based there).
constexpr ExodusSide kTetraSides[] = {
    {{0, 1, 3}, 3}, {{1, 2, 3}, 3}, {{0, 3, 2}, 3}, {{0, 2, 1}, 3}};
constexpr ExodusSide kPyramidSides[] = {
    {{0, 1, 4}, 3}, {{1, 2, 4}, 3}, {{2, 3, 4}, 3}, {{0, 4, 3}, 3}, {{0, 3, 2, 1}, 4}};
constexpr ExodusSide kWedgeSides[] = {
    {{0, 1, 4, 3}, 4}, {{1, 2, 5, 4}, 4}, {{0, 3, 5, 2}, 4}, {{0, 2, 1}, 3}, {{3, 4, 5}, 3}};
constexpr ExodusSide kHexSides[] = {{{0, 1, 5, 4}, 4}, {{1, 2, 6, 5}, 4}, {{2, 3, 7, 6}, 4},
                                    {{0, 4, 7, 3}, 4}, {{0, 3, 2, 1}, 4}, {{4, 5, 6, 7}, 4}};

}  // namespace

absl::StatusOr<ExodusTopology> TopologyOfBlock(absl::string_view type_name,
                                               std::int64_t nodes_per_element) {
  std::string name = absl::AsciiStrToUpper(type_name);
  while (!name.empty() && (name.back() == ' ' || name.back() == '\0')) name.pop_back();
  const std::size_t digits = name.find_first_of("0123456789");
  const absl::string_view letters = absl::string_view(name).substr(0, digits);
  std::optional<std::int64_t> named_count;
  if (digits != std::string::npos) {
    std::int64_t count = 0;
    if (!absl::SimpleAtoi(absl::string_view(name).substr(digits), &count)) {
      return absl::InvalidArgumentError(
          absl::StrCat("element type '", type_name, "' is not supported: ", kSupported));
    }
    named_count = count;
  }
  const auto found = std::find_if(kTopologies.begin(), kTopologies.end(),
                                  [&](const NamedTopology& t) { return t.letters == letters; });
  if (found == kTopologies.end()) {
    return absl::InvalidArgumentError(
        absl::StrCat("element type '", type_name, "' is not supported: ", kSupported));
  }
  ExodusTopology topology = found->topology;
  if (letters == "SHELL" && nodes_per_element == 3) topology = {kVtkTriangle, 3, "TRI3"};
  if (named_count.has_value() && *named_count != nodes_per_element) {
    return absl::InvalidArgumentError(absl::StrCat("element type '", type_name, "' names ",
                                                   *named_count, " nodes but the block has ",
                                                   nodes_per_element, " per element"));
  }
  if (nodes_per_element > topology.node_count) {
    return absl::InvalidArgumentError(
        absl::StrCat("element type '", type_name, "' with ", nodes_per_element,
                     " nodes per element is not supported: getme smooths linear elements (",
                     letters, " has ", topology.node_count, " nodes)"));
  }
  if (nodes_per_element < topology.node_count) {
    return absl::InvalidArgumentError(
        absl::StrCat("element type '", type_name, "' needs ", topology.node_count,
                     " nodes per element, the block has ", nodes_per_element));
  }
  return topology;
}

std::optional<ExodusTopology> TopologyOfVtkCell(int vtk_type) {
  for (const NamedTopology& entry : kTopologies) {
    if (entry.topology.vtk_type == vtk_type) return entry.topology;
  }
  return std::nullopt;
}

void ConvertExodusVtkOrder(int vtk_type, std::span<std::int64_t> nodes) {
  if (vtk_type != kVtkWedge || nodes.size() != kVtkWedgeToPaperPrism.size()) return;
  std::array<std::int64_t, 6> copy{};
  std::copy(nodes.begin(), nodes.end(), copy.begin());
  MirrorVtkPaperOrder(ElementType::kPrism, std::span<const std::int64_t>(copy), nodes);
}

int SideCount(int vtk_type) {
  switch (vtk_type) {
    case kVtkTetra:
      return 4;
    case kVtkPyramid:
    case kVtkWedge:
      return 5;
    case kVtkHexahedron:
      return 6;
    default:
      return 0;
  }
}

ExodusSide SideNodes(int vtk_type, int side) {
  if (side < 1 || side > SideCount(vtk_type)) return {};
  switch (vtk_type) {
    case kVtkTetra:
      return kTetraSides[side - 1];
    case kVtkPyramid:
      return kPyramidSides[side - 1];
    case kVtkWedge:
      return kWedgeSides[side - 1];
    default:
      return kHexSides[side - 1];
  }
}

}  // namespace getme::formats
