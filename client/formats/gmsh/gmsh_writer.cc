#include "formats/gmsh/gmsh_writer.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/gmsh/gmsh_element_type.h"
#include "formats/gmsh/gmsh_layout.h"
#include "formats/vtk_values.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

// Cell arrays the entities and element tags carry; not written as views.
bool IsTagArray(absl::string_view name) {
  return name == "gmsh:physical" || name == "gmsh:geometrical" || name == "medit:ref";
}

// Values in the file's encoding: ASCII numbers separated by spaces, lines ended by Eol(); or
// little-endian binary (Eol() writes nothing).
class Out {
 public:
  explicit Out(bool binary) : binary_(binary) {}

  bool binary() const { return binary_; }
  std::string& text() { return out_; }

  void Line(absl::string_view text) { absl::StrAppend(&out_, text, "\n"); }

  void Int(std::int64_t value) {
    if (binary_) {
      AppendLittle(static_cast<std::uint32_t>(static_cast<std::int32_t>(value)), 4);
    } else {
      Space();
      absl::StrAppend(&out_, value);
    }
  }
  void Size(std::int64_t value) {
    if (binary_) {
      AppendLittle(static_cast<std::uint64_t>(value), 8);
    } else {
      Space();
      absl::StrAppend(&out_, value);
    }
  }
  void Real(double value) {
    if (binary_) {
      AppendLittle(std::bit_cast<std::uint64_t>(value), 8);
    } else {
      Space();
      AppendReal(out_, value);
    }
  }
  void Eol() {
    if (binary_) return;
    out_.push_back('\n');
    line_start_ = true;
  }

  // "$Name\n" opens every section; binary data ends with its own newline before "$EndName".
  void Begin(absl::string_view name) { absl::StrAppend(&out_, "$", name, "\n"); }
  void End(absl::string_view name) {
    if (binary_) out_.push_back('\n');
    absl::StrAppend(&out_, "$End", name, "\n");
  }

 private:
  void Space() {
    if (!line_start_) out_.push_back(' ');
    line_start_ = false;
  }
  void AppendLittle(std::uint64_t value, int size) {
    for (int i = 0; i < size; ++i) out_.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
  }

  bool binary_;
  bool line_start_ = true;
  std::string out_;
};

// One array to write as a view: which grid array, which tags and entries.
struct ViewPlan {
  bool on_nodes = true;
  const DataArray* array = nullptr;
  int component = -1;  // ≥ 0: only this component (an array split into single-component views)
  std::string name;
  const GmshDataView* read = nullptr;  // the section it was read from, if any
};

class Writer {
 public:
  Writer(const MeshDocument& document, const WriteOptions& options, GmshLayout layout)
      : document_(document),
        grid_(document.grid),
        v41_(options.gmsh_version == GmshVersion::k41),
        out_(options.encoding == Encoding::kBinary),
        layout_(std::move(layout)),
        cell_views_on_nodes_(!v41_ && TypeRuns(grid_.cells) > 1) {}

  absl::StatusOr<std::string> Write() {
    if (absl::Status status = Check(); !status.ok()) return status;
    WriteMeshFormat();
    const GmshExtras* extras = document_.gmsh ? &*document_.gmsh : nullptr;
    const bool raw_allowed = extras != nullptr && layout_.keeps_tags &&
                             extras->version_major == (v41_ ? 4 : 2) &&
                             extras->binary == out_.binary() &&
                             (!extras->binary || (!extras->big_endian && extras->data_size == 8));
    std::size_t next_raw = 0;
    std::size_t next_view = 0;
    if (extras != nullptr) {
      for (const std::string& name : extras->section_order) {
        absl::Status status;
        if (name == "MeshFormat") continue;
        if (name == "PhysicalNames") {
          if (!mesh_written_) WritePhysicalNames();
        } else if (name == "Entities" && extras->version_major == 4) {
          if (!mesh_written_) WriteEntities();
        } else if (name == "Nodes" || name == "Elements") {
          status = WriteMesh();
        } else if (name == "NodeData" || name == "ElementData") {
          if (next_view < extras->data_views.size()) {
            status = WriteMesh();
            if (status.ok()) status = WriteReadView(extras->data_views[next_view++]);
          }
        } else if (next_raw < extras->raw_sections.size()) {
          const GmshRawSection& raw = extras->raw_sections[next_raw++];
          // Text sections that refer to no tag fit any variant; $ElementData string tags name
          // $InterpolationScheme's schemes, so it must not be lost.
          const bool portable = raw.name == "Comments" || raw.name == "InterpolationScheme";
          if (raw_allowed || portable) {
            out_.text().append(absl::StrCat("$", raw.name, "\n", raw.body, "$End", raw.name, "\n"));
          } else {
            spdlog::warn(
                "Gmsh: section ${} of the input (MSH {} {}) cannot be carried over to MSH {} {}{}; "
                "it is left out",
                raw.name, extras->version_major == 4 ? "4.1" : "2.2",
                extras->binary ? "binary" : "ASCII", v41_ ? "4.1" : "2.2",
                out_.binary() ? "binary" : "ASCII",
                layout_.keeps_tags ? "" : " with renumbered nodes and elements");
          }
        }
        if (!status.ok()) return status;
      }
    }
    if (absl::Status status = WriteMesh(); !status.ok()) return status;
    if (absl::Status status = WriteNewViews(); !status.ok()) return status;
    if (!grid_.field_data.empty()) {
      std::vector<std::string> names;
      for (const VtkAttribute& attribute : grid_.field_data) {
        for (const DataArray& array : attribute.arrays) names.push_back(array.name);
      }
      spdlog::warn("Gmsh: MSH files have no field data; {} left out", absl::StrJoin(names, ", "));
    }
    return std::move(out_.text());
  }

