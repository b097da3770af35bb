#include "getme_server/rpc_metrics_interceptor.h"

#include <string>

#include "absl/status/status.h"

namespace getme::server {
namespace {

class CountingInterceptor final : public grpc::experimental::Interceptor {
 public:
  CountingInterceptor(ServerMetrics& metrics, const char* method)
      : metrics_(metrics), method_(method == nullptr ? "" : method) {}

  void Intercept(grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(
            grpc::experimental::InterceptionHookPoints::PRE_SEND_STATUS)) {
      // Abseil's canonical codes are gRPC's, value for value: reuse their names.
      const auto code = static_cast<absl::StatusCode>(methods->GetSendStatus().error_code());
      metrics_.CountRpc(method_, absl::StatusCodeToString(code));
    }
    methods->Proceed();
  }

 private:
  ServerMetrics& metrics_;
  std::string method_;
};

class CountingInterceptorFactory final
    : public grpc::experimental::ServerInterceptorFactoryInterface {
 public:
  explicit CountingInterceptorFactory(ServerMetrics& metrics) : metrics_(metrics) {}

  grpc::experimental::Interceptor* CreateServerInterceptor(
      grpc::experimental::ServerRpcInfo* info) override {
    return new CountingInterceptor(metrics_, info->method());
  }

 private:
  ServerMetrics& metrics_;
};

}  // namespace

std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface> RpcMetricsInterceptor(
    ServerMetrics& metrics) {
  return std::make_unique<CountingInterceptorFactory>(metrics);
}

}  // namespace getme::server
