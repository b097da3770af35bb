#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "formats/mesh_document.h"

namespace getme::formats::testing {

// A case directory of write_fixtures.py's output (OPENFOAM_FIXTURES/name).
std::string CasePath(const std::string& name);
std::string FixturePath(const std::string& name);

// NAME.checkMesh: checkMesh's counts ("hexahedra" → 24, "patch xmin" → 9).
std::map<std::string, std::int64_t> CheckMeshCounts(const std::string& name);

// The number of grid cells of each VTK type.
std::map<int, std::int64_t> CellTypeCounts(const UnstructuredGrid& grid);

// The values of the integer array `name` of `attributes`; empty if there is none.
std::vector<std::int64_t> IntegerArray(const std::vector<VtkAttribute>& attributes,
                                       const std::string& name);

std::string ReadText(const std::string& path);
void WriteText(const std::string& path, const std::string& text);

}  // namespace getme::formats::testing
