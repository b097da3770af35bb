// AppendInParallel gives the bytes of one serial pass for every thread count, cutting only at
// whole lines; the legacy VTK writer's ASCII output is the same with 1 and several threads.

#include "formats/parallel_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "formats/grid_mesh.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

// Item i as text, with a line break after every `unit` items: the shape of a VTK array.
void FormatItems(std::string& text, std::int64_t begin, std::int64_t end, std::int64_t unit) {
  for (std::int64_t i = begin; i < end; ++i) {
    absl::StrAppend(&text, i * 7919 % 100003, (i + 1) % unit == 0 ? "\n" : " ");
  }
}

TEST(AppendInParallel, SameBytesForEveryThreadCountAndCutsOnlyAtWholeLines) {
  for (const std::int64_t count : {std::int64_t{0}, std::int64_t{1}, kParallelTextItems - 1,
                                   2 * kParallelTextItems + 5, std::int64_t{100001}}) {
    for (const std::int64_t unit : {1, 3, 7}) {
      std::string serial = "head ";
      FormatItems(serial, 0, count, unit);
      for (const int threads : {1, 2, 3, 8}) {
        SCOPED_TRACE(absl::StrCat(count, " items, lines of ", unit, ", ", threads, " threads"));
        std::mutex mutex;
        std::vector<std::pair<std::int64_t, std::int64_t>> runs;
        std::string text = "head ";
        AppendInParallel(text, count, unit, threads,
                         [&](std::string& part, std::int64_t begin, std::int64_t end) {
                           {
                             const std::lock_guard<std::mutex> lock(mutex);
                             runs.emplace_back(begin, end);
                           }
                           FormatItems(part, begin, end, unit);
                         });
        EXPECT_EQ(text, serial);
        std::sort(runs.begin(), runs.end());
        ASSERT_FALSE(runs.empty());
        EXPECT_EQ(runs.front().first, 0);
        EXPECT_EQ(runs.back().second, count);
        for (std::size_t r = 0; r + 1 < runs.size(); ++r) {
          EXPECT_EQ(runs[r].second, runs[r + 1].first);
          EXPECT_EQ(runs[r].second % unit, 0) << "a line cut at item " << runs[r].second;
        }
        // Split where there is enough to split, never more runs than threads.
        const std::int64_t expected_runs =
            std::max<std::int64_t>(1, std::min<std::int64_t>(threads, count / kParallelTextItems));
        EXPECT_EQ(static_cast<std::int64_t>(runs.size()), expected_runs);
      }
    }
  }
}

// cub_wedge_like: 112k cells and 21k points, so every large section is split, with the quality
// arrays the CLI adds (doubles and integers), in the classic layout and in 5.1's.
TEST(SerializeVtkThreads, AsciiBytesDoNotDependOnTheThreadCount) {
  absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(testing::SharedMesh("cub_wedge_like.vtk"));
  ASSERT_TRUE(file.ok()) << file.status();
  absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_TRUE(UpdateGridFromMesh(mesh->mesh, mesh->cell_elements, *file).ok());
  ASSERT_GT(file->cells.size(), 4 * kParallelTextItems);
  for (const int minor : {0, 1}) {
    file->version_major = 5;
    file->version_minor = minor;
    SCOPED_TRACE(absl::StrCat("version 5.", minor));
    const absl::StatusOr<std::string> one = SerializeVtk(*file, Encoding::kAscii, 1);
    ASSERT_TRUE(one.ok()) << one.status();
    for (const int threads : {2, 3, 4}) {
      const absl::StatusOr<std::string> many = SerializeVtk(*file, Encoding::kAscii, threads);
      ASSERT_TRUE(many.ok()) << many.status();
      EXPECT_TRUE(*many == *one) << threads << " threads: the bytes differ";
    }
  }
}

}  // namespace
}  // namespace getme::formats
