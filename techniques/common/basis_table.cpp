// The combine and normal kernels of basis_table.h, one per instruction set. The project
// builds for generic x86-64 (the float twins must not contract to FMA, bezier_eval.h), so
// the AVX2 and AVX-512 kernels are compiled for their targets function by function and
// picked at run time.
//
// Register blocking: a kernel keeps the x, y, z sums of several point blocks in registers
// and, per control point, broadcasts its three coordinates once and loads one weight
// vector per block. Four AVX-512 blocks give 12 independent accumulators: enough to cover
// the FMA latency (4 cycles, 2 pipes) with 7 loads per 12 multiply-adds.
#include "techniques/common/basis_table.h"

#include <cassert>
#include <cmath>
#include <utility>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define TB_X86_KERNELS 1
#else
#define TB_X86_KERNELS 0
#endif

namespace tb::techniques {
namespace {

// Arguments shared by every combine kernel.
struct CombineArgs {
  const double* weights;  // BasisTable::data()
  size_t control_points;
  size_t blocks;
  const mesh::Vec3d* control;
  double* out[3];
};

void combinePortable(const CombineArgs& a) {
  constexpr size_t L = kBatchLanes;
  for (size_t b = 0; b < a.blocks; ++b) {
    double sum[3][L] = {};
    const double* w = a.weights + b * a.control_points * L;
    for (size_t k = 0; k < a.control_points; ++k, w += L) {
      const double c[3] = {a.control[k].x, a.control[k].y, a.control[k].z};
      for (int axis = 0; axis < 3; ++axis) {
        for (size_t lane = 0; lane < L; ++lane) sum[axis][lane] += w[lane] * c[axis];
      }
    }
    for (int axis = 0; axis < 3; ++axis) {
      for (size_t lane = 0; lane < L; ++lane) a.out[axis][b * L + lane] = sum[axis][lane];
    }
  }
}

void normalsPortable(const std::array<AlignedDoubles, 3>& du,
                     const std::array<AlignedDoubles, 3>& dv, std::array<AlignedDoubles, 3>& normal,
                     size_t points) {
  for (size_t i = 0; i < points; ++i) {
    BatchPoints::set(normal, i, normalize(cross(BatchPoints::at(du, i), BatchPoints::at(dv, i))));
  }
}

#if TB_X86_KERNELS

// `Blocks` blocks of 8 points starting at block `first`. `kControlPoints` is the
// table's control point count when known at compile time (0: read at run time): the
// loop over them is then unrolled whole, with no loop exit to mispredict per block group.
template <int Blocks, size_t kControlPoints>
__attribute__((target("avx512f"), always_inline)) inline void combineBlocksAvx512(
    const CombineArgs& a, size_t first) {
  constexpr size_t L = kBatchLanes;
  const size_t control_points = kControlPoints != 0 ? kControlPoints : a.control_points;
  const size_t stride = control_points * L;
  const double* w = a.weights + first * stride;
  __m512d x[Blocks], y[Blocks], z[Blocks];
  for (int i = 0; i < Blocks; ++i) x[i] = y[i] = z[i] = _mm512_setzero_pd();
#pragma GCC unroll 20
  for (size_t k = 0; k < control_points; ++k) {
    const __m512d cx = _mm512_set1_pd(a.control[k].x);
    const __m512d cy = _mm512_set1_pd(a.control[k].y);
    const __m512d cz = _mm512_set1_pd(a.control[k].z);
    for (int i = 0; i < Blocks; ++i) {
      __m512d wi = _mm512_load_pd(w + i * stride + k * L);
      // Keeps the weights in a register: GCC otherwise folds the load into each of the
      // three FMAs, tripling the 512-bit loads (3 per FMA group instead of 1).
      asm("" : "+v"(wi));
      x[i] = _mm512_fmadd_pd(wi, cx, x[i]);
      y[i] = _mm512_fmadd_pd(wi, cy, y[i]);
      z[i] = _mm512_fmadd_pd(wi, cz, z[i]);
    }
  }
  for (int i = 0; i < Blocks; ++i) {
    const size_t at = (first + i) * L;
    _mm512_store_pd(a.out[0] + at, x[i]);
    _mm512_store_pd(a.out[1] + at, y[i]);
    _mm512_store_pd(a.out[2] + at, z[i]);
  }
}

template <size_t kControlPoints>
__attribute__((target("avx512f"))) void combineAvx512(const CombineArgs& a) {
  size_t b = 0;
  for (; b + 4 <= a.blocks; b += 4) combineBlocksAvx512<4, kControlPoints>(a, b);
  switch (a.blocks - b) {
    case 3:
      return combineBlocksAvx512<3, kControlPoints>(a, b);
    case 2:
      return combineBlocksAvx512<2, kControlPoints>(a, b);
    case 1:
      return combineBlocksAvx512<1, kControlPoints>(a, b);
    default:
      return;
  }
}

// The control point counts of the shipped kernels (acc 16 and 12, Gregory 20 and 15)
// get their own unrolled copies.
__attribute__((target("avx512f"))) void combineAvx512(const CombineArgs& a) {
  switch (a.control_points) {
    case 12:
      return combineAvx512<12>(a);
    case 15:
      return combineAvx512<15>(a);
    case 16:
      return combineAvx512<16>(a);
    case 20:
      return combineAvx512<20>(a);
    default:
      return combineAvx512<0>(a);
  }
}

// Two 4-lane halves per block; `Blocks` blocks at a time (2 blocks: 12 accumulators of
// the 16 ymm registers).
template <int Blocks>
__attribute__((target("avx2,fma"))) inline void combineBlocksAvx2(const CombineArgs& a,
                                                                  size_t first) {
  constexpr size_t L = kBatchLanes;
  constexpr int kHalves = 2 * Blocks;
  const size_t stride = a.control_points * L;
  const double* w = a.weights + first * stride;
  __m256d x[kHalves], y[kHalves], z[kHalves];
  for (int i = 0; i < kHalves; ++i) x[i] = y[i] = z[i] = _mm256_setzero_pd();
  for (size_t k = 0; k < a.control_points; ++k, w += L) {
    const __m256d cx = _mm256_broadcast_sd(&a.control[k].x);
    const __m256d cy = _mm256_broadcast_sd(&a.control[k].y);
    const __m256d cz = _mm256_broadcast_sd(&a.control[k].z);
    for (int i = 0; i < kHalves; ++i) {
      __m256d wi = _mm256_load_pd(w + (i / 2) * stride + (i % 2) * 4);
      asm("" : "+x"(wi));  // one load per weight vector, as in the AVX-512 kernel
      x[i] = _mm256_fmadd_pd(wi, cx, x[i]);
      y[i] = _mm256_fmadd_pd(wi, cy, y[i]);
      z[i] = _mm256_fmadd_pd(wi, cz, z[i]);
    }
  }
  for (int i = 0; i < kHalves; ++i) {
    const size_t at = first * L + size_t(i) * 4;
    _mm256_store_pd(a.out[0] + at, x[i]);
    _mm256_store_pd(a.out[1] + at, y[i]);
    _mm256_store_pd(a.out[2] + at, z[i]);
  }
}

__attribute__((target("avx2,fma"))) void combineAvx2(const CombineArgs& a) {
  size_t b = 0;
  for (; b + 2 <= a.blocks; b += 2) combineBlocksAvx2<2>(a, b);
  for (; b < a.blocks; ++b) combineBlocksAvx2<1>(a, b);
}

// The cross product rounds each product, as cross() does (fp-contract off: GCC would fuse
// the product and the difference), so parallel tangents give exactly zero and the normal
// stays zero there.
__attribute__((target("avx512f"), optimize("fp-contract=off"))) void normalsAvx512(
    const std::array<AlignedDoubles, 3>& du, const std::array<AlignedDoubles, 3>& dv,
    std::array<AlignedDoubles, 3>& normal, size_t blocks) {
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
  for (size_t at = 0; at < blocks * kBatchLanes; at += kBatchLanes) {
    const __m512d ux = _mm512_load_pd(du[0].data() + at), uy = _mm512_load_pd(du[1].data() + at),
                  uz = _mm512_load_pd(du[2].data() + at);
    const __m512d vx = _mm512_load_pd(dv[0].data() + at), vy = _mm512_load_pd(dv[1].data() + at),
                  vz = _mm512_load_pd(dv[2].data() + at);
    const __m512d nx = _mm512_sub_pd(_mm512_mul_pd(uy, vz), _mm512_mul_pd(uz, vy));
    const __m512d ny = _mm512_sub_pd(_mm512_mul_pd(uz, vx), _mm512_mul_pd(ux, vz));
    const __m512d nz = _mm512_sub_pd(_mm512_mul_pd(ux, vy), _mm512_mul_pd(uy, vx));
    // maskz_sqrt with every lane set is sqrt (GCC 12 warns about _mm512_sqrt_pd's
    // undefined pass-through operand).
    const __m512d length = _mm512_maskz_sqrt_pd(
        __mmask8(0xFF), _mm512_fmadd_pd(nz, nz, _mm512_fmadd_pd(ny, ny, _mm512_mul_pd(nx, nx))));
    const __mmask8 nonzero = _mm512_cmp_pd_mask(length, zero, _CMP_GT_OQ);
    const __m512d scale = _mm512_mask_div_pd(one, nonzero, one, length);
    _mm512_store_pd(normal[0].data() + at, _mm512_mul_pd(nx, scale));
    _mm512_store_pd(normal[1].data() + at, _mm512_mul_pd(ny, scale));
    _mm512_store_pd(normal[2].data() + at, _mm512_mul_pd(nz, scale));
  }
}

__attribute__((target("avx2,fma"), optimize("fp-contract=off"))) void normalsAvx2(
    const std::array<AlignedDoubles, 3>& du, const std::array<AlignedDoubles, 3>& dv,
    std::array<AlignedDoubles, 3>& normal, size_t blocks) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  for (size_t at = 0; at < blocks * kBatchLanes; at += 4) {
    const __m256d ux = _mm256_load_pd(du[0].data() + at), uy = _mm256_load_pd(du[1].data() + at),
                  uz = _mm256_load_pd(du[2].data() + at);
    const __m256d vx = _mm256_load_pd(dv[0].data() + at), vy = _mm256_load_pd(dv[1].data() + at),
                  vz = _mm256_load_pd(dv[2].data() + at);
    const __m256d nx = _mm256_sub_pd(_mm256_mul_pd(uy, vz), _mm256_mul_pd(uz, vy));
    const __m256d ny = _mm256_sub_pd(_mm256_mul_pd(uz, vx), _mm256_mul_pd(ux, vz));
    const __m256d nz = _mm256_sub_pd(_mm256_mul_pd(ux, vy), _mm256_mul_pd(uy, vx));
    const __m256d length =
        _mm256_sqrt_pd(_mm256_fmadd_pd(nz, nz, _mm256_fmadd_pd(ny, ny, _mm256_mul_pd(nx, nx))));
    const __m256d nonzero = _mm256_cmp_pd(length, zero, _CMP_GT_OQ);
    const __m256d scale = _mm256_blendv_pd(one, _mm256_div_pd(one, length), nonzero);
    _mm256_store_pd(normal[0].data() + at, _mm256_mul_pd(nx, scale));
    _mm256_store_pd(normal[1].data() + at, _mm256_mul_pd(ny, scale));
    _mm256_store_pd(normal[2].data() + at, _mm256_mul_pd(nz, scale));
  }
}

#endif  // TB_X86_KERNELS

}  // namespace

