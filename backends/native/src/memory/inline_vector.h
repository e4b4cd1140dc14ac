// SPDX-License-Identifier: MIT
// InlineVector<T, N>: a vector of at most N elements stored in place (no heap), for the per-contact
// data a step creates and copies many times (a manifold's points, gaps and impulses). The subset of
// std::vector's interface the backend uses. Exceeding N is a logic error: it throws
// std::length_error instead of writing past the storage. (C++26 names this std::inplace_vector;
// Boost's static_vector would bring Boost into a project with no other use for it.)
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <stdexcept>

namespace vroc::native {

template <typename T, std::size_t N>
class InlineVector {
public:
    using value_type = T;
    using size_type = std::size_t;
    using iterator = T*;
    using const_iterator = const T*;

    InlineVector() = default;
    InlineVector(std::initializer_list<T> init) { assign(init.begin(), init.end()); }
    InlineVector(size_type n, const T& value) { assign(n, value); }
    InlineVector& operator=(std::initializer_list<T> init) {
        assign(init.begin(), init.end());
        return *this;
    }

    size_type size() const { return size_; }
    bool empty() const { return size_ == 0; }
    static constexpr size_type capacity() { return N; }
    void reserve(size_type n) const { check(n); }

    T* data() { return items_.data(); }
    const T* data() const { return items_.data(); }
    iterator begin() { return items_.data(); }
    iterator end() { return items_.data() + size_; }
    const_iterator begin() const { return items_.data(); }
    const_iterator end() const { return items_.data() + size_; }
    T& operator[](size_type i) { return items_[i]; }
    const T& operator[](size_type i) const { return items_[i]; }
    T& front() { return items_[0]; }
    const T& front() const { return items_[0]; }
    T& back() { return items_[size_ - 1]; }
    const T& back() const { return items_[size_ - 1]; }

    void clear() { size_ = 0; }
    void push_back(const T& value) {
        check(size_ + 1);
        items_[size_++] = value;
    }
    void pop_back() { --size_; }
    void resize(size_type n, const T& value = T()) {
        check(n);
        for (size_type i = size_; i < n; ++i) items_[i] = value;
        size_ = n;
    }
    void assign(size_type n, const T& value) {
        check(n);
        std::fill_n(items_.begin(), n, value);
        size_ = n;
    }
    template <typename It>
    void assign(It first, It last) {
        size_ = 0;
        for (; first != last; ++first) push_back(*first);
    }
    iterator erase(iterator first, iterator last) {
        iterator out = std::move(last, end(), first);
        size_ = static_cast<size_type>(out - begin());
        return first;
    }

    friend bool operator==(const InlineVector& x, const InlineVector& y) {
        return std::equal(x.begin(), x.end(), y.begin(), y.end());
    }

private:
    static void check(size_type n) {
        if (n > N) throw std::length_error("InlineVector: more elements than its fixed capacity");
    }

    std::array<T, N> items_{};
    size_type size_ = 0;
};

}  // namespace vroc::native
