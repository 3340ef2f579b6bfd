// SPDX-License-Identifier: MIT
// A vector stored in chunks shared between copies: copying it copies one pointer per chunk, and changing an
// element copies only its chunk, and only while another copy still shares it. Keyframes of a view that holds
// every primitive of a large scene then cost little more than the primitives that changed between them.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace hsr::viz {

template <class T, std::size_t ChunkSize = 256>
class CowVector {
public:
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    const T& operator[](std::size_t i) const { return (*chunks_[i / ChunkSize])[i % ChunkSize]; }

    // The element, for changing: its chunk is copied first if another vector shares it.
    T& mut(std::size_t i) {
        auto& chunk = chunks_[i / ChunkSize];
        if (chunk.use_count() > 1) chunk = std::make_shared<std::vector<T>>(*chunk);
        return (*chunk)[i % ChunkSize];
    }

    void push_back(T value) {
        if (size_ % ChunkSize == 0) {
            chunks_.push_back(std::make_shared<std::vector<T>>());
            chunks_.back()->reserve(ChunkSize);
        } else if (chunks_.back().use_count() > 1) {
            chunks_.back() = std::make_shared<std::vector<T>>(*chunks_.back());
        }
        chunks_.back()->push_back(std::move(value));
        ++size_;
    }

    const T& back() const { return (*this)[size_ - 1]; }
    void clear() {
        chunks_.clear();
        size_ = 0;
    }
    [[nodiscard]] std::vector<T> to_vector() const {
        std::vector<T> out;
        out.reserve(size_);
        for (const auto& chunk : chunks_) out.insert(out.end(), chunk->begin(), chunk->end());
        return out;
    }
    friend bool operator==(const CowVector& a, const CowVector& b) {
        if (a.size_ != b.size_) return false;
        for (std::size_t i = 0; i < a.size_; ++i)
            if (!(a[i] == b[i])) return false;
        return true;
    }

    // What a copy of this vector costs (the chunk pointers), not what it holds.
    [[nodiscard]] std::size_t copy_bytes() const { return chunks_.capacity() * sizeof(chunks_[0]); }

    class const_iterator {
    public:
        const_iterator(const CowVector* v, std::size_t i) : v_(v), i_(i) {}
        const T& operator*() const { return (*v_)[i_]; }
        const_iterator& operator++() {
            ++i_;
            return *this;
        }
        bool operator==(const const_iterator& o) const { return i_ == o.i_; }

    private:
        const CowVector* v_;
        std::size_t i_;
    };
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size_}; }

private:
    std::vector<std::shared_ptr<std::vector<T>>> chunks_;
    std::size_t size_ = 0;
};

}  // namespace hsr::viz
