// Random numbers of an evolution run. Every child draws from its own stream,
// seeded from (run seed, generation, stream), so a run is bit-identical
// whatever the number of threads and wherever it is resumed. The sampling
// algorithms are written out (rather than std::normal_distribution and
// friends, whose algorithms differ between standard libraries) so that a
// seed means the same run on every platform.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace walkers {

class Random {
 public:
  // Streams of a generation: children use their index; the two parent
  // shuffles use these.
  static constexpr std::uint64_t kMutationParents = 1000;
  static constexpr std::uint64_t kCrossoverParents = 1001;
  // kRedraws + child: the redraws of a child whose proposal was a duplicate
  // (for learners other than the GA, which draws again from its own streams)
  static constexpr std::uint64_t kRedraws = std::uint64_t{1} << 32;

  Random(std::uint64_t seed, std::uint64_t generation, std::uint64_t stream)
      : engine_(Mix(Mix(Mix(seed) ^ generation) ^ stream)) {}

  // Uniform in [0, 1), from the top 53 bits.
  double Uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  bool Bernoulli(double p) { return Uniform() < p; }

  // Normal(mean, sigma^2) by Box–Muller (one value per call).
  double Normal(double mean, double sigma) {
    const double u1 = 1.0 - Uniform();  // (0, 1]
    const double u2 = Uniform();
    return mean + sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
  }

  // Uniform integer in [0, n), by rejection (no modulo bias).
  std::uint64_t Below(std::uint64_t n) {
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
    std::uint64_t x;
    do x = engine_();
    while (x >= limit);
    return x % n;
  }

  // Fisher–Yates.
  template <typename T>
  void Shuffle(std::vector<T>* v) {
    for (std::size_t i = v->size(); i > 1; --i) std::swap((*v)[i - 1], (*v)[Below(i)]);
  }

 private:
  // SplitMix64's finaliser: decorrelates nearby seeds.
  static std::uint64_t Mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::mt19937_64 engine_;
};

}  // namespace walkers
