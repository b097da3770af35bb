#pragma once

#include <functional>
#include <utility>

namespace getme::server {

// Keeps a job's result from expiring until it is destroyed (moved-from holds release nothing).
// Smooth fetches its job's result the moment the job ends, but on a loaded machine that moment can
// come later than a short --result_ttl after the end; the result must not expire under the call
// that is about to send it.
class ResultHold {
 public:
  ResultHold() = default;
  explicit ResultHold(std::function<void()> release) : release_(std::move(release)) {}
  ResultHold(ResultHold&& other) noexcept : release_(std::exchange(other.release_, nullptr)) {}
  ResultHold& operator=(ResultHold&& other) noexcept {
    if (this != &other) {
      Release();
      release_ = std::exchange(other.release_, nullptr);
    }
    return *this;
  }
  ResultHold(const ResultHold&) = delete;
  ResultHold& operator=(const ResultHold&) = delete;
  ~ResultHold() { Release(); }

 private:
  void Release() {
    if (release_) std::exchange(release_, nullptr)();
  }
  std::function<void()> release_;
};

}  // namespace getme::server
