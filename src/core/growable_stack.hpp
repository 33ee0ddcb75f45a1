// SPDX-License-Identifier: MIT
// GrowableStack: a stack in a local array that moves to the heap only if it overflows,
// for tree traversals that must not allocate in the common case yet never overflow.
#pragma once

#include <cstdint>
#include <vector>

namespace i2d {

template <class T, int32_t N>
class GrowableStack {
public:
    void push(const T& value) {
        if (count_ < N) {
            local_[count_++] = value;
        } else {
            overflow_.push_back(value);
            ++count_;
        }
    }
    T pop() {
        --count_;
        if (count_ < N) {
            return local_[count_];
        }
        T value = overflow_.back();
        overflow_.pop_back();
        return value;
    }
    bool empty() const { return count_ == 0; }

private:
    T local_[N];
    std::vector<T> overflow_;
    int32_t count_ = 0;
};

}  // namespace i2d
