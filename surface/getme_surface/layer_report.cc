#include "getme_surface/layer_report.h"

#include "getme/mesh/mesh_quality.h"

namespace getme::surface {
namespace {

LayerState StateOf(const LayerHeights& heights) {
  return LayerState{heights.first_min,         heights.first_mean, heights.first_max,
                    heights.mean_lean_degrees, heights.q_min,      heights.q_mean};
}

}  // namespace

LayerHeights MeasureKeptLayers(const Mesh& mesh, const SurfaceSlide& slide, ThreadPool& pool) {
  return MeasureLayerHeights(mesh, slide.layers(), slide.walls(), slide.columns(),
                             ComputeElementQualities(mesh, pool));
}

LayerReport MakeLayerReport(const SurfaceSlide& slide, const LayerHeights& before,
                            const LayerHeights& after) {
  const LayerColumns& columns = slide.layers();
  LayerReport report;
  report.columns = columns.column_count();
  report.column_elements = columns.column_elements();
  report.layer_nodes = static_cast<std::int64_t>(slide.columns().nodes.size());
  report.layers = columns.layers;
  report.conflicting_nodes = columns.conflicting_nodes;
  report.ends_tetrahedron = columns.ends.tetrahedron;
  report.ends_pyramid = columns.ends.pyramid;
  report.ends_prism_side = columns.ends.prism_side;
  report.ends_isotropic = columns.ends.isotropic;
  report.ends_taken = columns.ends.taken;
  report.ends_boundary = columns.ends.boundary;
  report.before = StateOf(before);
  report.after = StateOf(after);
  report.max_height_change = MaxRelativeHeightChange(before, after);
  return report;
}

}  // namespace getme::surface
