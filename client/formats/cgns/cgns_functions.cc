#include "formats/cgns/cgns_functions.h"

#include "formats/runtime_library.h"

namespace getme::formats::cgns {
namespace {

absl::Status BindCgnsFunctions(const RuntimeLibrary& library, CgnsFunctions& functions) {
#define GETME_BIND_CGNS_FUNCTION(name) \
  if (absl::Status status = library.Bind(#name, functions.name); !status.ok()) return status;
  GETME_CGNS_FUNCTIONS(GETME_BIND_CGNS_FUNCTION)
#undef GETME_BIND_CGNS_FUNCTION
  return absl::OkStatus();
}

LazyFunctionTable<CgnsFunctions>& Table() {
  static LazyFunctionTable<CgnsFunctions> table("libcgns.so.3.4", "CGNS", "libcgns3.4",
                                                &BindCgnsFunctions);
  return table;
}

}  // namespace

absl::Status LoadCgnsFunctions() { return Table().Load(); }

const CgnsFunctions& Cgns() { return Table().Get(); }

}  // namespace getme::formats::cgns
