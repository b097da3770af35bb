#include "formats/cgns/cgns_functions.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>

#include "absl/status/statusor.h"
#include "formats/runtime_library.h"

namespace getme::formats::cgns {
namespace {

CgnsFunctions functions;
bool loaded = false;

absl::Status Load() {
  absl::StatusOr<RuntimeLibrary> library =
      RuntimeLibrary::Open("libcgns.so.3.4", "CGNS", "libcgns3.4");
  if (!library.ok()) return library.status();
#define GETME_BIND_CGNS_FUNCTION(name) \
  if (absl::Status status = library->Bind(#name, functions.name); !status.ok()) return status;
  GETME_CGNS_FUNCTIONS(GETME_BIND_CGNS_FUNCTION)
#undef GETME_BIND_CGNS_FUNCTION
  loaded = true;
  return absl::OkStatus();
}

}  // namespace

absl::Status LoadCgnsFunctions() {
  static std::once_flag once;
  static absl::Status status;
  std::call_once(once, [] { status = Load(); });
  return status;
}

const CgnsFunctions& Cgns() {
  if (!loaded) {
    std::fputs("getme: a CGNS function was called before LoadCgnsFunctions\n", stderr);
    std::abort();
  }
  return functions;
}

}  // namespace getme::formats::cgns
