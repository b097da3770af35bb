// Writes legacy .vtk files as .vtu in every layout, for check_meshio_reads_ours.py:
//   vtu_write_samples OUTPUT_DIR INPUT.vtk...
// writes OUTPUT_DIR/<input stem>.<layout>.vtu. Exit status 1 on any failure.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "formats/vtk_reader.h"
#include "formats/vtu/vtu_writer.h"

namespace {

using getme::formats::Encoding;
using getme::formats::GmshVersion;
using getme::formats::VtuLayout;
using getme::formats::WriteOptions;

struct Layout {
  const char* name;
  WriteOptions options;
};

const Layout kLayouts[] = {
    {"ascii", {Encoding::kAscii, GmshVersion::k41, VtuLayout::kInline, false}},
    {"inline", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kInline, false}},
    {"inline_zlib", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kInline, true}},
    {"appended", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kAppended, false}},
    {"appended_zlib", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kAppended, true}},
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR INPUT.vtk...\n", argv[0]);
    return 2;
  }
  const std::filesystem::path output = argv[1];
  std::filesystem::create_directories(output);
  for (int i = 2; i < argc; ++i) {
    const absl::StatusOr<getme::formats::UnstructuredGrid> file =
        getme::formats::ReadVtkFile(argv[i]);
    if (!file.ok()) {
      std::fprintf(stderr, "%s\n", std::string(file.status().message()).c_str());
      return 1;
    }
    getme::formats::MeshDocument document;
    document.grid = *file;
    for (const Layout& layout : kLayouts) {
      const absl::StatusOr<std::string> bytes =
          getme::formats::SerializeVtu(document, layout.options);
      const std::filesystem::path path =
          output / (std::filesystem::path(argv[i]).stem().string() + "." + layout.name + ".vtu");
      if (!bytes.ok()) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(),
                     std::string(bytes.status().message()).c_str());
        return 1;
      }
      std::ofstream(path, std::ios::binary) << *bytes;
    }
  }
  return 0;
}