bool batchKernelSupported(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::kPortable:
      return true;
#if TB_X86_KERNELS
    case BatchKernel::kAvx2Fma:
      __builtin_cpu_init();
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case BatchKernel::kAvx512:
      __builtin_cpu_init();
      return __builtin_cpu_supports("avx512f");
#else
    case BatchKernel::kAvx2Fma:
    case BatchKernel::kAvx512:
      return false;
#endif
  }
  return false;
}

BatchKernel fastestBatchKernel() {
  static const BatchKernel kFastest = [] {
    for (BatchKernel k : {BatchKernel::kAvx512, BatchKernel::kAvx2Fma}) {
      if (batchKernelSupported(k)) return k;
    }
    return BatchKernel::kPortable;
  }();
  return kFastest;
}

const char* toString(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::kPortable:
      return "portable";
    case BatchKernel::kAvx2Fma:
      return "avx2_fma";
    case BatchKernel::kAvx512:
      return "avx512";
  }
  return "?";
}

void combineControlPoints(const BasisTable& basis, const mesh::Vec3d* control,
                          std::array<AlignedDoubles, 3>& out, BatchKernel kernel) {
  assert(batchKernelSupported(kernel) && control != nullptr);
  for (const AlignedDoubles& axis : out) {
    assert(axis.size() >= basis.blocks() * kBatchLanes);
    (void)axis;
  }
  const CombineArgs args{basis.data(),
                         basis.controlPoints(),
                         basis.blocks(),
                         control,
                         {out[0].data(), out[1].data(), out[2].data()}};
  switch (kernel) {
#if TB_X86_KERNELS
    case BatchKernel::kAvx512:
      return combineAvx512(args);
    case BatchKernel::kAvx2Fma:
      return combineAvx2(args);
#endif
    default:
      return combinePortable(args);
  }
}

void normalsFromTangents(const std::array<AlignedDoubles, 3>& du,
                         const std::array<AlignedDoubles, 3>& dv,
                         std::array<AlignedDoubles, 3>& normal, size_t count, BatchKernel kernel) {
  assert(batchKernelSupported(kernel) && count <= normal[0].size());
  const size_t blocks = batchBlocks(count);
  for (const std::array<AlignedDoubles, 3>* field : {&du, &dv, &std::as_const(normal)}) {
    for (const AlignedDoubles& axis : *field) {
      assert(axis.size() >= blocks * kBatchLanes);
      (void)axis;
    }
  }
  switch (kernel) {
#if TB_X86_KERNELS
    case BatchKernel::kAvx512:
      return normalsAvx512(du, dv, normal, blocks);
    case BatchKernel::kAvx2Fma:
      return normalsAvx2(du, dv, normal, blocks);
#endif
    default:
      return normalsPortable(du, dv, normal, count);
  }
}

}  // namespace tb::techniques
