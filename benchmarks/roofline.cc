// Two ceilings of the PD stencil kernel on one core, measured with the kernel's compiler
// options (benchmarks/roofline.sh builds this file):
//  - memory: a STREAM-like triad a = b + s c over arrays far larger than the caches [GB/s];
//  - the divide/square-root unit: per element the two square roots and two divisions that a
//    stored bond costs in the dilatation and force passes (sqrt(y), n / (l + L); sqrt(y),
//    1 / ((l + L) l)), vectorised and compiled for the same instruction sets as the kernel,
//    with independent elements so that only the unit's throughput limits [elements/s].
// Prints the medians of 5 repetitions.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#  define CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#  define CLONES
#endif

namespace
{
  CLONES void
  triad(double *a, const double *b, const double *c, const double s, const long n)
  {
#pragma omp simd
    for (long i = 0; i < n; ++i)
      a[i] = b[i] + s * c[i];
  }

  CLONES void
  quotients(const double *y, double *out, const long n)
  {
    const double L = 1e-3;
#pragma omp simd
    for (long i = 0; i < n; ++i)
      {
        const double l1 = std::sqrt(y[i]);
        const double e  = (y[i] - L * L) / (l1 + L);
        const double l2 = std::sqrt(y[i] + e * 1e-30);
        const double r  = 1. / ((l2 + L) * l2);
        out[i]          = e * l2 * r + r;
      }
  }

  template <typename Work>
  double
  median_seconds(const Work &work)
  {
    std::vector<double> times;
    for (int r = 0; r < 5; ++r)
      {
        const auto start = std::chrono::steady_clock::now();
        work();
        times.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      }
    std::sort(times.begin(), times.end());
    return times[2];
  }
} // namespace

int
main()
{
  const long          n_stream = 20'000'000;
  std::vector<double> a(n_stream, 0.), b(n_stream, 1.), c(n_stream, 2.);
  const double t_triad = median_seconds([&] { triad(a.data(), b.data(), c.data(), 3., n_stream); });
  std::printf("triad bandwidth: %.2f GB/s\n", 3. * 8. * n_stream / t_triad * 1e-9);

  // In the L1 cache, repeated: only the arithmetic counts.
  const long          n = 1024, repeats = 20'000;
  std::vector<double> y(n), out(n);
  for (long i = 0; i < n; ++i)
    y[i] = 1e-6 * (1. + 1e-3 * i);
  const double t_quotients = median_seconds([&] {
    for (long r = 0; r < repeats; ++r)
      {
        quotients(y.data(), out.data(), n);
        y[r % n] += 1e-30 * out[(r * 7) % n];
      }
  });
  std::printf("2 sqrt + 2 div per element: %.3e elements/s\n", n * repeats / t_quotients);
  return out[3] > 0 ? 0 : 1;
}
