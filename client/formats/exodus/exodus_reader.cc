#include "formats/exodus/exodus_reader.h"

#include <exodusII.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <span>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "formats/exodus/exodus_element_types.h"
#include "formats/exodus/exodus_functions.h"
#include "formats/exodus/exodus_library.h"
#include "formats/file_io.h"
#include "formats/vtk_cell_type.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

// A netCDF header may declare dimensions of any length, independent of the data that follows.
// Counts are checked against the file size before anything is allocated: even compressed
// netCDF-4 data of a real mesh needs far more than one byte per 16 values.
constexpr std::int64_t kValuesPerFileByte = 16;

// Exodus names are at most 32 characters by default (MAX_NAME_LENGTH); files written with
// longer names record their length, read up to this many.
constexpr int kLongestName = 255;

std::string Quoted(const std::string& name) {
  return name.empty() ? std::string() : absl::StrCat(" ('", name, "')");
}

// Reads Exodus's parts in order, keeping the file size and names needed for messages.
class ExodusFileReader {
 public:
  ExodusFileReader(int exoid, std::int64_t file_size) : exoid_(exoid), file_size_(file_size) {}

  absl::StatusOr<MeshDocument> Read();

 private:
  absl::Status CheckCount(std::int64_t count, absl::string_view what) const;
  // The same for count_a × count_b (both already checked), without overflowing.
  absl::Status CheckProduct(std::int64_t a, std::int64_t b, absl::string_view what) const;
  absl::StatusOr<std::vector<std::int64_t>> Ids(ex_entity_type type, std::int64_t count,
                                                absl::string_view what);
  absl::StatusOr<std::vector<std::string>> Names(ex_entity_type type, std::int64_t count,
                                                 absl::string_view what);
  // A side or node set's entry and distribution-factor counts, each checked against the file.
  struct SetCounts {
    std::int64_t entries = 0;
    std::int64_t factors = 0;
  };
  absl::StatusOr<SetCounts> ReadSetCounts(ex_entity_type type, std::int64_t id,
                                          const std::string& where, absl::string_view entry_name);
  absl::Status ReadCoordinates();
  absl::Status ReadBlocks();
  absl::Status ReadSideSets();
  absl::Status ReadNodeSets();
  absl::Status ReadNumberMaps();
  void WarnAboutUnread();

  int exoid_;
  std::int64_t file_size_;
  ex_init_params init_{};
  MeshDocument document_;
  ExodusExtras extras_;
  std::vector<std::int64_t> block_of_cell_;  // block id per grid cell (-1: side set face)
  std::vector<std::int64_t> side_set_of_cell_;
};

absl::Status ExodusFileReader::CheckCount(std::int64_t count, absl::string_view what) const {
  if (count < 0 || count > kValuesPerFileByte * file_size_) {
    return absl::InvalidArgumentError(
        absl::StrCat(what, " = ", count, " is more than this ", file_size_, "-byte file can hold"));
  }
  return absl::OkStatus();
}

absl::Status ExodusFileReader::CheckProduct(std::int64_t a, std::int64_t b,
                                            absl::string_view what) const {
  if (a != 0 && b > kValuesPerFileByte * file_size_ / a) {
    return absl::InvalidArgumentError(absl::StrCat(what, " = ", a, " × ", b, " is more than this ",
                                                   file_size_, "-byte file can hold"));
  }
  return absl::OkStatus();
}

absl::StatusOr<std::vector<std::int64_t>> ExodusFileReader::Ids(ex_entity_type type,
                                                                std::int64_t count,
                                                                absl::string_view what) {
  std::vector<std::int64_t> ids(static_cast<std::size_t>(count));
  if (count > 0 && Exodus().ex_get_ids(exoid_, type, ids.data()) < 0) {
    return ExodusError(absl::StrCat("cannot read the ", what, " ids"));
  }
  // The library finds blocks and sets by id, so a repeated id makes the later ones unreachable;
  // -1 marks cells outside any block or side set in the grid's cell arrays.
  std::vector<std::int64_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    if (sorted[k] < 0) {
      return absl::InvalidArgumentError(
          absl::StrCat(what, " id ", sorted[k], ": ids must not be negative"));
    }
    if (k > 0 && sorted[k] == sorted[k - 1]) {
      return absl::InvalidArgumentError(absl::StrCat(what, " id ", sorted[k], " is used twice"));
    }
  }
  return ids;
}

