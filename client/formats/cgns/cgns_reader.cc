#include "formats/cgns/cgns_reader.h"

#include <cgnslib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/cgns/cgns_element_type.h"
#include "formats/cgns/cgns_extras.h"
#include "formats/cgns/cgns_functions.h"
#include "formats/cgns/cgns_library.h"
#include "formats/vtk_cell_type.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

using cgns::Cgns;
using cgns::CgnsPosition;
using cgns::CgnsTypeName;
using cgns::ElementKind;
using cgns::KindOfCgnsType;
using cgns::LibraryError;

// Names in CGNS are at most 32 characters (SIDS §2.2); the library writes a terminating NUL.
using Name = char[33];

absl::Status Malformed(absl::string_view what) {
  return LibraryError(absl::StatusCode::kInvalidArgument, what);
}

// Element numbers of the zone (1-based, section ranges) → grid cell indices.
struct SectionRange {
  std::int64_t start = 0;
  std::int64_t end = 0;
  std::int64_t first_cell = 0;
};

// How many bytes one array read from a file may take: counts in a damaged file (a zone of 2^31
// vertices in a 1 kB file) must not make the reader allocate gigabytes before the library says
// the data is not there. HDF5 datasets may be compressed (meshio writes gzip), so the limit is
// generous: 1000 times the file's size, at least 64 MiB.
std::int64_t AllocationLimit(std::int64_t file_bytes) {
  return std::max<std::int64_t>(std::int64_t{64} << 20, 1000 * file_bytes);
}

class ZoneReader {
 public:
  ZoneReader(int file, int base, int zone, std::string zone_label, std::int64_t file_bytes,
             MeshDocument* document)
      : file_(file),
        base_(base),
        zone_(zone),
        zone_label_(std::move(zone_label)),
        file_bytes_(file_bytes),
        document_(*document),
        extras_(*document->cgns) {}

  absl::Status Read() {
    cgsize_t size[3] = {0, 0, 0};
    Name name{};
    if (Cgns().cg_zone_read(file_, base_, zone_, name, size) != CG_OK) {
      return Malformed(absl::StrCat(zone_label_, ": cg_zone_read"));
    }
    if (size[0] <= 0) {
      return absl::InvalidArgumentError(absl::StrCat(zone_label_, ": no vertices"));
    }
    vertex_count_ = size[0];
    if (absl::Status status = CheckSize(zone_label_, "vertices", vertex_count_, 3 * sizeof(double));
        !status.ok()) {
      return status;
    }
    if (absl::Status status = ReadCoordinates(); !status.ok()) return status;
    if (absl::Status status = ReadSections(); !status.ok()) return status;
    if (absl::Status status = ReadBoundaryConditions(); !status.ok()) return status;
    return ReadVertexSolutions();
  }

 private:
  absl::Status ReadCoordinates() {
    int count = 0;
    if (Cgns().cg_ncoords(file_, base_, zone_, &count) != CG_OK) {
      return Malformed(absl::StrCat(zone_label_, ": cg_ncoords"));
    }
    bool all_single = true;
    bool found[3] = {false, false, false};
    for (int c = 1; c <= count; ++c) {
      CGNS_ENUMT(DataType_t) type{};
      Name name{};
      if (Cgns().cg_coord_info(file_, base_, zone_, c, &type, name) != CG_OK) {
        return Malformed(absl::StrCat(zone_label_, ": coordinate ", c, ": cg_coord_info"));
      }
      for (int axis = 0; axis < 3; ++axis) {
        if (std::string(name) == kAxes[axis]) {
          found[axis] = true;
          all_single = all_single && type == CGNS_ENUMV(RealSingle);
        }
      }
    }
    std::vector<std::string> missing;
    for (int axis = 0; axis < 3; ++axis) {
      if (!found[axis]) missing.push_back(kAxes[axis]);
    }
    if (!missing.empty()) {
      return absl::InvalidArgumentError(absl::StrCat(zone_label_, ": GridCoordinates has no ",
                                                     absl::StrJoin(missing, ", "),
                                                     " (getme reads Cartesian coordinates)"));
    }
    const std::int64_t n = vertex_count_;
    DataArray& points = document_.grid.points;
    points.name = "Points";
    points.type = all_single ? VtkDataType::kFloat : VtkDataType::kDouble;
    points.components = 3;
    points.reals.assign(static_cast<std::size_t>(3 * n), 0.0);
    std::vector<double> values(static_cast<std::size_t>(n));
    for (int axis = 0; axis < 3; ++axis) {
      cgsize_t range_min = 1;
      cgsize_t range_max = static_cast<cgsize_t>(n);
      if (Cgns().cg_coord_read(file_, base_, zone_, kAxes[axis], CGNS_ENUMV(RealDouble), &range_min,
                               &range_max, values.data()) != CG_OK) {
        return Malformed(absl::StrCat(zone_label_, ": ", kAxes[axis], ": cg_coord_read"));
      }
      for (std::int64_t i = 0; i < n; ++i) points.reals[3 * i + axis] = values[i];
    }
    return absl::OkStatus();
  }

