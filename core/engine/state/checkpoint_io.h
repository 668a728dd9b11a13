#pragma once

// Raw reads and writes of the engine's checkpoint: vectors carry their length, which must match
// the vector they are read into (sized beforehand from the sample) or stay within a bound.

#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace sedem {

template <class T>
void write_vector(std::ostream& out, const std::vector<T>& v) {
  const std::uint64_t n = v.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(n * sizeof(T)));
}

template <class T>
void read_vector(std::istream& in, std::vector<T>& v) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  if (!in || n != v.size()) throw std::runtime_error("checkpoint does not match this sample");
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)));
}

// One field of every record of `v`, written as write_vector writes a vector of that field (and
// read back into it), without a copy of the field: a checkpoint of ten million grains would
// otherwise hold another 8 bytes a grain for each field while it is written.
template <class R, class T>
void write_field(std::ostream& out, const std::vector<R>& v, T R::*field) {
  const std::uint64_t n = v.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  for (const R& r : v) out.write(reinterpret_cast<const char*>(&(r.*field)), sizeof(T));
}

template <class R, class T>
void read_field(std::istream& in, std::vector<R>& v, T R::*field) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  if (!in || n != v.size()) throw std::runtime_error("checkpoint does not match this sample");
  for (R& r : v) in.read(reinterpret_cast<char*>(&(r.*field)), sizeof(T));
}

// A vector whose length the sample only bounds (at most `most` entries).
template <class T>
void read_vector_upto(std::istream& in, std::vector<T>& v, std::uint64_t most) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  if (!in || n > most) throw std::runtime_error("checkpoint does not match this sample");
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)));
}

template <class T>
void write_value(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
void read_value(std::istream& in, T& v) {
  in.read(reinterpret_cast<char*>(&v), sizeof v);
}

}  // namespace sedem
