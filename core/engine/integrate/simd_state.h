#pragma once

// The engine is compiled for baseline x86-64 (SSE2) while glibc's libm runs AVX/FMA code. Once
// the upper halves of the AVX registers are left dirty (by library code or by the state the
// kernel restores), every switch between the two kinds of code costs a state transition:
// measured here, the members' free update took 640 ns a grain instead of 65 (exp and log
// calls waiting on the transition), a tenth of local steps' wall time. A vzeroupper at the
// start of each hot loop puts the registers back in the clean state; it is a no-op where the
// CPU has no AVX.

namespace sedem {

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx"))) inline void zero_upper_registers() {
  __builtin_ia32_vzeroupper();
}
inline void clean_simd_state() {
  static const bool avx = __builtin_cpu_supports("avx");
  if (avx) zero_upper_registers();
}
#else
inline void clean_simd_state() {}
#endif

}  // namespace sedem
