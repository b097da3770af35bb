#include "getme_wire/progress.h"

#include "getme_wire/enums.h"

namespace getme::wire {

v1::ProgressEvent ToWireEvent(const ProgressEvent& event) {
  v1::ProgressEvent wire;
  wire.set_phase(ToWirePhase(event.phase));
  wire.set_iteration(event.iteration);
  wire.set_q_min(event.q_min);
  wire.set_q_mean(event.q_mean);
  wire.set_invalid_elements(event.invalid);
  wire.set_reverted_nodes(event.reverted_nodes);
  wire.set_elapsed_seconds(event.elapsed_seconds);
  wire.set_phase_done(event.phase_done);
  return wire;
}

ProgressEvent FromWireProgress(const v1::ProgressEvent& event) {
  ProgressEvent result;
  result.phase = PhaseOrSimultaneous(event.phase());
  result.iteration = event.iteration();
  result.q_min = event.q_min();
  result.q_mean = event.q_mean();
  result.invalid = event.invalid_elements();
  result.reverted_nodes = event.reverted_nodes();
  result.elapsed_seconds = event.elapsed_seconds();
  result.phase_done = event.phase_done();
  return result;
}

}  // namespace getme::wire