  absl::Status ReadSections() {
    int count = 0;
    if (Cgns().cg_nsections(file_, base_, zone_, &count) != CG_OK) {
      return Malformed(absl::StrCat(zone_label_, ": cg_nsections"));
    }
    if (count == 0) {
      return absl::InvalidArgumentError(absl::StrCat(zone_label_, ": no element sections"));
    }
    for (int s = 1; s <= count; ++s) {
      if (absl::Status status = ReadSection(s); !status.ok()) return status;
    }
    const std::vector<std::uint8_t>& types = document_.grid.cells.types;
    if (std::none_of(types.begin(), types.end(),
                     [](std::uint8_t type) { return ElementTypeOfCell(type).has_value(); })) {
      return absl::InvalidArgumentError(
          absl::StrCat(zone_label_,
                       ": no volume elements (TETRA_4, PYRA_5, PENTA_6, HEXA_8); getme smooths "
                       "volume meshes"));
    }
    return absl::OkStatus();
  }

  absl::Status ReadSection(int s) {
    Name name{};
    CGNS_ENUMT(ElementType_t) type{};
    cgsize_t start = 0;
    cgsize_t end = 0;
    int boundary_count = 0;
    int parent_flag = 0;
    if (Cgns().cg_section_read(file_, base_, zone_, s, name, &type, &start, &end, &boundary_count,
                               &parent_flag) != CG_OK) {
      return Malformed(absl::StrCat(zone_label_, ": section ", s, ": cg_section_read"));
    }
    const std::string label = absl::StrCat(zone_label_, " section '", name, "'");
    if (start < 1 || end < start) {
      return absl::InvalidArgumentError(
          absl::StrCat(label, ": element range ", start, "..", end, " is empty or not 1-based"));
    }
    const std::int64_t element_count = static_cast<std::int64_t>(end) - start + 1;
    for (const SectionRange& other : ranges_) {
      if (start <= other.end && other.start <= end) {
        return absl::InvalidArgumentError(absl::StrCat(label, ": element range ", start, "..", end,
                                                       " overlaps another section's ", other.start,
                                                       "..", other.end));
      }
    }
    const bool mixed = type == CGNS_ENUMV(MIXED);
    std::optional<ElementKind> kind = KindOfCgnsType(type);
    if (!mixed && !kind.has_value()) {
      return UnsupportedType(label, type);
    }
    cgsize_t data_size = 0;
    if (Cgns().cg_ElementDataSize(file_, base_, zone_, s, &data_size) != CG_OK) {
      return Malformed(absl::StrCat(label, ": cg_ElementDataSize"));
    }
    if (!mixed && data_size != element_count * kind->node_count) {
      return absl::InvalidArgumentError(
          absl::StrCat(label, ": ", data_size, " connectivity entries for ", element_count, " ",
                       CgnsTypeName(type), " elements (", kind->node_count, " each)"));
    }
    // MIXED: at least a type code and one node per element.
    if (mixed && data_size < 2 * element_count) {
      return absl::InvalidArgumentError(absl::StrCat(label, ": ", data_size,
                                                     " connectivity entries cannot hold ",
                                                     element_count, " MIXED elements"));
    }
    if (absl::Status status =
            CheckSize(label, "connectivity entries", data_size + element_count, sizeof(cgsize_t));
        !status.ok()) {
      return status;
    }
    std::vector<cgsize_t> connectivity(static_cast<std::size_t>(data_size));
    std::vector<cgsize_t> offsets;
    if (mixed) {
      offsets.resize(static_cast<std::size_t>(element_count + 1));
      if (Cgns().cg_poly_elements_read(file_, base_, zone_, s, connectivity.data(), offsets.data(),
                                       nullptr) != CG_OK) {
        return Malformed(absl::StrCat(label, ": cg_poly_elements_read"));
      }
    } else if (Cgns().cg_elements_read(file_, base_, zone_, s, connectivity.data(), nullptr) !=
               CG_OK) {
      return Malformed(absl::StrCat(label, ": cg_elements_read"));
    }
    ranges_.push_back({start, end, document_.grid.cells.size()});
    GridCells& cells = document_.grid.cells;
    std::vector<std::int64_t> nodes;
    std::int64_t position = 0;
    for (std::int64_t e = 0; e < element_count; ++e) {
      const std::int64_t number = start + e;
      if (mixed) {
        if (offsets[e] != position || offsets[e + 1] <= offsets[e] || offsets[e + 1] > data_size) {
          return absl::InvalidArgumentError(absl::StrCat(
              label, ": element ", number, ": ElementStartOffset ", offsets[e], "..",
              offsets[e + 1], " does not follow the previous element or exceeds ", data_size));
        }
        const cgsize_t code = connectivity[position];
        kind = KindOfCgnsType(static_cast<int>(code));
        if (!kind.has_value()) {
          return UnsupportedType(absl::StrCat(label, " element ", number), static_cast<int>(code));
        }
        if (offsets[e + 1] - offsets[e] != kind->node_count + 1) {
          return absl::InvalidArgumentError(absl::StrCat(
              label, ": element ", number, " (", CgnsTypeName(kind->cgns_type), ") has ",
              offsets[e + 1] - offsets[e] - 1, " nodes, not ", kind->node_count));
        }
        ++position;
      }
      nodes.assign(static_cast<std::size_t>(kind->node_count), 0);
      for (int k = 0; k < kind->node_count; ++k) {
        const std::int64_t node = connectivity[position + CgnsPosition(kind->vtk_type, k)];
        if (node < 1 || node > vertex_count_) {
          return absl::InvalidArgumentError(absl::StrCat(label, ": element ", number, ": node ",
                                                         node, " out of range 1..", vertex_count_));
        }
        nodes[k] = node - 1;
      }
      position += kind->node_count;
      cells.Add(kind->vtk_type, nodes);
    }
    return absl::OkStatus();
  }

