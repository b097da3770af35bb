#include "getme/smoothing/wide_vector_support.h"

#include <cstdint>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace getme {

#if defined(__x86_64__)
namespace {

// Bits of XCR0, the register the OS sets to say which register state it saves on a context
// switch (Intel SDM vol. 1, 13.3): SSE (1) and AVX's upper YMM halves (2); AVX-512's opmask (5),
// upper ZMM halves (6) and ZMM16-31 (7).
constexpr std::uint64_t kAvxState = (1u << 1) | (1u << 2);
constexpr std::uint64_t kAvx512State = kAvxState | (1u << 5) | (1u << 6) | (1u << 7);

std::uint64_t ReadXcr0() {
  std::uint32_t low = 0;
  std::uint32_t high = 0;
  // The instruction itself, not _xgetbv: that intrinsic needs the file compiled with -mxsave.
  __asm__ volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
  return (static_cast<std::uint64_t>(high) << 32) | low;
}

}  // namespace

WideVectorSupport DetectWideVectorSupport() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (__get_cpuid(1, &eax, &ebx, &ecx, &edx) == 0) return {};
  const std::uint32_t leaf1_ecx = ecx;
  const std::uint32_t leaf1_edx = edx;
  if (__get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx) == 0) return {};
  const std::uint32_t leaf7_ebx = ebx;
  // LZCNT is not in Highway's target strings: nothing compiled for them may use it.
  const bool has_all_leaf1 = (leaf1_edx & bit_SSE2) && (leaf1_ecx & bit_SSSE3) &&
                             (leaf1_ecx & bit_SSE4_1) && (leaf1_ecx & bit_SSE4_2) &&
                             (leaf1_ecx & bit_PCLMUL) && (leaf1_ecx & bit_AES) &&
                             (leaf1_ecx & bit_AVX) && (leaf1_ecx & bit_FMA) &&
                             (leaf1_ecx & bit_F16C) && (leaf1_ecx & bit_OSXSAVE);
  if (!has_all_leaf1) return {};
  const bool has_avx2_set =
      (leaf7_ebx & bit_AVX2) && (leaf7_ebx & bit_BMI) && (leaf7_ebx & bit_BMI2);
  const bool has_avx512_set = (leaf7_ebx & bit_AVX512F) && (leaf7_ebx & bit_AVX512VL) &&
                              (leaf7_ebx & bit_AVX512DQ) && (leaf7_ebx & bit_AVX512BW);
  const std::uint64_t xcr0 = ReadXcr0();
  WideVectorSupport support;
  support.avx2 = has_avx2_set && (xcr0 & kAvxState) == kAvxState;
  support.avx512 = support.avx2 && has_avx512_set && (xcr0 & kAvx512State) == kAvx512State;
  return support;
}

#else

WideVectorSupport DetectWideVectorSupport() { return {}; }

#endif

}  // namespace getme