 private:
  // ---- What binary fields can hold (the layout checked the rest of the model) ----

  absl::Status Check() {
    if (out_.binary() && !v41_) {
      // MSH 2.2 binary tags are ints (4.1's are size_t; views are checked as they are written).
      const auto too_large = [](std::int64_t tag) {
        return tag > std::numeric_limits<std::int32_t>::max();
      };
      for (std::int64_t tag : layout_.node_tags) {
        if (too_large(tag)) return TagError("node", tag);
      }
      for (std::int64_t tag : layout_.element_tags) {
        if (too_large(tag)) return TagError("element", tag);
      }
    }
    return absl::OkStatus();
  }

  static absl::Status TagError(absl::string_view what, std::int64_t tag) {
    return absl::InvalidArgumentError(absl::StrCat(
        what, " tag ", tag, " does not fit the 32-bit int of a binary MSH file; write ASCII"));
  }

  // ---- $MeshFormat, $PhysicalNames, $Entities ----

  void WriteMeshFormat() {
    out_.Begin("MeshFormat");
    out_.Line(absl::StrCat(v41_ ? "4.1" : "2.2", out_.binary() ? " 1 8" : " 0 8"));
    if (out_.binary()) {
      out_.Int(1);
      out_.text().push_back('\n');
    }
    out_.Line("$EndMeshFormat");
  }

  void WritePhysicalNames() {
    if (physical_names_written_) return;
    physical_names_written_ = true;
    if (layout_.physical_names.empty()) return;
    out_.Begin("PhysicalNames");
    out_.Line(absl::StrCat(layout_.physical_names.size()));
    for (const GmshPhysicalName& name : layout_.physical_names) {
      out_.Line(absl::StrCat(name.dim, " ", name.tag, " \"", name.name, "\""));
    }
    out_.Line("$EndPhysicalNames");
  }

  void WriteEntities() {
    if (entities_written_) return;
    entities_written_ = true;
    if (!v41_ || !layout_.write_entities) return;
    out_.Begin("Entities");
    std::int64_t counts[4] = {0, 0, 0, 0};
    for (const GmshEntity& entity : layout_.entities) ++counts[entity.dim];
    for (std::int64_t count : counts) out_.Size(count);
    out_.Eol();
    for (const GmshEntity& entity : layout_.entities) {
      out_.Int(entity.tag);
      for (int k = 0; k < 3; ++k) out_.Real(entity.min[k]);
      if (entity.dim > 0) {
        for (int k = 0; k < 3; ++k) out_.Real(entity.max[k]);
      }
      out_.Size(static_cast<std::int64_t>(entity.physical_tags.size()));
      for (int tag : entity.physical_tags) out_.Int(tag);
      if (entity.dim > 0) {
        out_.Size(static_cast<std::int64_t>(entity.boundary_tags.size()));
        for (int tag : entity.boundary_tags) out_.Int(tag);
      }
      out_.Eol();
    }
    out_.End("Entities");
  }

  // ---- $Nodes and $Elements, with what must precede them ----

