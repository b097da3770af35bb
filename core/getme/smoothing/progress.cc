#include "getme/smoothing/progress.h"

namespace getme {

const char* PhaseName(Phase phase) {
  switch (phase) {
    case Phase::kUntangle:
      return "untangle";
    case Phase::kSimultaneous:
      return "simultaneous";
    case Phase::kSequential:
      return "sequential";
    case Phase::kWarpage:
      return "warpage";
    case Phase::kSmartLaplace:
      return "smart-laplace";
    case Phase::kLaplace:
      return "laplace";
    case Phase::kPolish:
      return "polish";
    case Phase::kLayers:
      return "layers";
  }
  return "unknown";
}

}  // namespace getme
