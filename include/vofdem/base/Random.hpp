// Counter-based random numbers: a value depends only on (seed, key, stream), never on which rank
// or in which order it is drawn. That is what makes insertion give the same particles for the same
// -seed on any rank count.
#pragma once

#include <cstdint>

namespace vofdem::random {

// SplitMix64 finaliser: a bijective mix of 64 bits.
inline std::uint64_t Mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Uniform in [0, 1) for (seed, key, stream).
inline double Uniform(std::uint64_t seed, std::uint64_t key, std::uint64_t stream) {
  const std::uint64_t h = Mix(Mix(Mix(seed) ^ key) ^ (stream * 0xd1b54a32d192ed03ULL));
  return (h >> 11) * (1.0 / 9007199254740992.0);  // 53 random bits
}

}  // namespace vofdem::random
