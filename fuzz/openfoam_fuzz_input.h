#pragma once

// The openfoam fuzz target's input: a polyMesh directory in one byte string, its files points,
// faces, owner, neighbour, boundary joined by kPolyMeshSeparator (missing ones are empty), so
// that libFuzzer mutates every file parser and the checks across files at once.
#include <string>
#include <vector>

#include "absl/strings/str_join.h"
#include "absl/strings/str_split.h"
#include "absl/strings/string_view.h"
#include "absl/strings/strip.h"
#include "formats/openfoam/openfoam_reader.h"

namespace getme::fuzz {

inline constexpr absl::string_view kPolyMeshSeparator = "\n@@polyMesh@@\n";

// Files named as they would be on disk; a file starting with gzip's magic bytes is read as
// NAME.gz would be (the reader decides by the bytes).
inline formats::PolyMeshFiles SplitPolyMeshInput(absl::string_view bytes) {
  std::vector<absl::string_view> parts = absl::StrSplit(bytes, kPolyMeshSeparator);
  parts.resize(5);
  return {{"points", std::string(parts[0])},   {"faces", std::string(parts[1])},
          {"owner", std::string(parts[2])},    {"neighbour", std::string(parts[3])},
          {"boundary", std::string(parts[4])}, {}};
}

inline std::string JoinPolyMeshInput(const formats::PolyMeshFiles& files) {
  return absl::StrJoin({files.points.bytes, files.faces.bytes, files.owner.bytes,
                        files.neighbour.bytes, files.boundary.bytes},
                       kPolyMeshSeparator);
}

// The files SerializeOpenFoam wrote, put back in their roles by name ("points.gz" → points).
inline formats::PolyMeshFiles PolyMeshFilesOf(const std::vector<formats::PolyMeshFile>& written) {
  formats::PolyMeshFiles files;
  for (const formats::PolyMeshFile& file : written) {
    const absl::string_view base = absl::StripSuffix(file.name, ".gz");
    if (base == "points") files.points = file;
    if (base == "faces") files.faces = file;
    if (base == "owner") files.owner = file;
    if (base == "neighbour") files.neighbour = file;
    if (base == "boundary") files.boundary = file;
  }
  return files;
}

}  // namespace getme::fuzz
