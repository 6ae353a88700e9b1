#pragma once
// Little-endian byte writing and bounded reading for the .tvrec format (FORMAT.md): varints,
// zigzag deltas, and doubles sent as "the predicted value", "a float32 delta" or "raw bits",
// two bits each in a code byte ahead of up to four values.
//
// The reader never trusts the file: every read is bounded by the bytes left, every count is
// checked against them before anything is allocated, and every failure throws tv::Error naming
// the byte offset and the frame.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "tv/error.hpp"

namespace tv::rec {

// -- writing ----------------------------------------------------------------------------------

// A growing byte buffer written without a capacity test per byte: each writer asks for the room
// it needs once (varint: 10 bytes, a Group: 33), then stores through a pointer.
class Out {
 public:
  [[nodiscard]] std::size_t size() const { return n_; }
  [[nodiscard]] const std::uint8_t* data() const { return buf_.data(); }
  [[nodiscard]] std::uint8_t& at(std::size_t i) { return buf_[i]; }
  void clear() { n_ = 0; }
  void reserve(std::size_t n) {
    if (buf_.size() < n) buf_.resize(n);
  }
  [[nodiscard]] std::vector<std::uint8_t> bytes() const { return {buf_.data(), buf_.data() + n_}; }

  void room(std::size_t k) {
    if (buf_.size() - n_ < k) grow(k);
  }
  void u8(std::uint8_t v) {
    room(1);
    buf_[n_++] = v;
  }
  void u32(std::uint32_t v) {
    room(4);
    for (int i = 0; i < 4; ++i) buf_[n_++] = static_cast<std::uint8_t>(v >> (8 * i));
  }
  void u64(std::uint64_t v) {
    room(8);
    for (int i = 0; i < 8; ++i) buf_[n_++] = static_cast<std::uint8_t>(v >> (8 * i));
  }
  void f64(double v) { u64(std::bit_cast<std::uint64_t>(v)); }
  void varint(std::uint64_t v) {
    room(10);
    std::uint8_t* p = buf_.data() + n_;
    std::uint8_t* const start = p;
    while (v >= 0x80) {
      *p++ = static_cast<std::uint8_t>(v | 0x80);
      v >>= 7;
    }
    *p++ = static_cast<std::uint8_t>(v);
    n_ += static_cast<std::size_t>(p - start);
  }
  void zigzag(std::int64_t v) {
    varint((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
  }
  void str(std::string_view s) {
    varint(s.size());
    room(s.size());
    if (!s.empty()) std::memcpy(buf_.data() + n_, s.data(), s.size());
    n_ += s.size();
  }
  void raw(const void* data, std::size_t n) {
    room(n);
    if (n) std::memcpy(buf_.data() + n_, data, n);
    n_ += n;
  }

 private:
  friend class Group;
  [[gnu::noinline]] void grow(std::size_t k) {
    buf_.resize(std::max(buf_.size() * 2, n_ + k + 256));
  }
  std::vector<std::uint8_t> buf_;
  std::size_t n_ = 0;
};

[[nodiscard]] inline bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Code of a value against two predictions and a base for the float32 delta.
enum : std::uint8_t { kP0 = 0, kP1 = 1, kF32 = 2, kF64 = 3 };

// Up to four doubles behind one code byte. Predictions may depend on values put before them
// (the reader decodes in the same order).
class Group {
 public:
  // Room for the code byte and four f64 values, so that put() never tests the capacity.
  explicit Group(Out& o) : o_(o), at_(o.n_) {
    o.room(33);
    o.buf_[o.n_++] = 0;
  }
  // Most values are their first prediction: code 0, nothing to write.
  void put(double v, double p0, double p1, double base = 0.0) {
    if (sameBits(v, p0)) {
      ++n_;
      return;
    }
    putOther(v, p0, p1, base);
  }

 private:
  [[gnu::noinline]] void putOther(double v, double p0, double p1, double base) {
    std::uint8_t code = kF64;
    if (sameBits(v, p0)) {
      code = kP0;
    } else if (sameBits(v, p1)) {
      code = kP1;
    } else {
      const double d = v - base;
      if (std::isfinite(d) &&
          std::fabs(d) <= static_cast<double>(std::numeric_limits<float>::max())) {
        const auto f = static_cast<float>(d);
        if (sameBits(static_cast<double>(f), d) && sameBits(base + static_cast<double>(f), v)) {
          code = kF32;
          std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
          for (int i = 0; i < 4; ++i) o_.buf_[o_.n_++] = static_cast<std::uint8_t>(bits >> (8 * i));
        }
      }
      if (code == kF64) {
        const auto bits = std::bit_cast<std::uint64_t>(v);
        for (int i = 0; i < 8; ++i) o_.buf_[o_.n_++] = static_cast<std::uint8_t>(bits >> (8 * i));
      }
    }
    o_.buf_[at_] = static_cast<std::uint8_t>(o_.buf_[at_] | (code << (2 * n_)));
    ++n_;
  }

  Out& o_;
  std::size_t at_;
  int n_ = 0;
};

// -- reading ----------------------------------------------------------------------------------

class In {
 public:
  In() = default;
  // `base`: the file offset of data[0], for messages.
  In(const std::uint8_t* data, std::size_t size, std::uint64_t base, std::uint64_t frame)
      : p_(data), begin_(data), end_(data + size), base_(base), frame_(frame) {}

  [[nodiscard]] std::size_t left() const { return static_cast<std::size_t>(end_ - p_); }
  [[nodiscard]] bool done() const { return p_ == end_; }
  [[nodiscard]] std::uint64_t offset() const {
    return base_ + static_cast<std::uint64_t>(p_ - begin_);
  }
  [[nodiscard]] std::uint64_t frame() const { return frame_; }
  void setFrame(std::uint64_t f) { frame_ = f; }

  [[noreturn]] void fail(std::string_view what) const { failAt(offset(), what); }
  [[noreturn, gnu::cold, gnu::noinline]] void failAt(std::uint64_t at,
                                                     std::string_view what) const {
    tv::fail("tv::Replay", "byte " + std::to_string(at) + " (frame " + std::to_string(frame_) +
                               "): " + std::string(what));
  }

  // Every read below is a bounds test inline and, when it fails, a call to a cold function
  // that builds the message: a whole recording is read at a few instructions per byte.
  [[gnu::always_inline]] void need(std::size_t n, std::string_view what) const {
    if (left() < n) [[unlikely]]
      failNeed(n, what);
  }
  [[gnu::always_inline]] std::uint8_t u8(std::string_view what) {
    need(1, what);
    return *p_++;
  }
  [[gnu::always_inline]] std::uint32_t u32(std::string_view what) {
    need(4, what);
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t{p_[i]} << (8 * i);
    p_ += 4;
    return v;
  }
  [[gnu::always_inline]] std::uint64_t u64(std::string_view what) {
    need(8, what);
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{p_[i]} << (8 * i);
    p_ += 8;
    return v;
  }
  // A double that must be finite (every value tv records is).
  [[gnu::always_inline]] double f64(std::string_view what) {
    const double v = std::bit_cast<double>(u64(what));
    if (!std::isfinite(v)) [[unlikely]]
      failValue(offset() - 8, what, v);
    return v;
  }
  [[gnu::always_inline]] std::uint64_t varint(std::string_view what) {
    if (p_ != end_ && *p_ < 0x80) [[likely]]
      return *p_++;  // most are one byte
    return varintLong(what);
  }
  [[gnu::always_inline]] std::int64_t zigzag(std::string_view what) {
    const std::uint64_t u = varint(what);
    return static_cast<std::int64_t>(u >> 1) ^ -static_cast<std::int64_t>(u & 1);
  }
  // A count of things each at least `minBytes` long: refused before anything is allocated when
  // the chunk cannot hold that many.
  std::size_t count(std::string_view what, std::size_t minBytes) {
    const std::uint64_t at = offset();
    const std::uint64_t n = varint(what);
    if (minBytes > 0 && n > left() / minBytes) {
      failAt(at, std::string(what) + " " + std::to_string(n) + " is more than the " +
                     std::to_string(left()) + " bytes left in the chunk can hold");
    }
    if (minBytes == 0 && n > (std::uint64_t{1} << 31)) {
      failAt(at, std::string(what) + " " + std::to_string(n) + " is out of range");
    }
    return static_cast<std::size_t>(n);
  }
  std::string str(std::string_view what, std::size_t maxLength) {
    const std::uint64_t at = offset();
    const std::uint64_t n = varint(what);
    if (n > maxLength) {
      failAt(at, std::string(what) + " of " + std::to_string(n) + " bytes is longer than " +
                     std::to_string(maxLength));
    }
    need(static_cast<std::size_t>(n), what);
    std::string s(reinterpret_cast<const char*>(p_), static_cast<std::size_t>(n));
    p_ += n;
    return s;
  }

  [[noreturn, gnu::cold, gnu::noinline]] void failValue(std::uint64_t at, std::string_view what,
                                                        double v) const {
    failAt(at, std::string(what) + " is " + tv::formatNumber(v));
  }

 private:
  friend class GroupIn;
  [[noreturn, gnu::cold, gnu::noinline]] void failNeed(std::size_t n, std::string_view what) const {
    fail(std::string(what) + " needs " + std::to_string(n) + " bytes, only " +
         std::to_string(left()) + " left in the chunk");
  }
  [[gnu::noinline]] std::uint64_t varintLong(std::string_view what) {
    const std::uint64_t at = offset();
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (p_ == end_) failAt(at, std::string(what) + ": varint cut by the end of the chunk");
      const std::uint8_t byte = *p_++;
      if (shift == 63 && byte > 1) failAt(at, std::string(what) + ": varint over 64 bits");
      v |= std::uint64_t{byte & 0x7Fu} << shift;
      if ((byte & 0x80) == 0) return v;
    }
    failAt(at, std::string(what) + ": varint over 64 bits");
  }
  const std::uint8_t* p_ = nullptr;
  const std::uint8_t* begin_ = nullptr;
  const std::uint8_t* end_ = nullptr;
  std::uint64_t base_ = 0;
  std::uint64_t frame_ = 0;
};

class GroupIn {
 public:
  [[gnu::always_inline]] GroupIn(In& in, std::string_view what)
      : in_(in), what_(what), codes_(in.u8(what)) {}
  [[gnu::always_inline]] double get(double p0, double p1, double base = 0.0) {
    const unsigned code = codes_ & 3u;
    codes_ >>= 2;
    double v;
    if (code == kP0) [[likely]] {
      v = p0;
    } else if (code == kP1) {
      v = p1;
    } else if (code == kF32) {
      v = base + static_cast<double>(std::bit_cast<float>(in_.u32(what_)));
    } else {
      return in_.f64(what_);
    }
    // A prediction or a sum can overflow where the recorder's value could not have.
    if (!std::isfinite(v)) [[unlikely]] {
      in_.failValue(in_.offset() - (code == kF32 ? 4 : 0), what_, v);
    }
    return v;
  }

 private:
  In& in_;
  std::string_view what_;
  unsigned codes_;
};

}  // namespace tv::rec
