#include "formats/runtime_library.h"

#include <dlfcn.h>

#include "absl/strings/str_cat.h"

namespace getme::formats {

absl::StatusOr<RuntimeLibrary> RuntimeLibrary::Open(const char* soname, absl::string_view format,
                                                    absl::string_view package) {
  // RTLD_LOCAL: its symbols serve only the functions bound here; RTLD_NOW: a library that
  // cannot be fully bound fails here, with the loader's message, not at some later call.
  void* handle = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = dlerror();
    return absl::FailedPreconditionError(
        absl::StrCat(format, " files need ", soname, " (Debian package ", package,
                     "), which cannot be loaded: ", reason != nullptr ? reason : "unknown reason"));
  }
  return RuntimeLibrary(handle, soname);
}

absl::StatusOr<void*> RuntimeLibrary::Find(const char* name) const {
  dlerror();  // clear an earlier error: a symbol's value may legitimately be null
  void* symbol = dlsym(handle_, name);
  if (symbol == nullptr) {
    const char* reason = dlerror();
    return absl::InternalError(absl::StrCat(soname_, " has no function ", name, ": ",
                                            reason != nullptr ? reason : "null symbol"));
  }
  return symbol;
}

}  // namespace getme::formats
