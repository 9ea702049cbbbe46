#pragma once
// FNV-1a, 64 bit (Fowler-Noll-Vo), written once: h = (h ^ unit) * prime, from an offset basis.
// The snapshot's case shards and the recovery files' names use the standard basis. The snapshot
// fingerprints (stored in the references' sidecars), the weld's cells and the topology's positions
// were first written with a basis one digit short of it; they keep that basis, so that stored
// fingerprints stay equal and the tables hash as before.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace sweep {

inline constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
/// The basis the fingerprints, the weld and the topology were written with (see above).
inline constexpr std::uint64_t kShortFnvOffsetBasis = 1469598103934665603ull;
inline constexpr std::uint64_t kFnvPrime = 1099511628211ull;

class Fnv1a {
 public:
  explicit constexpr Fnv1a(std::uint64_t basis = kFnvOffsetBasis) : hash_(basis) {}
  /// Each of the `size` bytes at `data`, in order.
  constexpr Fnv1a& add_bytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ bytes[i]) * kFnvPrime;
    return *this;
  }
  /// A whole word as one unit (the tables' variant: one xor and one multiply per value).
  constexpr Fnv1a& add_word(std::uint64_t word) {
    hash_ = (hash_ ^ word) * kFnvPrime;
    return *this;
  }
  constexpr std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_;
};

/// The standard FNV-1a of `text`'s bytes.
inline std::uint64_t fnv1a(std::string_view text) {
  return Fnv1a().add_bytes(text.data(), text.size()).value();
}

}  // namespace sweep
