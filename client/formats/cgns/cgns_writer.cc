#include "formats/cgns/cgns_writer.h"

#include <cgnslib.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/cgns/cgns_element_type.h"
#include "formats/cgns/cgns_extras.h"
#include "formats/cgns/cgns_functions.h"
#include "formats/cgns/cgns_library.h"
#include "formats/file_io.h"
#include "formats/vtk_cell_type.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

using cgns::Cgns;
using cgns::CgnsPosition;
using cgns::ElementKind;
using cgns::KindOfVtkType;

// More alternations of element types than this, and the typed sections would multiply: one
// MIXED section per part (volume, boundary) is written instead.
constexpr int kMaxTypedSections = 16;

absl::Status Failed(absl::string_view what) {
  return cgns::LibraryError(absl::StatusCode::kInternal, what);
}

// CGNS names are at most 32 characters (SIDS §2.2).
std::string CgnsName(std::string name) {
  if (name.size() > 32) name.resize(32);
  return name;
}

struct Section {
  std::string name;
  bool mixed = false;
  int cgns_type = 0;
  std::int64_t first = 0;  // into the output order
  std::int64_t count = 0;
};

// A boundary condition to write: its elements (output numbers, 1-based) or nodes.
struct Condition {
  std::string name;
  int bc_type = CGNS_ENUMV(BCTypeUserDefined);
  std::string family;
  bool on_nodes = false;
  std::vector<cgsize_t> members;
  CGNS_ENUMT(GridLocation_t) location = CGNS_ENUMV(FaceCenter);
};

class Writer {
 public:
  Writer(const MeshDocument& document, int file) : document_(document), file_(file) {}

  absl::Status Write() {
    if (absl::Status status = Plan(); !status.ok()) return status;
    const CgnsExtras defaults;
    const CgnsExtras& extras = document_.cgns.has_value() ? *document_.cgns : defaults;
    if (Cgns().cg_base_write(file_, CgnsName(extras.base_name).c_str(), 3, 3, &base_) != CG_OK) {
      return Failed("cg_base_write");
    }
    cgsize_t size[3] = {static_cast<cgsize_t>(grid().point_count()),
                        static_cast<cgsize_t>(volume_count_), 0};
    if (Cgns().cg_zone_write(file_, base_, CgnsName(extras.zone_name).c_str(), size,
                             CGNS_ENUMV(Unstructured), &zone_) != CG_OK) {
      return Failed("cg_zone_write");
    }
    if (absl::Status status = WriteCoordinates(); !status.ok()) return status;
    if (absl::Status status = WriteSections(); !status.ok()) return status;
    for (const CgnsFamily& family : extras.families) {
      int index = 0;
      if (Cgns().cg_family_write(file_, base_, CgnsName(family.name).c_str(), &index) != CG_OK) {
        return Failed(absl::StrCat("family '", family.name, "': cg_family_write"));
      }
      int bc = 0;
      if (family.has_bc &&
          Cgns().cg_fambc_write(file_, base_, index, "FamBC",
                                static_cast<CGNS_ENUMT(BCType_t)>(family.bc_type), &bc) != CG_OK) {
        return Failed(absl::StrCat("family '", family.name, "': cg_fambc_write"));
      }
    }
    if (absl::Status status = WriteConditions(); !status.ok()) return status;
    return WriteSolutions();
  }

 private:
  const UnstructuredGrid& grid() const { return document_.grid; }