  absl::Status CheckSize(absl::string_view where, absl::string_view what, std::int64_t count,
                         std::size_t value_bytes) const {
    if (count <= AllocationLimit(file_bytes_) / static_cast<std::int64_t>(value_bytes)) {
      return absl::OkStatus();
    }
    return absl::InvalidArgumentError(absl::StrCat(where, ": ", count, " ", what,
                                                   " are more than a file of ", file_bytes_,
                                                   " bytes can hold"));
  }

  absl::Status UnsupportedType(absl::string_view where, int type) const {
    return absl::InvalidArgumentError(absl::StrCat(where, ": ", CgnsTypeName(type),
                                                   " elements are not supported; getme reads ",
                                                   cgns::kSupportedElementTypes));
  }

  // The grid cell of element `number`, or -1.
  // `sorted_ranges_` (by start) must be set: ReadBoundaryConditions does.
  std::int64_t CellOfElement(std::int64_t number) const {
    auto after = std::upper_bound(
        sorted_ranges_.begin(), sorted_ranges_.end(), number,
        [](std::int64_t value, const SectionRange& range) { return value < range.start; });
    if (after == sorted_ranges_.begin()) return -1;
    const SectionRange& range = *std::prev(after);
    return number <= range.end ? range.first_cell + (number - range.start) : -1;
  }