  absl::Status WriteMesh() {
    if (mesh_written_) return absl::OkStatus();
    mesh_written_ = true;
    WritePhysicalNames();
    WriteEntities();
    if (v41_) {
      WriteNodes41();
      WriteElements41();
    } else {
      WriteNodes22();
      WriteElements22();
    }
    return absl::OkStatus();
  }

  void WritePoint(std::int64_t i) {
    for (int k = 0; k < 3; ++k) out_.Real(grid_.points.AsDouble(3 * i + k));
  }

  void WriteNodes22() {
    out_.Begin("Nodes");
    const std::int64_t n = grid_.point_count();
    out_.Line(absl::StrCat(n));
    for (std::int64_t i = 0; i < n; ++i) {
      out_.Int(layout_.node_tags[i]);
      WritePoint(i);
      out_.Eol();
    }
    out_.End("Nodes");
  }

  void WriteNodes41() {
    out_.Begin("Nodes");
    const std::int64_t n = grid_.point_count();
    std::int64_t min_tag = 0;
    std::int64_t max_tag = 0;
    for (std::int64_t i = 0; i < n; ++i) {
      min_tag = i == 0 ? layout_.node_tags[i] : std::min(min_tag, layout_.node_tags[i]);
      max_tag = std::max(max_tag, layout_.node_tags[i]);
    }
    out_.Size(static_cast<std::int64_t>(layout_.node_blocks.size()));
    out_.Size(n);
    out_.Size(min_tag);
    out_.Size(max_tag);
    out_.Eol();
    std::int64_t first = 0;
    for (const GmshNodeBlock& block : layout_.node_blocks) {
      out_.Int(block.dim);
      out_.Int(block.tag);
      out_.Int(block.parametric ? 1 : 0);
      out_.Size(block.count);
      out_.Eol();
      for (std::int64_t i = first; i < first + block.count; ++i) {
        out_.Size(layout_.node_tags[i]);
        out_.Eol();
      }
      const int parametric = block.parametric ? block.dim : 0;
      for (std::int64_t i = 0; i < block.count; ++i) {
        WritePoint(first + i);
        for (int k = 0; k < parametric; ++k) out_.Real(block.parametric_coords[i * parametric + k]);
        out_.Eol();
      }
      first += block.count;
    }
    out_.End("Nodes");
  }

  // The cell's nodes in Gmsh's order, as node tags.
  void WriteCellNodes(std::int64_t c, const GmshElementTypeInfo& info, bool size_t_tags) {
    const std::int64_t* nodes = grid_.cells.nodes(c);
    for (int k = 0; k < info.node_count; ++k) {
      const std::int64_t tag = layout_.node_tags[nodes[GmshNodeOfVtkNode(info.code, k)]];
      if (size_t_tags) {
        out_.Size(tag);
      } else {
        out_.Int(tag);
      }
    }
  }

  GmshElementTypeInfo TypeOf(std::int64_t c) const {
    return *GmshElementTypeOfVtk(grid_.cells.types[c]);
  }

  void WriteElements22() {
    out_.Begin("Elements");
    const std::int64_t m = grid_.cells.size();
    out_.Line(absl::StrCat(m));
    const GmshTagLists& lists = layout_.element_tag_lists;
    const auto tag_count = [&](std::int64_t c) { return lists.offsets[c + 1] - lists.offsets[c]; };
    std::int64_t c = 0;
    while (c < m) {
      const GmshElementTypeInfo info = TypeOf(c);
      // Binary: a header per run of elements of one type and tag count.
      std::int64_t run_end = c + 1;
      if (out_.binary()) {
        while (run_end < m && grid_.cells.types[run_end] == grid_.cells.types[c] &&
               tag_count(run_end) == tag_count(c)) {
          ++run_end;
        }
        out_.Int(info.code);
        out_.Int(run_end - c);
        out_.Int(tag_count(c));
      }
      for (; c < run_end; ++c) {
        out_.Int(layout_.element_tags[c]);
        if (!out_.binary()) {
          out_.Int(info.code);
          out_.Int(tag_count(c));
        }
        for (std::int64_t k = lists.offsets[c]; k < lists.offsets[c + 1]; ++k) {
          out_.Int(lists.values[k]);
        }
        WriteCellNodes(c, info, false);
        out_.Eol();
      }
    }
    out_.End("Elements");
  }

