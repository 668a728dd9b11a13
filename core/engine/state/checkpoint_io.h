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