  absl::Status ReadBoundaryConditions() {
    sorted_ranges_ = ranges_;
    std::sort(sorted_ranges_.begin(), sorted_ranges_.end(),
              [](const SectionRange& a, const SectionRange& b) { return a.start < b.start; });
    int count = 0;
    if (Cgns().cg_nbocos(file_, base_, zone_, &count) != CG_OK) {
      return Malformed(absl::StrCat(zone_label_, ": cg_nbocos"));
    }
    const std::int64_t cell_count = document_.grid.cells.size();
    std::vector<std::int64_t> owner(static_cast<std::size_t>(cell_count), 0);
    for (int bc = 1; bc <= count; ++bc) {
      Name name{};
      CGNS_ENUMT(BCType_t) bc_type{};
      CGNS_ENUMT(PointSetType_t) set_type{};
      cgsize_t point_count = 0;
      int normal_index[3] = {0, 0, 0};
      cgsize_t normal_size = 0;
      CGNS_ENUMT(DataType_t) normal_type{};
      int datasets = 0;
      if (Cgns().cg_boco_info(file_, base_, zone_, bc, name, &bc_type, &set_type, &point_count,
                              normal_index, &normal_size, &normal_type, &datasets) != CG_OK) {
        return Malformed(absl::StrCat(zone_label_, ": boundary condition ", bc, ": cg_boco_info"));
      }
      const std::string label = absl::StrCat(zone_label_, " boundary condition '", name, "'");
      CGNS_ENUMT(GridLocation_t) location{};
      if (Cgns().cg_boco_gridlocation_read(file_, base_, zone_, bc, &location) != CG_OK) {
        return Malformed(absl::StrCat(label, ": cg_boco_gridlocation_read"));
      }
      const bool is_range =
          set_type == CGNS_ENUMV(PointRange) || set_type == CGNS_ENUMV(ElementRange);
      const bool is_list = set_type == CGNS_ENUMV(PointList) || set_type == CGNS_ENUMV(ElementList);
      if (!is_range && !is_list) {
        return absl::InvalidArgumentError(
            absl::StrCat(label, ": point set type ", Cgns().cg_PointSetTypeName(set_type),
                         " is not supported (PointList, PointRange, ElementList, ElementRange)"));
      }
      // The library's own writer refuses an empty point set (cg_boco_write: "Invalid input:
      // npoint=0"), so getme could not write such a condition back either.
      if (point_count <= 0 || (is_range && point_count != 2)) {
        return absl::InvalidArgumentError(absl::StrCat(label, ": ", point_count, " values in a ",
                                                       Cgns().cg_PointSetTypeName(set_type)));
      }
      if (absl::Status status = CheckSize(label, "points", point_count, sizeof(cgsize_t));
          !status.ok()) {
        return status;
      }
      std::vector<cgsize_t> points(static_cast<std::size_t>(point_count));
      // The normals, if any, are not wanted: the library skips them for a null pointer.
      if (Cgns().cg_boco_read(file_, base_, zone_, bc, points.data(), nullptr) != CG_OK) {
        return Malformed(absl::StrCat(label, ": cg_boco_read"));
      }
      std::vector<std::int64_t> members;
      if (is_range) {
        if (points[0] > points[1]) {
          return absl::InvalidArgumentError(
              absl::StrCat(label, ": range ", points[0], "..", points[1], " is reversed"));
        }
        for (std::int64_t i = points[0]; i <= points[1]; ++i) members.push_back(i);
      } else {
        members.assign(points.begin(), points.end());
      }
      CgnsBoundaryCondition condition;
      condition.name = name;
      condition.bc_type = bc_type;
      // SIDS §9.3: a BC's PointRange/PointList holds vertices unless GridLocation says a kind of
      // element; the pre-3.1 ElementRange/ElementList always hold elements.
      const bool elements = set_type == CGNS_ENUMV(ElementRange) ||
                            set_type == CGNS_ENUMV(ElementList) || location != CGNS_ENUMV(Vertex);
      const std::int64_t index = static_cast<std::int64_t>(extras_.boundary_conditions.size()) + 1;
      if (elements) {
        for (const std::int64_t number : members) {
          const std::int64_t cell = CellOfElement(number);
          if (cell < 0) {
            return absl::InvalidArgumentError(
                absl::StrCat(label, ": element ", number, " is in no section"));
          }
          if (owner[cell] != 0) {
            return absl::InvalidArgumentError(
                absl::StrCat(label, ": element ", number, " is also in boundary condition '",
                             extras_.boundary_conditions[owner[cell] - 1].name,
                             "' (getme keeps one condition per element)"));
          }
          owner[cell] = index;
        }
      } else {
        condition.on_nodes = true;
        for (const std::int64_t node : members) {
          if (node < 1 || node > vertex_count_) {
            return absl::InvalidArgumentError(
                absl::StrCat(label, ": vertex ", node, " out of range 1..", vertex_count_));
          }
          condition.nodes.push_back(node - 1);
        }
      }
      if (absl::Status status = ReadFamilyName(bc, label, &condition.family); !status.ok()) {
        return status;
      }
      extras_.boundary_conditions.push_back(std::move(condition));
    }
    if (count > 0) {
      VtkAttribute attribute;
      attribute.kind = VtkAttributeKind::kScalars;
      attribute.name = kCgnsBcArray;
      attribute.lookup_table = "default";
      DataArray array;
      array.name = kCgnsBcArray;
      array.type = VtkDataType::kInt32;
      array.integers = std::move(owner);
      attribute.arrays.push_back(std::move(array));
      document_.grid.cell_data.push_back(std::move(attribute));
    }
    return absl::OkStatus();
  }

