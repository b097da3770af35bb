// grpc.health.v1 and server reflection answer. Debian ships no generated stubs for their protos,
// so the test calls them through grpc::GenericStub with hand-encoded protobuf bytes.
#include <algorithm>
#include <string>
#include <vector>

#include "google/protobuf/descriptor.pb.h"
#include "google/protobuf/io/coded_stream.h"
#include "google/protobuf/wire_format_lite.h"
#include "grpcpp/channel.h"
#include "grpcpp/generic/generic_stub.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

using google::protobuf::internal::WireFormatLite;

grpc::ByteBuffer ToBuffer(const std::string& bytes) {
  grpc::Slice slice(bytes);
  return grpc::ByteBuffer(&slice, 1);
}

std::string FromBuffer(const grpc::ByteBuffer& buffer) {
  std::vector<grpc::Slice> slices;
  EXPECT_TRUE(buffer.Dump(&slices).ok());
  std::string bytes;
  for (const auto& slice : slices) {
    bytes.append(reinterpret_cast<const char*>(slice.begin()), slice.size());
  }
  return bytes;
}

// Field `field` of an encoded message: varints as their value, length-delimited as bytes.
struct Fields {
  std::vector<std::uint64_t> varints;
  std::vector<std::string> bytes;
};
Fields ReadField(const std::string& message, int field) {
  Fields fields;
  google::protobuf::io::CodedInputStream input(
      reinterpret_cast<const std::uint8_t*>(message.data()), static_cast<int>(message.size()));
  while (std::uint32_t tag = input.ReadTag()) {
    if (WireFormatLite::GetTagFieldNumber(tag) != field) {
      EXPECT_TRUE(WireFormatLite::SkipField(&input, tag));
      continue;
    }
    if (WireFormatLite::GetTagWireType(tag) == WireFormatLite::WIRETYPE_VARINT) {
      std::uint64_t value = 0;
      EXPECT_TRUE(input.ReadVarint64(&value));
      fields.varints.push_back(value);
    } else {
      std::uint32_t length = 0;
      std::string value;
      EXPECT_TRUE(input.ReadVarint32(&length));
      EXPECT_TRUE(input.ReadString(&value, static_cast<int>(length)));
      fields.bytes.push_back(value);
    }
  }
  return fields;
}

std::string LengthDelimited(int field, const std::string& value) {
  std::string encoded;
  encoded.push_back(static_cast<char>((field << 3) | 2));
  encoded.push_back(static_cast<char>(value.size()));  // short values only
  return encoded + value;
}

void Await(grpc::CompletionQueue& queue, void* expected_tag) {
  void* tag = nullptr;
  bool ok = false;
  ASSERT_TRUE(queue.Next(&tag, &ok));
  EXPECT_EQ(tag, expected_tag);
  EXPECT_TRUE(ok);
}

// One request, one response on the bidirectional reflection stream.
std::string AskReflection(const std::shared_ptr<grpc::Channel>& channel,
                          const std::string& request) {
  grpc::GenericStub stub(channel);
  grpc::ClientContext context;
  grpc::CompletionQueue queue;
  auto call = stub.PrepareCall(
      &context, "/grpc.reflection.v1alpha.ServerReflection/ServerReflectionInfo", &queue);
  int start, write, done, read, finish;
  call->StartCall(&start);
  Await(queue, &start);
  call->Write(ToBuffer(request), &write);
  Await(queue, &write);
  call->WritesDone(&done);
  Await(queue, &done);
  grpc::ByteBuffer response;
  call->Read(&response, &read);
  Await(queue, &read);
  grpc::Status status;
  call->Finish(&status, &finish);
  void* tag = nullptr;
  bool ok = false;
  // The server may end the stream with or without a further empty read.
  while (queue.Next(&tag, &ok) && tag != &finish) {
  }
  EXPECT_TRUE(status.ok()) << status.error_message();
  queue.Shutdown();
  while (queue.Next(&tag, &ok)) {
  }
  return FromBuffer(response);
}

TEST(HealthReflectionTest, HealthCheckAnswersServing) {
  TestServer test = StartTestServer();
  grpc::GenericStub stub(test.channel);
  grpc::CompletionQueue queue;
  for (const std::string service : {"", "getme.v1.Smoother"}) {
    grpc::ClientContext context;
    const std::string request = service.empty() ? "" : LengthDelimited(1, service);
    auto call =
        stub.PrepareUnaryCall(&context, "/grpc.health.v1.Health/Check", ToBuffer(request), &queue);
    call->StartCall();
    grpc::ByteBuffer response;
    grpc::Status status;
    int tag_value;
    call->Finish(&response, &status, &tag_value);
    Await(queue, &tag_value);
    ASSERT_TRUE(status.ok()) << "service '" << service << "': " << status.error_message();
    // HealthCheckResponse.status (field 1): SERVING = 1.
    const Fields fields = ReadField(FromBuffer(response), 1);
    ASSERT_EQ(fields.varints.size(), 1u);
    EXPECT_EQ(fields.varints[0], 1u);
  }
  queue.Shutdown();
}

TEST(HealthReflectionTest, ReflectionListsTheSmootherAndDescribesIt) {
  TestServer test = StartTestServer();
  // ServerReflectionRequest.list_services (field 7).
  const std::string listed = AskReflection(test.channel, LengthDelimited(7, "*"));
  // ServerReflectionResponse.list_services_response (6) → service (1) → name (1).
  std::vector<std::string> names;
  for (const std::string& list : ReadField(listed, 6).bytes) {
    for (const std::string& service : ReadField(list, 1).bytes) {
      names.push_back(ReadField(service, 1).bytes.at(0));
    }
  }
  EXPECT_NE(std::find(names.begin(), names.end(), "getme.v1.Smoother"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "grpc.health.v1.Health"), names.end());

  // file_containing_symbol (4) → file_descriptor_response (4) → file_descriptor_proto (1).
  const std::string described =
      AskReflection(test.channel, LengthDelimited(4, "getme.v1.Smoother"));
  const Fields files = ReadField(described, 4);
  ASSERT_EQ(files.bytes.size(), 1u);
  bool found = false;
  for (const std::string& file : ReadField(files.bytes[0], 1).bytes) {
    google::protobuf::FileDescriptorProto proto;
    ASSERT_TRUE(proto.ParseFromString(file));
    for (const auto& service : proto.service()) {
      if (service.name() != "Smoother") continue;
      found = true;
      std::vector<std::string> methods;
      for (const auto& method : service.method()) methods.push_back(method.name());
      for (const char* expected : {"Smooth", "SubmitJob", "WatchJob", "GetJob", "CancelJob",
                                   "ListJobs", "GetResult", "EvaluateQuality"}) {
        EXPECT_NE(std::find(methods.begin(), methods.end(), expected), methods.end()) << expected;
      }
    }
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace getme::server::testing
