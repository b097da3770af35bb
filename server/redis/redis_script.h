#pragma once

#include <string>

namespace getme::redis {

// A Lua script and its SHA-1, the name Redis caches it under: RedisClient::Eval sends the SHA-1
// (EVALSHA) and the source only when the server does not know it yet (after a restart or
// SCRIPT FLUSH). Build each script once, e.g. as a static, not per call.
class RedisScript {
 public:
  explicit RedisScript(std::string source);

  const std::string& source() const { return source_; }
  // Lower-case hex, as SCRIPT LOAD answers.
  const std::string& sha1() const { return sha1_; }

 private:
  std::string source_;
  std::string sha1_;
};

}  // namespace getme::redis