  absl::Status ReadFamilyName(int bc, absl::string_view label, std::string* family) {
    if (Cgns().cg_goto(file_, base_, "Zone_t", zone_, "ZoneBC_t", 1, "BC_t", bc, "end") != CG_OK) {
      return Malformed(absl::StrCat(label, ": cg_goto"));
    }
    Name name{};
    const int result = Cgns().cg_famname_read(name);
    if (result == CG_NODE_NOT_FOUND) return absl::OkStatus();
    if (result != CG_OK) return Malformed(absl::StrCat(label, ": FamilyName: cg_famname_read"));
    *family = name;
    return absl::OkStatus();
  }

  absl::Status ReadVertexSolutions() {
    int count = 0;
    if (Cgns().cg_nsols(file_, base_, zone_, &count) != CG_OK) {
      return Malformed(absl::StrCat(zone_label_, ": cg_nsols"));
    }
    for (int s = 1; s <= count; ++s) {
      Name name{};
      CGNS_ENUMT(GridLocation_t) location{};
      if (Cgns().cg_sol_info(file_, base_, zone_, s, name, &location) != CG_OK) {
        return Malformed(absl::StrCat(zone_label_, ": solution ", s, ": cg_sol_info"));
      }
      const std::string label = absl::StrCat(zone_label_, " FlowSolution '", name, "'");
      if (location != CGNS_ENUMV(Vertex)) {
        spdlog::warn("{}: GridLocation {} not read (only vertex solutions become point arrays)",
                     label, Cgns().cg_GridLocationName(location));
        continue;
      }
      int field_count = 0;
      if (Cgns().cg_nfields(file_, base_, zone_, s, &field_count) != CG_OK) {
        return Malformed(absl::StrCat(label, ": cg_nfields"));
      }
      for (int f = 1; f <= field_count; ++f) {
        CGNS_ENUMT(DataType_t) type{};
        Name field{};
        if (Cgns().cg_field_info(file_, base_, zone_, s, f, &type, field) != CG_OK) {
          return Malformed(absl::StrCat(label, ": field ", f, ": cg_field_info"));
        }
        const bool integer = type == CGNS_ENUMV(Integer) || type == CGNS_ENUMV(LongInteger);
        DataArray array;
        array.name = field;
        array.type = integer ? VtkDataType::kInt32 : VtkDataType::kDouble;
        if (type == CGNS_ENUMV(LongInteger)) array.type = VtkDataType::kInt64;
        if (type == CGNS_ENUMV(RealSingle)) array.type = VtkDataType::kFloat;
        cgsize_t range_min = 1;
        cgsize_t range_max = static_cast<cgsize_t>(vertex_count_);
        if (integer) {
          std::vector<cglong_t> values(static_cast<std::size_t>(vertex_count_));
          if (Cgns().cg_field_read(file_, base_, zone_, s, field, CGNS_ENUMV(LongInteger),
                                   &range_min, &range_max, values.data()) != CG_OK) {
            return Malformed(absl::StrCat(label, " field '", field, "': cg_field_read"));
          }
          array.integers.assign(values.begin(), values.end());
        } else {
          array.reals.resize(static_cast<std::size_t>(vertex_count_));
          if (Cgns().cg_field_read(file_, base_, zone_, s, field, CGNS_ENUMV(RealDouble),
                                   &range_min, &range_max, array.reals.data()) != CG_OK) {
            return Malformed(absl::StrCat(label, " field '", field, "': cg_field_read"));
          }
        }
        VtkAttribute attribute;
        attribute.kind = VtkAttributeKind::kScalars;
        attribute.name = array.name;
        attribute.lookup_table = "default";
        attribute.arrays.push_back(std::move(array));
        document_.grid.point_data.push_back(std::move(attribute));
      }
    }
    return absl::OkStatus();
  }

