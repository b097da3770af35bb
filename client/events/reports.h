#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "getme/elements/element_type.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme_surface/boundary_surface_counts.h"
#include "getme_surface/layer_report.h"

namespace getme::events {

// What a finished smoothing run reports, in text (summary table) or JSON (result line). Plain
// data, so the gRPC client can fill it from the wire.
struct SmoothReport {
  std::string input;
  std::string output;
  Method method = Method::kGetme;
  std::int64_t nodes = 0;
  std::array<std::int64_t, kElementTypeCount> elements_by_type{};
  std::int64_t passthrough_cells = 0;
  SmoothingResult result;
  std::string boundary = "fixed";  // fixed, free or slide
  // The input's boundary surface as `--boundary slide` saw it (surface/, docs/boundary.md).
  std::optional<surface::BoundarySurfaceCounts> boundary_surface;  // with --boundary slide only
  std::optional<surface::LayerReport> layers;                      // with --keep-layers only
};

// What `getme quality` reports.
struct QualityReport {
  std::string input;
  std::int64_t nodes = 0;
  std::int64_t passthrough_cells = 0;
  MeshQuality quality;
  // The file's cell index of each entry of quality.first_invalid (element ids count volume
  // cells only, so they differ from the cell numbers a viewer shows when surface cells exist).
  std::vector<std::int64_t> first_invalid_cells;
};

}  // namespace getme::events