absl::StatusOr<ExodusFileReader::SetCounts> ExodusFileReader::ReadSetCounts(
    ex_entity_type type, std::int64_t id, const std::string& where, absl::string_view entry_name) {
  SetCounts counts;
  if (Exodus().ex_get_set_param(exoid_, type, id, &counts.entries, &counts.factors) < 0) {
    return ExodusError(where);
  }
  if (absl::Status status = CheckCount(counts.entries, absl::StrCat(where, ": ", entry_name));
      !status.ok()) {
    return status;
  }
  if (absl::Status status =
          CheckCount(counts.factors, absl::StrCat(where, ": distribution factor count"));
      !status.ok()) {
    return status;
  }
  return counts;
}

absl::StatusOr<std::vector<std::string>> ExodusFileReader::Names(ex_entity_type type,
                                                                 std::int64_t count,
                                                                 absl::string_view what) {
  std::vector<std::string> names(static_cast<std::size_t>(count));
  if (count == 0) return names;
  const int length = static_cast<int>(Exodus().ex_inquire_int(exoid_, EX_INQ_MAX_READ_NAME_LENGTH));
  std::vector<std::vector<char>> buffers(names.size(),
                                         std::vector<char>(std::max(length, 0) + 1, '\0'));
  std::vector<char*> pointers;
  for (std::vector<char>& buffer : buffers) pointers.push_back(buffer.data());
  if (Exodus().ex_get_names(exoid_, type, pointers.data()) < 0) {
    return ExodusError(absl::StrCat("cannot read the ", what, " names"));
  }
  for (std::size_t k = 0; k < names.size(); ++k) {
    buffers[k].back() = '\0';
    names[k] = buffers[k].data();
    while (!names[k].empty() && names[k].back() == ' ') names[k].pop_back();
  }
  return names;
}

absl::Status ExodusFileReader::ReadCoordinates() {
  const std::int64_t count = init_.num_nodes;
  std::vector<double> x(count), y(count), z(count);
  if (count > 0 && Exodus().ex_get_coord(exoid_, x.data(), y.data(), z.data()) < 0) {
    return ExodusError("cannot read the node coordinates");
  }
  DataArray& points = document_.grid.points;
  points.name = "Points";
  points.type = VtkDataType::kDouble;
  points.components = 3;
  points.reals.resize(static_cast<std::size_t>(3 * count));
  for (std::int64_t node = 0; node < count; ++node) {
    points.reals[3 * node] = x[node];
    points.reals[3 * node + 1] = y[node];
    points.reals[3 * node + 2] = z[node];
  }
  return absl::OkStatus();
}