  static constexpr const char* kAxes[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};

  int file_;
  int base_;
  int zone_;
  std::string zone_label_;
  std::int64_t file_bytes_;
  MeshDocument& document_;
  CgnsExtras& extras_;
  std::int64_t vertex_count_ = 0;
  std::vector<SectionRange> ranges_;         // in section order
  std::vector<SectionRange> sorted_ranges_;  // by first element number (ranges do not overlap)
};

absl::Status ReadFamilies(int file, int base, absl::string_view base_label, CgnsExtras* extras) {
  int count = 0;
  if (Cgns().cg_nfamilies(file, base, &count) != CG_OK) {
    return Malformed(absl::StrCat(base_label, ": cg_nfamilies"));
  }
  for (int f = 1; f <= count; ++f) {
    CgnsFamily family;
    Name name{};
    int bc_count = 0;
    int geometry_count = 0;
    if (Cgns().cg_family_read(file, base, f, name, &bc_count, &geometry_count) != CG_OK) {
      return Malformed(absl::StrCat(base_label, ": family ", f, ": cg_family_read"));
    }
    family.name = name;
    if (bc_count > 0) {
      Name bc_name{};
      CGNS_ENUMT(BCType_t) bc_type{};
      if (Cgns().cg_fambc_read(file, base, f, 1, bc_name, &bc_type) != CG_OK) {
        return Malformed(absl::StrCat(base_label, " family '", name, "': cg_fambc_read"));
      }
      family.has_bc = true;
      family.bc_type = bc_type;
    }
    extras->families.push_back(std::move(family));
  }
  return absl::OkStatus();
}