  // Output order (volume cells first), sections, and the conditions' members.
  absl::Status Plan() {
    const GridCells& cells = grid().cells;
    if (grid().points.components != 3 ||
        grid().points.reals.size() != static_cast<std::size_t>(3 * grid().point_count())) {
      return absl::InvalidArgumentError("points: not 3 real components per point");
    }
    if (grid().point_count() == 0) return absl::InvalidArgumentError("no points");
    if (grid().point_count() > std::numeric_limits<cgsize_t>::max() ||
        static_cast<std::int64_t>(cells.connectivity.size()) + cells.size() >
            std::numeric_limits<cgsize_t>::max()) {
      return absl::InvalidArgumentError(
          "more than 2^31-1 nodes or connectivity entries: this CGNS library build has 32-bit "
          "indices (cgsize_t)");
    }
    std::vector<std::int64_t> others;
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      const std::optional<ElementKind> kind = KindOfVtkType(cells.types[cell]);
      if (!kind.has_value() || cells.node_count(cell) != kind->node_count) {
        const std::optional<VtkCellTypeInfo> info = CellTypeInfo(cells.types[cell]);
        return absl::InvalidArgumentError(
            absl::StrCat("cell ", cell, ": VTK type ", static_cast<int>(cells.types[cell]),
                         info.has_value() ? absl::StrCat(" (", info->name, ")") : std::string(),
                         " with ", cells.node_count(cell), " nodes cannot be written to CGNS (",
                         cgns::kSupportedElementTypes, ")"));
      }
      for (std::int64_t k = 0; k < cells.node_count(cell); ++k) {
        const std::int64_t node = cells.nodes(cell)[k];
        if (node < 0 || node >= grid().point_count()) {
          return absl::InvalidArgumentError(absl::StrCat(
              "cell ", cell, ": node ", node, " out of range 0..", grid().point_count() - 1));
        }
      }
      if (ElementTypeOfCell(cells.types[cell]).has_value()) {
        order_.push_back(cell);
      } else {
        others.push_back(cell);
      }
    }
    volume_count_ = static_cast<std::int64_t>(order_.size());
    if (volume_count_ == 0) {
      return absl::InvalidArgumentError(
          "no volume cells: a CGNS zone of cell dimension 3 needs tetrahedra, pyramids, prisms "
          "or hexahedra");
    }
    if (!others.empty() && others.front() < order_.back()) {
      spdlog::warn(
          "CGNS: the volume cells are written before the {} surface, line and vertex cells, as "
          "the zone's cells come first: cell numbers differ from the input's",
          others.size());
    }
    order_.insert(order_.end(), others.begin(), others.end());
    PlanSections(0, volume_count_, "Volume");
    PlanSections(volume_count_, static_cast<std::int64_t>(order_.size()), "Boundary");
    number_of_.assign(static_cast<std::size_t>(cells.size()), 0);
    for (std::size_t i = 0; i < order_.size(); ++i) {
      number_of_[order_[i]] = static_cast<cgsize_t>(i + 1);
    }
    return PlanConditions();
  }

  void PlanSections(std::int64_t begin, std::int64_t end, const char* part) {
    if (begin == end) return;
    const GridCells& cells = grid().cells;
    std::vector<Section> runs;
    for (std::int64_t i = begin; i < end; ++i) {
      const int cgns_type = KindOfVtkType(cells.types[order_[i]])->cgns_type;
      if (runs.empty() || runs.back().cgns_type != cgns_type) {
        runs.push_back({"", false, cgns_type, i, 0});
      }
      ++runs.back().count;
    }
    if (runs.size() > static_cast<std::size_t>(kMaxTypedSections)) {
      sections_.push_back(
          {absl::StrCat(part, " MIXED"), true, CGNS_ENUMV(MIXED), begin, end - begin});
      return;
    }
    std::map<int, int> seen;
    for (Section& run : runs) {
      const int occurrence = ++seen[run.cgns_type];
      run.name = absl::StrCat(cgns::CgnsTypeName(run.cgns_type),
                              occurrence > 1 ? absl::StrCat(" ", occurrence) : std::string());
      sections_.push_back(std::move(run));
    }
  }

  // The array whose values group the boundary cells, and how to name a group, when the
  // document has no CGNS conditions of its own.
  absl::Status PlanConditions() {
    const GridCells& cells = grid().cells;
    if (document_.cgns.has_value()) {
      const std::vector<CgnsBoundaryCondition>& read = document_.cgns->boundary_conditions;
      for (const CgnsBoundaryCondition& condition : read) {
        Condition out;
        out.name = CgnsName(condition.name);
        out.bc_type = condition.bc_type;
        out.family = condition.family;
        out.on_nodes = condition.on_nodes;
        if (condition.on_nodes) {
          out.location = CGNS_ENUMV(Vertex);
          for (const std::int64_t node : condition.nodes) {
            if (node < 0 || node >= grid().point_count()) {
              return absl::InvalidArgumentError(absl::StrCat("boundary condition '", condition.name,
                                                             "': node ", node, " out of range"));
            }
            out.members.push_back(static_cast<cgsize_t>(node + 1));
          }
        }
        conditions_.push_back(std::move(out));
      }
      const DataArray* owner = FindArray(grid().cell_data, kCgnsBcArray);
      if (owner != nullptr && owner->components == 1 && owner->tuple_count() == cells.size()) {
        for (const std::int64_t cell : order_) {
          const double value = owner->AsDouble(cell);
          if (value == 0) continue;
          if (value < 1 || value > static_cast<double>(conditions_.size()) ||
              conditions_[static_cast<std::size_t>(value) - 1].on_nodes) {
            return absl::InvalidArgumentError(absl::StrCat(
                "cell ", cell, ": ", kCgnsBcArray, " = ", value,
                " names no element boundary condition (there are ", conditions_.size(), ")"));
          }
          conditions_[static_cast<std::size_t>(value) - 1].members.push_back(number_of_[cell]);
        }
      }
      for (Condition& condition : conditions_) {
        if (!condition.on_nodes) condition.location = LocationOf(condition.members);
      }
      return absl::OkStatus();
    }
    for (const char* name : {kCgnsBcArray, "gmsh:physical", "medit:ref"}) {
      const DataArray* tags = FindArray(grid().cell_data, name);
      if (tags == nullptr || tags->components != 1 || tags->tuple_count() != cells.size()) {
        continue;
      }
      std::map<std::int64_t, std::size_t> index_of_tag;
      for (const std::int64_t cell : order_) {
        const int type = cells.types[cell];
        if (type != kVtkTriangle && type != kVtkQuad) continue;
        const auto tag = static_cast<std::int64_t>(tags->AsDouble(cell));
        if (std::string(name) == kCgnsBcArray && tag == 0) continue;
        auto [it, inserted] = index_of_tag.emplace(tag, conditions_.size());
        if (inserted) {
          Condition condition;
          condition.name = CgnsName(GroupName(name, tag));
          conditions_.push_back(std::move(condition));
        }
        conditions_[it->second].members.push_back(number_of_[cell]);
      }
      break;
    }
    return absl::OkStatus();
  }

  std::string GroupName(absl::string_view array, std::int64_t tag) const {
    if (array == "gmsh:physical" && document_.gmsh.has_value()) {
      for (const GmshPhysicalName& physical : document_.gmsh->physical_names) {
        if (physical.dim == 2 && physical.tag == tag) return physical.name;
      }
    }
    if (array == "gmsh:physical") return absl::StrCat("physical ", tag);
    if (array == "medit:ref") return absl::StrCat("ref ", tag);
    return absl::StrCat("bc ", tag);
  }

  // FaceCenter for triangles and quads (SIDS §9.3), EdgeCenter for lines, Vertex for vertex
  // cells; mixed kinds take FaceCenter, what aflr3_to_cgns and most writers use.
  CGNS_ENUMT(GridLocation_t) LocationOf(const std::vector<cgsize_t>& members) const {
    bool lines = !members.empty();
    for (const cgsize_t number : members) {
      lines = lines && grid().cells.types[order_[number - 1]] == 3;
    }
    return lines ? CGNS_ENUMV(EdgeCenter) : CGNS_ENUMV(FaceCenter);
  }

  absl::Status WriteCoordinates() {
    const std::int64_t n = grid().point_count();
    std::vector<double> values(static_cast<std::size_t>(n));
    static constexpr const char* kAxes[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
    for (int axis = 0; axis < 3; ++axis) {
      for (std::int64_t i = 0; i < n; ++i) values[i] = grid().points.reals[3 * i + axis];
      int index = 0;
      if (Cgns().cg_coord_write(file_, base_, zone_, CGNS_ENUMV(RealDouble), kAxes[axis],
                                values.data(), &index) != CG_OK) {
        return Failed(absl::StrCat(kAxes[axis], ": cg_coord_write"));
      }
    }
    return absl::OkStatus();
  }

  absl::Status WriteSections() {
    const GridCells& cells = grid().cells;
    for (const Section& section : sections_) {
      std::vector<cgsize_t> connectivity;
      std::vector<cgsize_t> offsets{0};
      for (std::int64_t i = section.first; i < section.first + section.count; ++i) {
        const std::int64_t cell = order_[i];
        const ElementKind kind = *KindOfVtkType(cells.types[cell]);
        if (section.mixed) connectivity.push_back(kind.cgns_type);
        for (int k = 0; k < kind.node_count; ++k) {
          connectivity.push_back(
              static_cast<cgsize_t>(cells.nodes(cell)[CgnsPosition(kind.vtk_type, k)] + 1));
        }
        offsets.push_back(static_cast<cgsize_t>(connectivity.size()));
      }
      const cgsize_t start = static_cast<cgsize_t>(section.first + 1);
      const cgsize_t end = static_cast<cgsize_t>(section.first + section.count);
      int index = 0;
      const int result =
          section.mixed
              ? Cgns().cg_poly_section_write(file_, base_, zone_, section.name.c_str(),
                                             CGNS_ENUMV(MIXED), start, end, 0, connectivity.data(),
                                             offsets.data(), &index)
              : Cgns().cg_section_write(file_, base_, zone_, section.name.c_str(),
                                        static_cast<CGNS_ENUMT(ElementType_t)>(section.cgns_type),
                                        start, end, 0, connectivity.data(), &index);
      if (result != CG_OK) {
        return Failed(absl::StrCat("section '", section.name, "': cg_section_write"));
      }
    }
    return absl::OkStatus();
  }

  absl::Status WriteConditions() {
    for (Condition& condition : conditions_) {
      const std::string label = absl::StrCat("boundary condition '", condition.name, "'");
      if (condition.members.empty()) {
        // cg_boco_write refuses an empty point set ("Invalid input: npoint=0").
        spdlog::warn("CGNS: {} has no elements or nodes left and is not written", label);
        continue;
      }
      std::sort(condition.members.begin(), condition.members.end());
      const bool contiguous =
          !condition.members.empty() && condition.members.back() - condition.members.front() + 1 ==
                                            static_cast<cgsize_t>(condition.members.size());
      std::vector<cgsize_t> range;
      if (contiguous) range = {condition.members.front(), condition.members.back()};
      const std::vector<cgsize_t>& points = contiguous ? range : condition.members;
      int index = 0;
      if (Cgns().cg_boco_write(file_, base_, zone_, condition.name.c_str(),
                               static_cast<CGNS_ENUMT(BCType_t)>(condition.bc_type),
                               contiguous ? CGNS_ENUMV(PointRange) : CGNS_ENUMV(PointList),
                               static_cast<cgsize_t>(points.size()), points.data(),
                               &index) != CG_OK) {
        return Failed(absl::StrCat(label, ": cg_boco_write"));
      }
      if (Cgns().cg_boco_gridlocation_write(file_, base_, zone_, index, condition.location) !=
          CG_OK) {
        return Failed(absl::StrCat(label, ": cg_boco_gridlocation_write"));
      }
      if (!condition.family.empty()) {
        if (Cgns().cg_goto(file_, base_, "Zone_t", zone_, "ZoneBC_t", 1, "BC_t", index, "end") !=
                CG_OK ||
            Cgns().cg_famname_write(CgnsName(condition.family).c_str()) != CG_OK) {
          return Failed(absl::StrCat(label, ": FamilyName '", condition.family, "'"));
        }
      }
    }
    return absl::OkStatus();
  }

  absl::Status WriteSolutions() {
    std::vector<std::string> skipped;
    std::vector<const DataArray*> point_arrays;
    std::vector<const DataArray*> cell_arrays;
    for (const VtkAttribute& attribute : grid().point_data) {
      for (const DataArray& array : attribute.arrays) {
        if (array.components == 1 && array.tuple_count() == grid().point_count()) {
          point_arrays.push_back(&array);
        } else {
          skipped.push_back(absl::StrCat("point array '", array.name, "'"));
        }
      }
    }
    for (const VtkAttribute& attribute : grid().cell_data) {
      for (const DataArray& array : attribute.arrays) {
        if (array.name == kCgnsBcArray && document_.cgns.has_value()) continue;
        if (array.components == 1 && array.tuple_count() == grid().cells.size()) {
          cell_arrays.push_back(&array);
        } else {
          skipped.push_back(absl::StrCat("cell array '", array.name, "'"));
        }
      }
    }
    if (!grid().field_data.empty()) skipped.push_back("field data");
    if (!skipped.empty()) {
      spdlog::warn("CGNS: not written (one component per point or cell only): {}",
                   absl::StrJoin(skipped, ", "));
    }
    if (!cell_arrays.empty() && volume_count_ < grid().cells.size()) {
      spdlog::warn(
          "CGNS: cell arrays are written for the volume cells only (CellCenter solution); the "
          "values of the {} boundary cells are not stored",
          grid().cells.size() - volume_count_);
    }
    if (absl::Status status = WriteSolution("PointData", CGNS_ENUMV(Vertex), point_arrays, {});
        !status.ok()) {
      return status;
    }
    const std::vector<std::int64_t> volume_cells(order_.begin(), order_.begin() + volume_count_);
    return WriteSolution("CellData", CGNS_ENUMV(CellCenter), cell_arrays, volume_cells);
  }

  // `rows`: which tuples, in order (empty = all).
  absl::Status WriteSolution(const char* name, CGNS_ENUMT(GridLocation_t) location,
                             const std::vector<const DataArray*>& arrays,
                             const std::vector<std::int64_t>& rows) {
    if (arrays.empty()) return absl::OkStatus();
    int solution = 0;
    if (Cgns().cg_sol_write(file_, base_, zone_, name, location, &solution) != CG_OK) {
      return Failed(absl::StrCat("FlowSolution '", name, "': cg_sol_write"));
    }
    for (const DataArray* array : arrays) {
      const std::int64_t count =
          rows.empty() ? array->tuple_count() : static_cast<std::int64_t>(rows.size());
      const auto row = [&](std::int64_t i) { return rows.empty() ? i : rows[i]; };
      int field = 0;
      int result = CG_OK;
      if (IsIntegerType(array->type)) {
        std::vector<cglong_t> values(static_cast<std::size_t>(count));
        for (std::int64_t i = 0; i < count; ++i) values[i] = array->integers[row(i)];
        const bool fits = std::all_of(values.begin(), values.end(), [](cglong_t v) {
          return v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
        });
        if (fits) {
          std::vector<int> narrow(values.begin(), values.end());
          result = Cgns().cg_field_write(file_, base_, zone_, solution, CGNS_ENUMV(Integer),
                                         CgnsName(array->name).c_str(), narrow.data(), &field);
        } else {
          result = Cgns().cg_field_write(file_, base_, zone_, solution, CGNS_ENUMV(LongInteger),
                                         CgnsName(array->name).c_str(), values.data(), &field);
        }
      } else {
        std::vector<double> values(static_cast<std::size_t>(count));
        for (std::int64_t i = 0; i < count; ++i) values[i] = array->reals[row(i)];
        result = Cgns().cg_field_write(file_, base_, zone_, solution, CGNS_ENUMV(RealDouble),
                                       CgnsName(array->name).c_str(), values.data(), &field);
      }
      if (result != CG_OK) {
        return Failed(
            absl::StrCat("FlowSolution '", name, "' field '", array->name, "': cg_field_write"));
      }
    }
    return absl::OkStatus();
  }

  const MeshDocument& document_;
  int file_;
  int base_ = 0;
  int zone_ = 0;
  std::vector<std::int64_t> order_;  // grid cells in output order
  std::vector<cgsize_t> number_of_;  // grid cell → element number (1-based)
  std::int64_t volume_count_ = 0;
  std::vector<Section> sections_;
  std::vector<Condition> conditions_;
};

