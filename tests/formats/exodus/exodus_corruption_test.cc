// Random corruptions and truncations of real Exodus files must be refused with InvalidArgument
// or read (and then written and read back), never crash: the bytes go through the Exodus, netCDF
// and HDF5 libraries, so this also checks that their failures reach getme as statuses. The
// libFuzzer target fuzz/exodus_fuzzer.cc does the same with coverage feedback (docs/fuzzing.md).

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <iostream>
#include <random>
#include <string>

#include "exodus_test_util.h"
#include "formats/exodus/exodus_reader.h"
#include "formats/exodus/exodus_writer.h"
#include "formats/file_io.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GETME_EXODUS_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define GETME_EXODUS_TEST_ASAN 1
#endif

#ifdef GETME_EXODUS_TEST_ASAN
// AddressSanitizer reserves terabytes of address space for its shadow memory, so the address
// space cap below would stop it from starting; its allocator takes the same cap instead, and
// returns null past it as malloc does under the cap (environment ASAN_OPTIONS add to these).
extern "C" const char* __asan_default_options() {
  return "max_allocation_size_mb=4096:allocator_may_return_null=1";
}
#endif

namespace getme::formats {
namespace {

using testing::ExodusFixture;

struct Outcome {
  int refused = 0;
  int read = 0;
};

void ParseAndRoundTrip(const std::string& bytes, Outcome* outcome) {
  const absl::StatusOr<MeshDocument> document = ParseExodus(bytes);
  if (!document.ok()) {
    ASSERT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument) << document.status();
    ++outcome->refused;
    return;
  }
  ++outcome->read;
  const absl::StatusOr<std::string> written = SerializeExodus(*document, document->as_read);
  if (!written.ok()) {
    ASSERT_EQ(written.status().code(), absl::StatusCode::kInvalidArgument) << written.status();
    return;
  }
  const absl::StatusOr<MeshDocument> again = ParseExodus(*written);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->grid.points.reals.size(), document->grid.points.reals.size());
  EXPECT_EQ(again->exodus->node_sets, document->exodus->node_sets);
}

class ExodusCorruptionTest : public ::testing::TestWithParam<const char*> {};

TEST_P(ExodusCorruptionTest, CorruptedBytesAreRefusedOrRead) {
  // A library that trusts a corrupted size allocates without bound (netCDF did, before
  // CheckNetcdfClassicHeader): cap this process at 4 GB so that shows as a refusal or a failure
  // here, not as the machine's OOM killer (under ASan, through its allocator: above).
#ifndef GETME_EXODUS_TEST_ASAN
  const rlimit limit{4ull << 30, 4ull << 30};
  ASSERT_EQ(setrlimit(RLIMIT_AS, &limit), 0);
#endif
  const absl::StatusOr<std::string> original = ReadFileBytes(ExodusFixture(GetParam()));
  ASSERT_TRUE(original.ok()) << original.status();
  std::mt19937_64 random(20261126);
  Outcome outcome;
  for (int trial = 0; trial < 1500 && !HasFatalFailure(); ++trial) {
    std::string bytes = *original;
    const int changes = 1 + static_cast<int>(random() % 4);
    for (int k = 0; k < changes; ++k) {
      bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
    }
    ParseAndRoundTrip(bytes, &outcome);
  }
  for (std::size_t length = 0; length < original->size() && !HasFatalFailure();
       length += 1 + original->size() / 300) {
    ParseAndRoundTrip(original->substr(0, length), &outcome);
  }
  EXPECT_GT(outcome.refused, 0);
  EXPECT_GT(outcome.read, 0);
  std::cout << GetParam() << ": " << outcome.refused << " refused, " << outcome.read << " read\n";
}

// netCDF-3 only. The netCDF-4 (HDF5) variant, hybrid_netcdf4.exo, crashes Debian's HDF5 1.10.8
// within its first 1,500 corruptions with this seed: an invalid free() in
// H5G__link_release_table, under nc_open (docs/fuzzing.md, "Findings"). getme cannot check an
// HDF5 file before HDF5 parses it, so corrupted netCDF-4 Exodus files are a known crash.
INSTANTIATE_TEST_SUITE_P(NetcdfVariants, ExodusCorruptionTest,
                         ::testing::Values("hybrid.exo", "hybrid_classic.exo"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

}  // namespace
}  // namespace getme::formats
