#pragma once

#include <cstddef>

#include "absl/strings/string_view.h"

namespace getme::server {

// The dashboard's static files (web/), compiled into the binary by CMake (server/embed_web.cmake)
// so a container or a copied binary needs nothing beside it.
struct DashboardAsset {
  absl::string_view path;  // URL path, e.g. "/" or "/dashboard.js"
  absl::string_view content_type;
  absl::string_view content;
};

// nullptr when no asset has that path.
const DashboardAsset* FindDashboardAsset(absl::string_view path);

}  // namespace getme::server
