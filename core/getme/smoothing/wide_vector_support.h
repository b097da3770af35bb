#pragma once

namespace getme {

// Whether this CPU, and the operating system on it, run the code Highway compiles for its AVX2
// and AVX3 (AVX-512) targets (element_passes_dispatch.cc).
//
// Highway's own check, hwy::SupportedTargets, lives in libhwy.so, whose loading calibrates a
// timer and cost every process that links it about 4 ms at start (docs/design.md, "Why Google
// Highway, and why only for dispatch"). So the same test is made here, for exactly the
// instruction sets hwy/ops/set_macros-inl.h compiles each target with (HWY_TARGET_STR_AVX2,
// HWY_TARGET_STR_AVX3), and tests/elements compares it with hwy::SupportedTargets.
struct WideVectorSupport {
  bool avx2 = false;    // SSSE3, SSE4.1/4.2, PCLMUL, AES, AVX, AVX2, BMI1/2, FMA, F16C
  bool avx512 = false;  // the above and AVX-512 F, VL, DQ, BW
};

// CPUID for the instruction sets and XGETBV for the OS's saving of the YMM, ZMM and opmask
// registers: a CPU feature the OS does not enable faults like a missing one. All false on
// other architectures.
WideVectorSupport DetectWideVectorSupport();

}  // namespace getme