absl::Status ExodusFileReader::ReadBlocks() {
  const std::int64_t count = init_.num_elem_blk;
  absl::StatusOr<std::vector<std::int64_t>> ids = Ids(EX_ELEM_BLOCK, count, "element block");
  if (!ids.ok()) return ids.status();
  absl::StatusOr<std::vector<std::string>> names = Names(EX_ELEM_BLOCK, count, "element block");
  if (!names.ok()) return names.status();
  GridCells& cells = document_.grid.cells;
  std::int64_t elements = 0;
  for (std::int64_t k = 0; k < count; ++k) {
    ExodusBlock block;
    block.id = (*ids)[k];
    block.name = (*names)[k];
    const std::string where = absl::StrCat("element block ", block.id, Quoted(block.name));
    ex_block param{};
    param.id = block.id;
    param.type = EX_ELEM_BLOCK;
    if (Exodus().ex_get_block_param(exoid_, &param) < 0) return ExodusError(where);
    block.topology = param.topology;
    block.cell_count = param.num_entry;
    absl::StatusOr<ExodusTopology> topology =
        TopologyOfBlock(block.topology, param.num_nodes_per_entry);
    if (!topology.ok()) {
      return absl::InvalidArgumentError(absl::StrCat(where, ": ", topology.status().message()));
    }
    // Each factor first, so that the products below cannot overflow.
    if (absl::Status status = CheckCount(param.num_entry, absl::StrCat(where, ": element count"));
        !status.ok()) {
      return status;
    }
    if (absl::Status status =
            CheckCount(param.num_attribute, absl::StrCat(where, ": attributes per element"));
        !status.ok()) {
      return status;
    }
    if (absl::Status status = CheckCount(param.num_entry * topology->node_count,
                                         absl::StrCat(where, ": connectivity length"));
        !status.ok()) {
      return status;
    }
    if (absl::Status status = CheckProduct(param.num_entry, param.num_attribute,
                                           absl::StrCat(where, ": attribute count"));
        !status.ok()) {
      return status;
    }
    elements += param.num_entry;
    if (elements > init_.num_elem) {
      return absl::InvalidArgumentError(absl::StrCat(where, ": the blocks hold more elements than ",
                                                     "num_elem = ", init_.num_elem));
    }
    std::vector<std::int64_t> connectivity(
        static_cast<std::size_t>(param.num_entry * topology->node_count));
    if (!connectivity.empty() && Exodus().ex_get_conn(exoid_, EX_ELEM_BLOCK, block.id,
                                                      connectivity.data(), nullptr, nullptr) < 0) {
      return ExodusError(absl::StrCat(where, ": cannot read the connectivity"));
    }
    std::vector<std::int64_t> nodes(static_cast<std::size_t>(topology->node_count));
    for (std::int64_t element = 0; element < param.num_entry; ++element) {
      for (int i = 0; i < topology->node_count; ++i) {
        const std::int64_t node = connectivity[element * topology->node_count + i];
        if (node < 1 || node > init_.num_nodes) {
          return absl::InvalidArgumentError(absl::StrCat(where, ": element ", element + 1,
                                                         ": node ", node, " out of range 1..",
                                                         init_.num_nodes));
        }
        nodes[i] = node - 1;
      }
      ConvertExodusVtkOrder(topology->vtk_type, nodes);
      cells.Add(topology->vtk_type, nodes);
      block_of_cell_.push_back(block.id);
      side_set_of_cell_.push_back(-1);
    }
    if (param.num_attribute > 0) {
      block.attributes.resize(static_cast<std::size_t>(param.num_entry * param.num_attribute));
      if (param.num_entry > 0 &&
          Exodus().ex_get_attr(exoid_, EX_ELEM_BLOCK, block.id, block.attributes.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot read the attributes"));
      }
      std::vector<std::vector<char>> buffers(static_cast<std::size_t>(param.num_attribute),
                                             std::vector<char>(kLongestName + 1, '\0'));
      std::vector<char*> pointers;
      for (std::vector<char>& buffer : buffers) pointers.push_back(buffer.data());
      if (Exodus().ex_get_attr_names(exoid_, EX_ELEM_BLOCK, block.id, pointers.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot read the attribute names"));
      }
      for (std::vector<char>& buffer : buffers) {
        buffer.back() = '\0';
        block.attribute_names.emplace_back(buffer.data());
      }
    }
    extras_.blocks.push_back(std::move(block));
  }
  if (elements != init_.num_elem) {
    return absl::InvalidArgumentError(absl::StrCat("the element blocks hold ", elements,
                                                   " elements, num_elem says ", init_.num_elem));
  }
  return absl::OkStatus();
}

absl::Status ExodusFileReader::ReadSideSets() {
  const std::int64_t count = init_.num_side_sets;
  absl::StatusOr<std::vector<std::int64_t>> ids = Ids(EX_SIDE_SET, count, "side set");
  if (!ids.ok()) return ids.status();
  absl::StatusOr<std::vector<std::string>> names = Names(EX_SIDE_SET, count, "side set");
  if (!names.ok()) return names.status();
  GridCells& cells = document_.grid.cells;
  const std::int64_t element_count = init_.num_elem;
  for (std::int64_t k = 0; k < count; ++k) {
    ExodusSideSet set;
    set.id = (*ids)[k];
    set.name = (*names)[k];
    const std::string where = absl::StrCat("side set ", set.id, Quoted(set.name));
    const absl::StatusOr<SetCounts> counts =
        ReadSetCounts(EX_SIDE_SET, set.id, where, "entry count");
    if (!counts.ok()) return counts.status();
    const std::int64_t entries = counts->entries;
    const std::int64_t factors = counts->factors;
    set.elements.resize(static_cast<std::size_t>(entries));
    set.sides.resize(static_cast<std::size_t>(entries));
    if (entries > 0 && Exodus().ex_get_set(exoid_, EX_SIDE_SET, set.id, set.elements.data(),
                                           set.sides.data()) < 0) {
      return ExodusError(absl::StrCat(where, ": cannot read its elements and sides"));
    }
    // Checked here, before the library looks the sides up: it indexes its side tables with
    // these numbers.
    for (std::int64_t entry = 0; entry < entries; ++entry) {
      const std::int64_t element = set.elements[entry];
      if (element < 1 || element > element_count) {
        return absl::InvalidArgumentError(absl::StrCat(where, ": entry ", entry + 1, ": element ",
                                                       element, " out of range 1..",
                                                       element_count));
      }
      const int type = cells.types[element - 1];
      const int sides = SideCount(type);
      if (sides == 0) {
        return absl::InvalidArgumentError(
            absl::StrCat(where, ": entry ", entry + 1, ": element ", element, " (block ",
                         block_of_cell_[element - 1],
                         ") is not a volume element; getme keeps sides of volume elements only"));
      }
      if (set.sides[entry] < 1 || set.sides[entry] > sides) {
        return absl::InvalidArgumentError(absl::StrCat(where, ": entry ", entry + 1, ": side ",
                                                       set.sides[entry], " out of range 1..", sides,
                                                       " of element ", element));
      }
    }
    if (factors > 0) {
      set.distribution_factors.resize(static_cast<std::size_t>(factors));
      if (Exodus().ex_get_set_dist_fact(exoid_, EX_SIDE_SET, set.id,
                                        set.distribution_factors.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot read its distribution factors"));
      }
    }
    if (entries > 0) {
      std::vector<std::int64_t> node_counts(static_cast<std::size_t>(entries));
      std::vector<std::int64_t> nodes(static_cast<std::size_t>(4 * entries));
      if (Exodus().ex_get_side_set_node_list(exoid_, set.id, node_counts.data(), nodes.data()) <
          0) {
        return ExodusError(absl::StrCat(where, ": cannot list the nodes of its sides"));
      }
      std::int64_t position = 0;
      for (std::int64_t entry = 0; entry < entries; ++entry) {
        const std::int64_t size = node_counts[entry];
        const ExodusSide expected =
            SideNodes(cells.types[set.elements[entry] - 1], static_cast<int>(set.sides[entry]));
        if (size != expected.size || position + size > 4 * entries) {
          return absl::InvalidArgumentError(
              absl::StrCat(where, ": entry ", entry + 1, ": the Exodus library lists ", size,
                           " nodes for side ", set.sides[entry], ", expected ", expected.size));
        }
        std::vector<std::int64_t> face(static_cast<std::size_t>(size));
        for (std::int64_t i = 0; i < size; ++i) {
          const std::int64_t node = nodes[position + i];
          if (node < 1 || node > init_.num_nodes) {
            return absl::InvalidArgumentError(absl::StrCat(where, ": entry ", entry + 1, ": node ",
                                                           node, " out of range 1..",
                                                           init_.num_nodes));
          }
          face[i] = node - 1;
        }
        position += size;
        cells.Add(size == 3 ? kVtkTriangle : kVtkQuad, face);
        block_of_cell_.push_back(-1);
        side_set_of_cell_.push_back(set.id);
      }
    }
    extras_.side_sets.push_back(std::move(set));
  }
  return absl::OkStatus();
}

absl::Status ExodusFileReader::ReadNodeSets() {
  const std::int64_t count = init_.num_node_sets;
  absl::StatusOr<std::vector<std::int64_t>> ids = Ids(EX_NODE_SET, count, "node set");
  if (!ids.ok()) return ids.status();
  absl::StatusOr<std::vector<std::string>> names = Names(EX_NODE_SET, count, "node set");
  if (!names.ok()) return names.status();
  for (std::int64_t k = 0; k < count; ++k) {
    ExodusNodeSet set;
    set.id = (*ids)[k];
    set.name = (*names)[k];
    const std::string where = absl::StrCat("node set ", set.id, Quoted(set.name));
    const absl::StatusOr<SetCounts> counts =
        ReadSetCounts(EX_NODE_SET, set.id, where, "node count");
    if (!counts.ok()) return counts.status();
    const std::int64_t entries = counts->entries;
    const std::int64_t factors = counts->factors;
    set.nodes.resize(static_cast<std::size_t>(entries));
    if (entries > 0 &&
        Exodus().ex_get_set(exoid_, EX_NODE_SET, set.id, set.nodes.data(), nullptr) < 0) {
      return ExodusError(absl::StrCat(where, ": cannot read its nodes"));
    }
    for (std::int64_t entry = 0; entry < entries; ++entry) {
      std::int64_t& node = set.nodes[entry];
      if (node < 1 || node > init_.num_nodes) {
        return absl::InvalidArgumentError(absl::StrCat(where, ": entry ", entry + 1, ": node ",
                                                       node, " out of range 1..", init_.num_nodes));
      }
      --node;
    }
    if (factors > 0) {
      set.distribution_factors.resize(static_cast<std::size_t>(factors));
      if (Exodus().ex_get_set_dist_fact(exoid_, EX_NODE_SET, set.id,
                                        set.distribution_factors.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot read its distribution factors"));
      }
    }
    extras_.node_sets.push_back(std::move(set));
  }
  return absl::OkStatus();
}

absl::Status ExodusFileReader::ReadNumberMaps() {
  // Without a map in the file the library hands out 1..n; only other maps are kept.
  const auto read_map = [&](ex_entity_type type, std::int64_t count, absl::string_view what,
                            std::vector<std::int64_t>* kept) -> absl::Status {
    if (count == 0) return absl::OkStatus();
    std::vector<std::int64_t> map(static_cast<std::size_t>(count));
    if (Exodus().ex_get_id_map(exoid_, type, map.data()) < 0) {
      return ExodusError(absl::StrCat("cannot read the ", what));
    }
    for (std::int64_t k = 0; k < count; ++k) {
      if (map[k] != k + 1) {
        *kept = std::move(map);
        break;
      }
    }
    return absl::OkStatus();
  };
  if (absl::Status status =
          read_map(EX_NODE_MAP, init_.num_nodes, "node number map", &extras_.node_number_map);
      !status.ok()) {
    return status;
  }
  return read_map(EX_ELEM_MAP, init_.num_elem, "element number map", &extras_.element_number_map);
}

void ExodusFileReader::WarnAboutUnread() {
  std::vector<std::string> unread;
  const auto count_of = [&](ex_entity_type type) {
    int count = 0;
    return Exodus().ex_get_variable_param(exoid_, type, &count) < 0 ? 0 : count;
  };
  const std::int64_t steps = Exodus().ex_inquire_int(exoid_, EX_INQ_TIME);
  const int variables = count_of(EX_GLOBAL) + count_of(EX_NODAL) + count_of(EX_ELEM_BLOCK);
  if (variables > 0) {
    unread.push_back(absl::StrCat(variables, " result variables over ", steps, " time steps"));
  }
  const std::int64_t qa = Exodus().ex_inquire_int(exoid_, EX_INQ_QA);
  const std::int64_t info = Exodus().ex_inquire_int(exoid_, EX_INQ_INFO);
  if (qa > 0) unread.push_back(absl::StrCat(qa, " QA records"));
  if (info > 0) unread.push_back(absl::StrCat(info, " info records"));
  const std::int64_t other_sets = init_.num_edge_sets + init_.num_face_sets + init_.num_elem_sets;
  if (other_sets > 0) unread.push_back(absl::StrCat(other_sets, " edge, face or element sets"));
  const std::int64_t other_blocks = init_.num_edge_blk + init_.num_face_blk;
  if (other_blocks > 0) unread.push_back(absl::StrCat(other_blocks, " edge or face blocks"));
  if (!unread.empty()) {
    spdlog::warn("Exodus: not read (getme keeps the mesh, its blocks and sets): {}",
                 absl::StrJoin(unread, ", "));
  }
}

absl::StatusOr<MeshDocument> ExodusFileReader::Read() {
  if (Exodus().ex_get_init_ext(exoid_, &init_) < 0)
    return ExodusError("cannot read the Exodus header");
  if (init_.num_dim != 3) {
    return absl::InvalidArgumentError(
        absl::StrCat("num_dim = ", init_.num_dim, ": getme smooths 3D volume meshes; this file is ",
                     init_.num_dim, "-dimensional"));
  }
  if (init_.num_elem_blk == 0) {
    return absl::InvalidArgumentError("no element blocks: the file holds no elements");
  }
  for (const auto& [count, what] :
       {std::pair{init_.num_nodes, "num_nodes"}, std::pair{init_.num_elem, "num_elem"},
        std::pair{init_.num_elem_blk, "num_el_blk"},
        std::pair{init_.num_side_sets, "num_side_sets"},
        std::pair{init_.num_node_sets, "num_node_sets"}}) {
    if (absl::Status status = CheckCount(count, what); !status.ok()) return status;
  }
  extras_.title = init_.title;
  const std::int64_t used_name_length =
      Exodus().ex_inquire_int(exoid_, EX_INQ_DB_MAX_USED_NAME_LENGTH);
  if (used_name_length > MAX_NAME_LENGTH &&
      Exodus().ex_set_max_name_length(
          exoid_, static_cast<int>(std::min<std::int64_t>(used_name_length, kLongestName))) < 0) {
    return ExodusError("cannot set the name length");
  }
  if (absl::Status status = ReadCoordinates(); !status.ok()) return status;
  if (absl::Status status = ReadBlocks(); !status.ok()) return status;
  if (absl::Status status = ReadSideSets(); !status.ok()) return status;
  if (absl::Status status = ReadNodeSets(); !status.ok()) return status;
  if (absl::Status status = ReadNumberMaps(); !status.ok()) return status;
  WarnAboutUnread();

  document_.format = FileFormat::kExodus;
  document_.as_read.encoding = Encoding::kBinary;
  for (auto& [name, values] : {std::pair{"exodus:block", &block_of_cell_},
                               std::pair{"exodus:sideset", &side_set_of_cell_}}) {
    VtkAttribute attribute;
    attribute.kind = VtkAttributeKind::kScalars;
    attribute.name = name;
    attribute.lookup_table = "default";
    DataArray array;
    array.name = name;
    array.type = VtkDataType::kInt64;
    array.integers = std::move(*values);
    attribute.arrays.push_back(std::move(array));
    document_.grid.cell_data.push_back(std::move(attribute));
  }
  document_.exodus = std::move(extras_);
  return std::move(document_);
}

}  // namespace

absl::StatusOr<MeshDocument> ReadExodus(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::unique_lock<std::mutex> lock = LockExodusLibrary();
  absl::StatusOr<ExodusFile> file = ExodusFile::Open(path);
  if (!file.ok()) return file.status();
  ExodusFileReader reader(file->id(), error ? 0 : static_cast<std::int64_t>(size));
  return reader.Read();
}

absl::StatusOr<MeshDocument> ParseExodus(absl::string_view bytes) {
  absl::StatusOr<TemporaryFile> file = TemporaryFile::Create(".exo");
  if (!file.ok()) return file.status();
  if (absl::Status status = WriteFileAtomically(file->path(), bytes); !status.ok()) return status;
  absl::StatusOr<MeshDocument> document = ReadExodus(file->path());
  if (!document.ok()) {
    // The temporary name means nothing to the caller, who passed bytes.
    return absl::Status(
        document.status().code(),
        absl::StrReplaceAll(document.status().message(), {{file->path(), "the data"}}));
  }
  return document;
}

}  // namespace getme::formats
