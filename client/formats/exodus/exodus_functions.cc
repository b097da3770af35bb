#include "formats/exodus/exodus_functions.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>

#include "absl/status/statusor.h"
#include "formats/runtime_library.h"

namespace getme::formats {
namespace {

ExodusFunctions functions;
bool loaded = false;

absl::Status Load() {
  absl::StatusOr<RuntimeLibrary> library =
      RuntimeLibrary::Open("libexoIIv2c.so.5", "Exodus II", "libexodusii5");
  if (!library.ok()) return library.status();
#define GETME_BIND_EXODUS_FUNCTION(name) \
  if (absl::Status status = library->Bind(#name, functions.name); !status.ok()) return status;
  GETME_EXODUS_FUNCTIONS(GETME_BIND_EXODUS_FUNCTION)
#undef GETME_BIND_EXODUS_FUNCTION
  // Quiet: no messages on stderr (the statuses carry them), and never EX_ABORT (exit()). A
  // process-wide option of the library, so set once.
  functions.ex_opts(0);
  loaded = true;
  return absl::OkStatus();
}

}  // namespace

absl::Status LoadExodusFunctions() {
  static std::once_flag once;
  static absl::Status status;
  std::call_once(once, [] { status = Load(); });
  return status;
}

const ExodusFunctions& Exodus() {
  if (!loaded) {
    std::fputs("getme: an Exodus II function was called before LoadExodusFunctions\n", stderr);
    std::abort();
  }
  return functions;
}

}  // namespace getme::formats