  void WriteElements41() {
    out_.Begin("Elements");
    const std::int64_t m = grid_.cells.size();
    const auto same_block = [&](std::int64_t a, std::int64_t b) {
      return grid_.cells.types[a] == grid_.cells.types[b] &&
             layout_.element_entities[a] == layout_.element_entities[b];
    };
    std::int64_t blocks = 0;
    std::int64_t min_tag = 0;
    std::int64_t max_tag = 0;
    for (std::int64_t c = 0; c < m; ++c) {
      if (c == 0 || !same_block(c - 1, c)) ++blocks;
      min_tag = c == 0 ? layout_.element_tags[c] : std::min(min_tag, layout_.element_tags[c]);
      max_tag = std::max(max_tag, layout_.element_tags[c]);
    }
    out_.Size(blocks);
    out_.Size(m);
    out_.Size(min_tag);
    out_.Size(max_tag);
    out_.Eol();
    std::int64_t c = 0;
    while (c < m) {
      std::int64_t run_end = c + 1;
      while (run_end < m && same_block(c, run_end)) ++run_end;
      const GmshElementTypeInfo info = TypeOf(c);
      out_.Int(layout_.element_entities[c].dim);
      out_.Int(layout_.element_entities[c].tag);
      out_.Int(info.code);
      out_.Size(run_end - c);
      out_.Eol();
      for (; c < run_end; ++c) {
        out_.Size(layout_.element_tags[c]);
        WriteCellNodes(c, info, true);
        out_.Eol();
      }
    }
    out_.End("Elements");
  }

  // ---- $NodeData / $ElementData ----

  const DataArray* FindTarget(bool on_nodes, absl::string_view name) const {
    const DataArray* array = FindArray(on_nodes ? grid_.point_data : grid_.cell_data, name);
    const std::int64_t count = on_nodes ? grid_.point_count() : grid_.cells.size();
    if (array == nullptr || array->components < 1 || array->tuple_count() != count ||
        array->value_count() != count * array->components) {
      return nullptr;
    }
    return array;
  }

  absl::Status WriteReadView(const GmshDataView& view) {
    const DataArray* array = FindTarget(view.on_nodes, view.array_name);
    if (array == nullptr) return absl::OkStatus();  // removed from the document: not written
    const std::int64_t count = view.on_nodes ? grid_.point_count() : grid_.cells.size();
    for (std::int64_t target : view.listed) {
      if (target < 0 || target >= count) {
        return absl::InvalidArgumentError(absl::StrCat("inconsistent Gmsh extras: view '",
                                                       view.array_name, "' lists entry ", target));
      }
    }
    written_arrays_.push_back(array);
    ViewPlan plan{view.on_nodes, array, -1, view.array_name, &view};
    return WriteView(plan);
  }

  absl::Status WriteNewViews() {
    for (const bool on_nodes : {true, false}) {
      const std::vector<VtkAttribute>& attributes = on_nodes ? grid_.point_data : grid_.cell_data;
      const std::int64_t count = on_nodes ? grid_.point_count() : grid_.cells.size();
      for (const VtkAttribute& attribute : attributes) {
        for (const DataArray& array : attribute.arrays) {
          if (!on_nodes && IsTagArray(array.name)) continue;
          if (std::find(written_arrays_.begin(), written_arrays_.end(), &array) !=
              written_arrays_.end()) {
            continue;
          }
          if (array.name.find_first_of("\"\n\r") != std::string::npos) {
            return absl::InvalidArgumentError(
                absl::StrCat(on_nodes ? "point" : "cell", " data array name '", array.name,
                             "' has a quote or line break, which a Gmsh string tag cannot hold"));
          }
          if (array.components < 1 || array.value_count() != count * array.components) {
            return absl::InvalidArgumentError(absl::StrCat(
                on_nodes ? "point" : "cell", " data array '", array.name, "' holds ",
                array.value_count(), " values, expected ", count, " × ", array.components));
          }
          if (array.components == 1 || array.components == 3 || array.components == 9) {
            if (absl::Status status = WriteView(ViewPlan{on_nodes, &array, -1, array.name});
                !status.ok()) {
              return status;
            }
            continue;
          }
          spdlog::warn(
              "Gmsh: {} data array '{}' has {} components; Gmsh views hold 1, 3 or 9, so it is "
              "written as {} single-component views '{}[0]'…",
              on_nodes ? "point" : "cell", array.name, array.components, array.components,
              array.name);
          for (int k = 0; k < array.components; ++k) {
            if (absl::Status status =
                    WriteView(ViewPlan{on_nodes, &array, k, absl::StrCat(array.name, "[", k, "]")});
                !status.ok()) {
              return status;
            }
          }
        }
      }
    }
    return absl::OkStatus();
  }

