// Four doubles processed at once (AVX2), with glibc's vector math library libmvec for the
// transcendental functions. The constitutive return evaluates PTW's flow stress five times per
// point and step, each with seven log/exp/erf calls: done four points at a time, those calls cost
// about a quarter as much (libmvec's AVX2 variants, documented to 4 ulp).
//
// Lanes are independent: what one lane computes never depends on the others, so a point's result
// does not depend on which points share its batch, nor on the thread count. Code that uses these
// types is compiled for AVX2 through COLDSPRAY_SIMD_TARGET and runs only where
// simd::available() says the processor has AVX2 and FMA; elsewhere the scalar code runs.
// The vector types are GCC/Clang vector extensions: element-wise arithmetic and comparisons, and
// `mask ? a : b` for per-lane selection.
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define COLDSPRAY_HAVE_SIMD 1
#define COLDSPRAY_SIMD_TARGET __attribute__((target("avx2,fma")))
#else
#define COLDSPRAY_HAVE_SIMD 0
#endif

#if COLDSPRAY_HAVE_SIMD

namespace coldspray::simd {

inline constexpr int kLanes = 4;
using Doubles = double __attribute__((vector_size(32)));
using Mask = decltype(Doubles{} < Doubles{});  // a comparison: all bits set where true

// libmvec's AVX2 entry points, named by the x86-64 vector function ABI (glibc >= 2.35 for erf,
// expm1 and log1p).
extern "C" {
COLDSPRAY_SIMD_TARGET Doubles _ZGVdN4v_exp(Doubles);
COLDSPRAY_SIMD_TARGET Doubles _ZGVdN4v_expm1(Doubles);
COLDSPRAY_SIMD_TARGET Doubles _ZGVdN4v_log(Doubles);
COLDSPRAY_SIMD_TARGET Doubles _ZGVdN4v_log1p(Doubles);
COLDSPRAY_SIMD_TARGET Doubles _ZGVdN4v_erf(Doubles);
}

COLDSPRAY_SIMD_TARGET inline Doubles exp(Doubles x) { return _ZGVdN4v_exp(x); }
COLDSPRAY_SIMD_TARGET inline Doubles expm1(Doubles x) { return _ZGVdN4v_expm1(x); }
COLDSPRAY_SIMD_TARGET inline Doubles log(Doubles x) { return _ZGVdN4v_log(x); }
COLDSPRAY_SIMD_TARGET inline Doubles log1p(Doubles x) { return _ZGVdN4v_log1p(x); }
COLDSPRAY_SIMD_TARGET inline Doubles erf(Doubles x) { return _ZGVdN4v_erf(x); }

COLDSPRAY_SIMD_TARGET inline Doubles broadcast(double v) { return Doubles{v, v, v, v}; }
COLDSPRAY_SIMD_TARGET inline Doubles max(Doubles a, Doubles b) { return a > b ? a : b; }
COLDSPRAY_SIMD_TARGET inline Doubles min(Doubles a, Doubles b) { return a < b ? a : b; }
COLDSPRAY_SIMD_TARGET inline Doubles abs(Doubles a) { return a < 0.0 ? -a : a; }
COLDSPRAY_SIMD_TARGET inline bool any(Mask m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

// Whether this processor runs the SIMD code (checked once).
inline bool available() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}

}  // namespace coldspray::simd

#endif
