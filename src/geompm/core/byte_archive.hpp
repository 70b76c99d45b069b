// The bytes of a saved state (a checkpoint's sections, docs/checkpoint-format.md): numbers as
// their in-memory bytes (little-endian, IEEE 754 doubles: a value read back is bit for bit the
// one written, so a resumed run goes on exactly as if it had never stopped), texts and arrays as
// a 64-bit count followed by their elements. Each owner of persistent state writes its own part
// with a ByteWriter and reads it back, in the same order, with a ByteReader.
#pragma once

#include <Eigen/Core>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace geompm {

static_assert(std::endian::native == std::endian::little,
              "the checkpoint format is little-endian (docs/checkpoint-format.md)");

namespace archive_detail {
template <class T>
struct is_fixed_eigen : std::false_type {};
template <int R, int C, int O, int MR, int MC>
struct is_fixed_eigen<Eigen::Matrix<double, R, C, O, MR, MC>>
    : std::bool_constant<(R > 0 && C > 0)> {};
}  // namespace archive_detail

/// The bytes a ByteWriter writes for one value of a fixed-size type: a number, a fixed-size Eigen
/// matrix, or a std::array of these. A reader can step over a vector of them, or into it,
/// without reading what comes before.
template <class T>
constexpr std::size_t archived_bytes() {
  if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>)
    return sizeof(T);
  else if constexpr (archive_detail::is_fixed_eigen<T>::value)
    return sizeof(double) * T::SizeAtCompileTime;
  else
    return std::tuple_size_v<T> * archived_bytes<typename T::value_type>();
}

class ByteWriter {
 public:
  /// A number, a text, a fixed-size Eigen matrix (Vec3, Mat3), a std::array, a std::pair, or a
  /// std::vector / std::map of any of these.
  template <class T>
  void put(const T& value) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      raw(&value, sizeof(T));
    } else if constexpr (archive_detail::is_fixed_eigen<T>::value) {
      raw(value.data(), sizeof(double) * T::SizeAtCompileTime);
    } else if constexpr (std::is_same_v<T, std::string>) {
      put(static_cast<std::uint64_t>(value.size()));
      raw(value.data(), value.size());
    } else {
      put_container(value);
    }
  }

  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  void raw(const void* data, std::size_t size) {
    // An empty container's data() may be null, which append and memcpy must not see (UBSan).
    if (size > 0) bytes_.append(static_cast<const char*>(data), size);
  }
  template <class T, std::size_t N>
  void put_container(const std::array<T, N>& values) {
    for (const T& v : values) put(v);
  }
  template <class A, class B>
  void put_container(const std::pair<A, B>& value) {
    put(value.first);
    put(value.second);
  }
  template <class T>
  void put_container(const std::vector<T>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    if constexpr (std::is_arithmetic_v<T>)
      raw(values.data(), values.size() * sizeof(T));
    else
      for (const T& v : values) put(v);
  }
  template <class K, class V>
  void put_container(const std::map<K, V>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    for (const auto& [k, v] : values) {
      put(k);
      put(v);
    }
  }

  std::string bytes_;
};

/// Reads what a ByteWriter wrote. Reading past the end, or a count larger than the bytes left,
/// throws InputError naming `context` (e.g. "out/checkpoint.bin: section 'points'").
class ByteReader {
 public:
  ByteReader(std::string_view bytes, std::string context)
      : bytes_(bytes), context_(std::move(context)) {}

  template <class T>
  void get(T& value) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      raw(&value, sizeof(T));
    } else if constexpr (archive_detail::is_fixed_eigen<T>::value) {
      raw(value.data(), sizeof(double) * T::SizeAtCompileTime);
    } else if constexpr (std::is_same_v<T, std::string>) {
      const std::size_t n = count(1);
      value.assign(bytes_.data() + at_, n);
      at_ += n;
    } else {
      get_container(value);
    }
  }
  template <class T>
  T get() {
    T value{};
    get(value);
    return value;
  }

  std::size_t remaining() const { return bytes_.size() - at_; }
  /// Throws unless every byte has been read (a section longer than its reader expects).
  void expect_end() const;
  const std::string& context() const { return context_; }

 private:
  void raw(void* data, std::size_t size) {
    if (size > remaining()) fail_short(size);
    if (size == 0) return;  // an empty container's data() may be null (UBSan)
    std::memcpy(data, bytes_.data() + at_, size);
    at_ += size;
  }
  // A 64-bit count of elements of at least `element_bytes` each, checked against the bytes left.
  std::size_t count(std::size_t element_bytes);
  [[noreturn]] void fail_short(std::size_t needed) const;

  template <class T, std::size_t N>
  void get_container(std::array<T, N>& values) {
    for (T& v : values) get(v);
  }
  template <class A, class B>
  void get_container(std::pair<A, B>& value) {
    get(value.first);
    get(value.second);
  }
  template <class T>
  void get_container(std::vector<T>& values) {
    if constexpr (std::is_arithmetic_v<T>) {
      values.resize(count(sizeof(T)));
      raw(values.data(), values.size() * sizeof(T));
    } else {
      values.resize(count(1));
      for (T& v : values) get(v);
    }
  }
  template <class K, class V>
  void get_container(std::map<K, V>& values) {
    values.clear();
    const std::size_t n = count(1);
    for (std::size_t i = 0; i < n; ++i) {
      K k{};
      get(k);
      get(values[k]);
    }
  }

  std::string_view bytes_;
  std::size_t at_ = 0;
  std::string context_;
};

}  // namespace geompm