absl::StatusOr<MeshDocument> ReadOpenFile(int file, std::int64_t file_bytes) {
  MeshDocument document;
  document.format = FileFormat::kCgns;
  document.as_read.encoding = Encoding::kBinary;
  CgnsExtras& extras = document.cgns.emplace();
  int file_type = CG_FILE_NONE;
  if (Cgns().cg_get_file_type(file, &file_type) != CG_OK) return Malformed("cg_get_file_type");
  extras.file_type = file_type == CG_FILE_HDF5 ? "HDF5" : "ADF";

  int base_count = 0;
  if (Cgns().cg_nbases(file, &base_count) != CG_OK) return Malformed("cg_nbases");
  std::vector<std::string> bases;
  std::vector<int> volume_bases;
  for (int b = 1; b <= base_count; ++b) {
    Name name{};
    int cell_dimension = 0;
    int physical_dimension = 0;
    if (Cgns().cg_base_read(file, b, name, &cell_dimension, &physical_dimension) != CG_OK) {
      return Malformed(absl::StrCat("base ", b, ": cg_base_read"));
    }
    bases.push_back(absl::StrCat("'", name, "' (cell dimension ", cell_dimension, ")"));
    if (cell_dimension == 3 && physical_dimension == 3) volume_bases.push_back(b);
  }
  if (volume_bases.empty()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "no base of cell and physical dimension 3 (bases: ",
        bases.empty() ? "none" : absl::StrJoin(bases, ", "), "); getme smooths volume meshes"));
  }
  if (volume_bases.size() > 1) {
    return absl::InvalidArgumentError(absl::StrCat(volume_bases.size(), " bases of dimension 3 (",
                                                   absl::StrJoin(bases, ", "),
                                                   "); getme reads one"));
  }
  const int base = volume_bases.front();
  Name base_name{};
  int cell_dimension = 0;
  int physical_dimension = 0;
  if (Cgns().cg_base_read(file, base, base_name, &cell_dimension, &physical_dimension) != CG_OK) {
    return Malformed("cg_base_read");
  }
  extras.base_name = base_name;
  const std::string base_label = absl::StrCat("base '", base_name, "'");

  int zone_count = 0;
  if (Cgns().cg_nzones(file, base, &zone_count) != CG_OK) {
    return Malformed(absl::StrCat(base_label, ": cg_nzones"));
  }
  std::vector<std::string> zones;
  std::string first_zone_name;
  for (int z = 1; z <= zone_count; ++z) {
    Name name{};
    cgsize_t size[9] = {};  // a structured zone's three index ranges
    if (Cgns().cg_zone_read(file, base, z, name, size) != CG_OK) {
      return Malformed(absl::StrCat(base_label, ": zone ", z, ": cg_zone_read"));
    }
    if (z == 1) first_zone_name = name;
    zones.push_back(absl::StrCat("'", name, "'"));
  }
  if (zone_count == 0) {
    return absl::InvalidArgumentError(absl::StrCat(base_label, " has no zone"));
  }
  if (zone_count > 1) {
    return absl::InvalidArgumentError(absl::StrCat(
        base_label, " has ", zone_count, " zones (", absl::StrJoin(zones, ", "),
        "); getme reads a single unstructured zone and does not merge zones (their shared "
        "nodes would need the zone connectivity); merge them first"));
  }
  CGNS_ENUMT(ZoneType_t) zone_type{};
  if (Cgns().cg_zone_type(file, base, 1, &zone_type) != CG_OK) {
    return Malformed(absl::StrCat(base_label, " zone ", zones[0], ": cg_zone_type"));
  }
  const std::string zone_label = absl::StrCat("zone ", zones[0]);
  if (zone_type != CGNS_ENUMV(Unstructured)) {
    return absl::InvalidArgumentError(absl::StrCat(zone_label, " is ",
                                                   Cgns().cg_ZoneTypeName(zone_type),
                                                   "; getme reads unstructured zones only"));
  }
  extras.zone_name = first_zone_name;
  if (absl::Status status = ReadFamilies(file, base, base_label, &extras); !status.ok()) {
    return status;
  }
  ZoneReader reader(file, base, 1, zone_label, file_bytes, &document);
  if (absl::Status status = reader.Read(); !status.ok()) return status;
  return document;
}

}  // namespace

absl::StatusOr<MeshDocument> ReadCgnsFile(const std::string& path) {
  std::lock_guard<std::mutex> lock(cgns::LibraryMutex());
  absl::StatusOr<cgns::OpenFile> file = cgns::OpenFile::Open(path, CG_MODE_READ);
  if (!file.ok()) return file.status();
  std::error_code error;
  const auto file_bytes = static_cast<std::int64_t>(std::filesystem::file_size(path, error));
  absl::StatusOr<MeshDocument> document = ReadOpenFile(file->handle(), error ? 0 : file_bytes);
  if (absl::Status status = file->Close(); !status.ok() && document.ok()) return status;
  return document;
}

absl::StatusOr<MeshDocument> ParseCgns(absl::string_view bytes) {
  absl::StatusOr<cgns::TemporaryFile> file = cgns::TemporaryFile::Create();
  if (!file.ok()) return file.status();
  {
    std::ofstream out(file->path(), std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      return absl::UnavailableError(
          absl::StrCat("cannot write the temporary file '", file->path(), "'"));
    }
  }
  return ReadCgnsFile(file->path());
}

}  // namespace getme::formats