absl::Status WriteTo(const std::string& path, const MeshDocument& document) {
  std::lock_guard<std::mutex> lock(cgns::LibraryMutex());
  absl::StatusOr<cgns::OpenFile> file = cgns::OpenFile::Open(path, CG_MODE_WRITE);
  if (!file.ok()) return file.status();
  Writer writer(document, file->handle());
  if (absl::Status status = writer.Write(); !status.ok()) return status;
  return file->Close();
}

}  // namespace

absl::Status WriteCgnsFile(const std::string& path, const MeshDocument& document) {
  // As WriteFileAtomically: beside the target, renamed once complete.
  const std::string temporary = path + ".tmp";
  // The library's own message for a file it cannot create is only "cgio_open_file: …": the
  // system's reason (no such directory, permission) comes from creating the file first.
  if (std::FILE* probe = std::fopen(temporary.c_str(), "wb"); probe != nullptr) {
    std::fclose(probe);
  } else {
    const int error = errno;
    return absl::ErrnoToStatus(error, absl::StrCat("cannot create '", temporary, "'"));
  }
  if (absl::Status status = WriteTo(temporary, document); !status.ok()) {
    std::remove(temporary.c_str());
    return status;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    return absl::ErrnoToStatus(error,
                               absl::StrCat("cannot rename '", temporary, "' to '", path, "'"));
  }
  return absl::OkStatus();
}

absl::StatusOr<std::string> SerializeCgns(const MeshDocument& document) {
  absl::StatusOr<cgns::TemporaryFile> temporary = cgns::TemporaryFile::Create();
  if (!temporary.ok()) return temporary.status();
  if (absl::Status status = WriteTo(temporary->path(), document); !status.ok()) return status;
  return ReadFileBytes(temporary->path());
}

}  // namespace getme::formats
