#pragma once

namespace getme::formats {

// What only a MEDIT file carries beyond MeshDocument::grid (owned by the MEDIT reader/writer).
struct MeditExtras {};

}  // namespace getme::formats
