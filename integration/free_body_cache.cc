#include "integration/free_body_cache.h"

#include <cstring>

namespace walkers {
namespace {

bool SameBits(const State& a, const State& b) {
  return std::memcmp(a.q.data(), b.q.data(), sizeof(double) * kNumCoords) == 0 &&
         std::memcmp(a.v.data(), b.v.data(), sizeof(double) * kNumCoords) == 0;
}

}  // namespace

FreeBodyState FreeBodyCache::Get(const Model& model, const State& state) {
  for (const Entry& entry : entries_) {
    if (entry.valid && SameBits(entry.state, state)) return entry.free_bodies;
  }
  Entry& entry = entries_[next_];
  next_ = (next_ + 1) % kSize;
  entry.state = state;
  entry.free_bodies = ToFreeBodies(model, state);
  entry.valid = true;
  return entry.free_bodies;
}

}  // namespace walkers
