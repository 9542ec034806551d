#pragma once
// Memory for the Z3 instantiations of shipped code that reads and writes arrays (the STC floor,
// proofs/z3/stc_floor.cpp): an array of N-bit words indexed by 64-bit words (size_t), held as one
// Z3 array term that every write replaces by a `store`.
//
// Every access the code makes records the obligation that its index is below the array's length
// (the length the shipped code documents, e.g. floor_size's), checked with the next claim like any
// other obligation (z3_int.hpp): a claim is proved only if every read and write on its path is in
// bounds.
//
// The code sees a MemoryRef (what a pointer is on the machine: indexable, and null or not); the
// proof owns the Memory and reads its array after the code has run.
#include "z3_int.hpp"

#include <string>
#include <utility>

namespace antkit::proofs {

template <int N>
class Memory {
public:
  using Word = Int<N, false>;

  // A symbolic array of `length` words: any contents.
  Memory(const std::string& name, const U64& length)
      : name_(name), length_(length),
        array_(Session::current().ctx().constant(
            name.c_str(), Session::current().ctx().array_sort(
                              Session::current().ctx().bv_sort(64),
                              Session::current().ctx().bv_sort(static_cast<unsigned>(N))))) {
    // Prover (prove.hpp) picks the QF_ABV solver once the session holds an array term, which it
    // learns from the session's table registry; register this array there (under its own address,
    // a key no table can have).
    Session::current().tables().emplace(std::pair<const void*, int>{this, N}, array_);
  }

  const std::string& name() const { return name_; }
  const U64& length() const { return length_; }
  const z3::expr& array() const { return array_; }
  void set_array(const z3::expr& a) { array_ = a; }

  // The word at i, as the specification reads it: no obligation (a claim's own reads).
  Word peek(const U64& i) const { return Word(z3::select(array_, i.expr())); }

  // The code's reads and writes: each records that the index is in bounds.
  Word read(const U64& i) const {
    in_bounds(i);
    return peek(i);
  }
  void write(const U64& i, const Word& v) {
    in_bounds(i);
    array_ = z3::store(array_, i.expr(), v.expr());
  }

private:
  void in_bounds(const U64& i) const {
    Session::current().oblige(name_ + " index < its length", z3::ult(i.expr(), length_.expr()));
  }

  std::string name_;
  U64 length_;
  z3::expr array_;
};

// What the code holds: a pointer-like handle on a Memory, or null (absent).
template <int N>
class MemoryRef {
public:
  using Word = Int<N, false>;

  MemoryRef() = default;
  explicit MemoryRef(Memory<N>* m) : m_(m) {}

  explicit operator bool() const { return m_ != nullptr; }

  // m[i] as an lvalue: reads convert, = and |= write.
  class Element {
  public:
    Element(Memory<N>& m, const U64& i) : m_(m), i_(i) {}
    operator Word() const { return m_.read(i_); }
    Element& operator=(const Word& v) {
      m_.write(i_, v);
      return *this;
    }
    Element& operator|=(const Word& v) {
      m_.write(i_, m_.read(i_) | v);
      return *this;
    }

  private:
    Memory<N>& m_;
    U64 i_;
  };

  Element operator[](const U64& i) const { return Element(*m_, i); }

private:
  Memory<N>* m_ = nullptr;
};

} // namespace antkit::proofs
