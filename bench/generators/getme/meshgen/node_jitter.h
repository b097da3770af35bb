#pragma once

#include <cstdint>
#include <span>

#include "getme/meshgen/mesh_draft.h"

namespace getme::meshgen {

struct JitterStats {
  std::int64_t moved = 0;      // nodes moved by their full random displacement
  std::int64_t shortened = 0;  // nodes moved by a halved displacement after a rejection
  std::int64_t kept = 0;       // nodes left in place: every tried displacement broke an element
};

// Moves node i by a random displacement with components uniform in [-max_move[i], max_move[i]]
// (max_move[i] == 0: the node stays, e.g. on the outer boundary). A move that makes an adjacent
// element invalid (Def. 2) is retried at half the length, a few times, then abandoned, so every
// element that was valid stays valid. Exactly three engine draws per node in node order, whatever
// happens to the move, so a given seed gives the same mesh on every platform.
JitterStats JitterNodes(MeshDraft& draft, std::span<const double> max_move, std::uint64_t seed);

}  // namespace getme::meshgen
