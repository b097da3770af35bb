#include "getme_wire/boundary_reports.h"

namespace getme::wire {
namespace {

void ToWireLayerState(const surface::LayerState& state, v1::LayerState& wire) {
  wire.set_first_min(state.first_min);
  wire.set_first_mean(state.first_mean);
  wire.set_first_max(state.first_max);
  wire.set_mean_lean_degrees(state.mean_lean_degrees);
  wire.set_q_min(state.q_min);
  wire.set_q_mean(state.q_mean);
}

surface::LayerState FromWireLayerState(const v1::LayerState& wire) {
  return surface::LayerState{wire.first_min(),         wire.first_mean(), wire.first_max(),
                             wire.mean_lean_degrees(), wire.q_min(),      wire.q_mean()};
}

void ToWireLayerReport(const surface::LayerReport& report, v1::LayerReport& wire) {
  wire.set_columns(report.columns);
  wire.set_column_elements(report.column_elements);
  wire.set_layer_nodes(report.layer_nodes);
  wire.set_layers(report.layers);
  wire.set_conflicting_nodes(report.conflicting_nodes);
  wire.set_ends_tetrahedron(report.ends_tetrahedron);
  wire.set_ends_pyramid(report.ends_pyramid);
  wire.set_ends_prism_side(report.ends_prism_side);
  wire.set_ends_isotropic(report.ends_isotropic);
  wire.set_ends_other_column(report.ends_taken);
  wire.set_ends_boundary(report.ends_boundary);
  ToWireLayerState(report.before, *wire.mutable_before());
  ToWireLayerState(report.after, *wire.mutable_after());
  wire.set_max_height_change(report.max_height_change);
}

surface::LayerReport FromWireLayerReport(const v1::LayerReport& wire) {
  surface::LayerReport report;
  report.columns = wire.columns();
  report.column_elements = wire.column_elements();
  report.layer_nodes = wire.layer_nodes();
  report.layers = wire.layers();
  report.conflicting_nodes = wire.conflicting_nodes();
  report.ends_tetrahedron = wire.ends_tetrahedron();
  report.ends_pyramid = wire.ends_pyramid();
  report.ends_prism_side = wire.ends_prism_side();
  report.ends_isotropic = wire.ends_isotropic();
  report.ends_taken = wire.ends_other_column();
  report.ends_boundary = wire.ends_boundary();
  report.before = FromWireLayerState(wire.before());
  report.after = FromWireLayerState(wire.after());
  report.max_height_change = wire.max_height_change();
  return report;
}

}  // namespace

void AddSurfaceReports(const SurfaceReports& reports, v1::SmoothResult& result) {
  if (reports.boundary_surface) {
    v1::BoundarySlideReport& slide = *result.mutable_boundary_slide();
    slide.set_feature_edges(reports.boundary_surface->feature_edges);
    slide.set_feature_curves(reports.boundary_surface->feature_curves);
    slide.set_corners(reports.boundary_surface->corners);
    slide.set_surface_groups(reports.boundary_surface->surface_groups);
    slide.set_interior_grouped_faces(reports.boundary_surface->interior_grouped_faces);
  }
  if (reports.layers) ToWireLayerReport(*reports.layers, *result.mutable_layers());
}

SurfaceReports FromWireSurfaceReports(const v1::SmoothResult& result) {
  SurfaceReports reports;
  if (result.boundary() == v1::BOUNDARY_SLIDE && result.has_boundary_slide()) {
    const v1::BoundarySlideReport& slide = result.boundary_slide();
    reports.boundary_surface = surface::BoundarySurfaceCounts{
        slide.feature_edges(), slide.feature_curves(), slide.corners(), slide.surface_groups(),
        slide.interior_grouped_faces()};
  }
  if (result.has_layers()) reports.layers = FromWireLayerReport(result.layers());
  return reports;
}

}  // namespace getme::wire