  // The runs of consecutive cells of one type: the cell blocks meshio makes of the $Elements.
  static std::int64_t TypeRuns(const GridCells& cells) {
    std::int64_t runs = 0;
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      if (cell == 0 || cells.types[cell] != cells.types[cell - 1]) ++runs;
    }
    return runs;
  }

  absl::Status WriteView(const ViewPlan& plan) {
    const DataArray& array = *plan.array;
    const bool element_nodes = !plan.on_nodes && cell_views_on_nodes_;
    const int components = plan.component >= 0 ? 1 : array.components;
    const std::int64_t count = plan.on_nodes ? grid_.point_count() : grid_.cells.size();
    const std::vector<std::int64_t>* listed =
        plan.read != nullptr && !plan.read->listed.empty() ? &plan.read->listed : nullptr;
    const std::int64_t entries =
        listed != nullptr ? static_cast<std::int64_t>(listed->size()) : count;
    const std::vector<std::int64_t>& tags =
        plan.on_nodes ? layout_.node_tags : layout_.element_tags;
    if (out_.binary()) {
      for (std::int64_t i = 0; i < entries; ++i) {
        const std::int64_t tag = tags[listed != nullptr ? (*listed)[i] : i];
        if (tag > std::numeric_limits<std::int32_t>::max()) {
          return TagError(plan.on_nodes ? "node" : "element", tag);
        }
      }
    }

    std::vector<std::string> string_tags = {plan.name};
    std::vector<double> real_tags = {0.0};
    std::vector<std::int64_t> integer_tags = {0, components, entries};
    if (plan.read != nullptr) {
      string_tags = plan.read->string_tags;
      if (string_tags.empty()) string_tags.push_back(plan.name);
      real_tags = plan.read->real_tags;
      integer_tags = plan.read->integer_tags;
      integer_tags[1] = components;
      integer_tags[2] = entries;
    }
    const absl::string_view section = plan.on_nodes   ? "NodeData"
                                      : element_nodes ? "ElementNodeData"
                                                      : "ElementData";
    out_.Begin(section);
    out_.Line(absl::StrCat(string_tags.size()));
    for (const std::string& tag : string_tags) out_.Line(absl::StrCat("\"", tag, "\""));
    out_.Line(absl::StrCat(real_tags.size()));
    for (double tag : real_tags) {
      std::string text;
      AppendReal(text, tag);
      out_.Line(text);
    }
    out_.Line(absl::StrCat(integer_tags.size()));
    for (std::int64_t tag : integer_tags) out_.Line(absl::StrCat(tag));
    for (std::int64_t i = 0; i < entries; ++i) {
      const std::int64_t target = listed != nullptr ? (*listed)[i] : i;
      out_.Int(tags[target]);
      const std::int64_t nodes = element_nodes ? grid_.cells.node_count(target) : 1;
      if (element_nodes) out_.Int(nodes);
      for (std::int64_t node = 0; node < nodes; ++node) {
        for (int k = 0; k < components; ++k) {
          const int component = plan.component >= 0 ? plan.component : k;
          out_.Real(array.AsDouble(target * array.components + component));
        }
      }
      out_.Eol();
    }
    out_.End(section);
    return absl::OkStatus();
  }

  const MeshDocument& document_;
  const UnstructuredGrid& grid_;
  bool v41_;
  Out out_;
  GmshLayout layout_;
  bool mesh_written_ = false;
  bool physical_names_written_ = false;
  bool entities_written_ = false;
  std::vector<const DataArray*> written_arrays_;
  // MSH 2.2 cell arrays go to $ElementNodeData when the elements are of more than one type (in
  // grid order, more than one run): see gmsh_writer.h.
  bool cell_views_on_nodes_;
};

}  // namespace

absl::StatusOr<std::string> SerializeGmsh(const MeshDocument& document,
                                          const WriteOptions& options) {
  absl::StatusOr<GmshLayout> layout = BuildGmshLayout(document, options.gmsh_version);
  if (!layout.ok()) return layout.status();
  return Writer(document, options, *std::move(layout)).Write();
}

}  // namespace getme::formats
