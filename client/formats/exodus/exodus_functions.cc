#include "formats/exodus/exodus_functions.h"

#include "formats/runtime_library.h"

namespace getme::formats {
namespace {

absl::Status BindExodusFunctions(const RuntimeLibrary& library, ExodusFunctions& functions) {
#define GETME_BIND_EXODUS_FUNCTION(name) \
  if (absl::Status status = library.Bind(#name, functions.name); !status.ok()) return status;
  GETME_EXODUS_FUNCTIONS(GETME_BIND_EXODUS_FUNCTION)
#undef GETME_BIND_EXODUS_FUNCTION
  // Quiet: no messages on stderr (the statuses carry them), and never EX_ABORT (exit()). A
  // process-wide option of the library, so set once.
  functions.ex_opts(0);
  return absl::OkStatus();
}

LazyFunctionTable<ExodusFunctions>& Table() {
  static LazyFunctionTable<ExodusFunctions> table("libexoIIv2c.so.5", "Exodus II", "libexodusii5",
                                                  &BindExodusFunctions);
  return table;
}

}  // namespace

absl::Status LoadExodusFunctions() { return Table().Load(); }

const ExodusFunctions& Exodus() { return Table().Get(); }

}  // namespace getme::formats
