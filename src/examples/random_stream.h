#pragma once
/// A small deterministic random stream (splitmix64 + Box–Muller) so that
/// generated fixtures are identical on every platform and library version
/// (std::normal_distribution is implementation-defined).

#include <cmath>
#include <cstdint>

namespace lpvid {

class RandomStream {
 public:
  explicit RandomStream(uint64_t seed) : state_(seed) {}
  uint64_t next_u64() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }
  /// Integer in [lo, hi].
  int uniform_int(int lo, int hi) { return lo + static_cast<int>(next_u64() % static_cast<uint64_t>(hi - lo + 1)); }
  /// Standard normal (Box–Muller, one value per call).
  double normal() {
    double u1 = uniform(), u2 = uniform();
    if (u1 < 1e-300) u1 = 1e-300;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  uint64_t state_;
};

/// The random pulse signal of the examples: for k = begin … end−1, runs of
/// 1–5 samples (uniform) at one level each, high with probability 1/2;
/// `set(k, high)` writes sample k. Draws hold then level, per run.
template <typename Set>
void random_pulse_train(RandomStream& rng, long begin, long end, Set set) {
  long k = begin;
  while (k < end) {
    const int hold = rng.uniform_int(1, 5);
    const bool high = !(rng.uniform() < 0.5);
    for (int j = 0; j < hold && k < end; ++j, ++k) set(k, high);
  }
}

}  // namespace lpvid
