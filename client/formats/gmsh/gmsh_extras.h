#pragma once

namespace getme::formats {

// What only a Gmsh MSH file carries beyond MeshDocument::grid (owned by the Gmsh reader/writer).
struct GmshExtras {};

}  // namespace getme::formats
