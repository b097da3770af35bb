#pragma once

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::formats {

// A C library opened when a format first needs it (dlopen by its soname) instead of linked.
//
// Why: the Exodus II library pulls in netCDF, HDF5 and Open MPI (with curl, GnuTLS, Kerberos and
// LDAP behind them), and CGNS its own HDF5: some 50 shared libraries whose loading and symbol
// binding cost every `getme` process about 15 ms at start, measured on this project's machine
// (docs/benchmarks.md, "Process start"), although only .exo and .cgns files use them. Opened
// here, they cost only the runs that read or write those files. The handle is never closed:
// the functions bound from it stay valid for the whole process.
class RuntimeLibrary {
 public:
  // FailedPrecondition naming the file format, the library and the Debian package that holds
  // it, with the loader's reason, when it cannot be loaded.
  static absl::StatusOr<RuntimeLibrary> Open(const char* soname, absl::string_view format,
                                             absl::string_view package);

  // Sets `function` to the library's function `name` (found in the library or in the libraries
  // it depends on); INTERNAL naming it when the library has no such symbol.
  template <typename Function>
  absl::Status Bind(const char* name, Function*& function) const {
    absl::StatusOr<void*> symbol = Find(name);
    if (!symbol.ok()) return symbol.status();
    // dlsym returns an object pointer; POSIX guarantees it converts to the function's pointer.
    static_assert(sizeof(function) == sizeof(void*));
    std::memcpy(&function, &*symbol, sizeof(function));
    return absl::OkStatus();
  }

 private:
  RuntimeLibrary(void* handle, std::string soname) : handle_(handle), soname_(std::move(soname)) {}
  absl::StatusOr<void*> Find(const char* name) const;

  void* handle_;
  std::string soname_;
};

// A table of functions (a struct of function pointers) bound from one RuntimeLibrary the first
// time a reader or writer needs it, once per process.
template <typename Functions>
class LazyFunctionTable {
 public:
  // Binds every member of the table from the library; may also set the library's options.
  using Binder = absl::Status (*)(const RuntimeLibrary& library, Functions& functions);

  LazyFunctionTable(const char* soname, const char* format, const char* package, Binder bind)
      : soname_(soname), format_(format), package_(package), bind_(bind) {}

  // Opens and binds on the first call; later calls return the first call's outcome.
  absl::Status Load() {
    std::call_once(once_, [this] {
      absl::StatusOr<RuntimeLibrary> library = RuntimeLibrary::Open(soname_, format_, package_);
      status_ = library.ok() ? bind_(*library, functions_) : library.status();
      loaded_.store(status_.ok(), std::memory_order_release);
    });
    return status_;
  }

  // The bound functions. Only after Load succeeded: called before, it aborts, since every
  // caller would crash on a null function anyway.
  const Functions& Get() const {
    if (!loaded_.load(std::memory_order_acquire)) {
      std::fprintf(stderr, "getme: a %s function was called before its library was loaded\n",
                   format_);
      std::abort();
    }
    return functions_;
  }

 private:
  const char* soname_;
  const char* format_;
  const char* package_;
  Binder bind_;
  std::once_flag once_;
  absl::Status status_;
  std::atomic<bool> loaded_{false};  // read by Get from any thread
  Functions functions_;
};

}  // namespace getme::formats
