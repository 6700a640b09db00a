#pragma once
// A fixed-capacity ring of elements kept in order (index 0 = oldest), with insertion at any
// position: the estimator's history of odometry and pose events. Storage is allocated once at
// construction; PushBack, Insert and PopFront never allocate.

#include <cassert>
#include <utility>
#include <vector>

namespace topay {

template <class T>
class EventRing {
 public:
  /// capacity >= 1.
  explicit EventRing(int capacity) : slots_(static_cast<std::size_t>(capacity)) {}

  int capacity() const { return static_cast<int>(slots_.size()); }
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool full() const { return size_ == capacity(); }

  /// i in [0, size): 0 is the oldest.
  T& operator[](int i) { return slots_[Slot(i)]; }
  const T& operator[](int i) const { return slots_[Slot(i)]; }
  T& back() { return (*this)[size_ - 1]; }
  const T& back() const { return (*this)[size_ - 1]; }

  /// Removes the oldest (size > 0).
  void PopFront() {
    assert(size_ > 0);
    head_ = (head_ + 1) % capacity();
    --size_;
  }
  /// Appends; the ring must not be full (PopFront first).
  void PushBack(T value) { Insert(size_, std::move(value)); }
  /// Inserts before index i (i in [0, size]), moving the later ones up; not full.
  void Insert(int i, T value) {
    assert(!full() && i >= 0 && i <= size_);
    ++size_;
    for (int k = size_ - 1; k > i; --k) (*this)[k] = std::move((*this)[k - 1]);
    (*this)[i] = std::move(value);
  }
  void Clear() { head_ = size_ = 0; }

 private:
  int Slot(int i) const { return (head_ + i) % capacity(); }

  std::vector<T> slots_;
  int head_ = 0;
  int size_ = 0;
};

}  // namespace topay
