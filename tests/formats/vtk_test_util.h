#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/unstructured_grid.h"

namespace getme::formats::testing {

// Paths of the shared Mesquite meshes (read-only).
std::string SharedMesh(const std::string& name);
std::vector<std::string> AllSharedMeshNames();

std::string ReadText(const std::string& path);

// The file's declared count after a keyword at the start of a line ("POINTS 45 float" → 45),
// found by plain text search, independently of the reader; -1 if absent.
std::int64_t DeclaredCount(const std::string& text, const std::string& keyword);
// All numbers on that line ("CELLS 16 144" → {16, 144}); empty if absent.
std::vector<std::int64_t> DeclaredNumbers(const std::string& text, const std::string& keyword);

// Asserts (gtest) that two files hold the same points (bit for bit), cells and attributes.
// Array types may differ only by float → double promotion.
void ExpectSameContent(const UnstructuredGrid& expected, const UnstructuredGrid& actual);

}  // namespace getme::formats::testing
