#pragma once

#include <memory>

#include "getme_server/server_metrics.h"
#include "grpcpp/support/server_interceptor.h"

namespace getme::server {

// Counts every gRPC call by full method name and final status code (getme_rpcs_total), in one
// place instead of at each handler, so health checks and reflection are counted too.
std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface> RpcMetricsInterceptor(
    ServerMetrics& metrics);

}  // namespace getme::server
