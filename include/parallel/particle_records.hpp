// Particles as bytes, to send between processes: every quantity of the listed particles (or
// those listed in `only`), level by level (value, dt, d2t), in the storage's quantity order.
// Processes running the same scene hold storages with the same quantities, so what one packs
// another unpacks.
#pragma once

#include <algorithm>
#include <cstring>
#include <span>
#include <stdexcept>
#include <vector>

#include "parallel/communicator.hpp"
#include "sph/storage.hpp"

namespace num::parallel {

/// The quantities to send: all (`only` empty) or those listed.
using QuantityIds = std::span<const sph::QuantityId>;
inline bool selected(QuantityIds only, sph::QuantityId id) {
    return only.empty() || std::find(only.begin(), only.end(), id) != only.end();
}

/// Bytes one particle takes.
template <int Dim>
std::size_t bytesPerParticle(const sph::Storage<Dim>& s, QuantityIds only = {}) {
    std::size_t bytes = 0;
    s.forEach([&](sph::QuantityId id, const sph::Quantity<Dim>& q) {
        if (!selected(only, id)) return;
        q.visit([&](const auto& b) { bytes += sizeof(b.value[0]) * std::size_t(q.levels()); });
    });
    return bytes;
}

/// Appends the particles `indices` of s to out.
template <int Dim>
void packParticles(const sph::Storage<Dim>& s, std::span<const sph::Size> indices, Bytes& out,
                   QuantityIds only = {}) {
    std::size_t at = out.size();
    out.resize(at + indices.size() * bytesPerParticle(s, only));
    s.forEach([&](sph::QuantityId id, const sph::Quantity<Dim>& q) {
        if (!selected(only, id)) return;
        q.visit([&](const auto& b) {
            using T = typename std::decay_t<decltype(b.value)>::value_type;
            for (int k = 0; k < q.levels(); ++k) {
                const T* level = b.level(k).data();
                for (sph::Size i : indices) {
                    std::memcpy(out.data() + at, level + i, sizeof(T));
                    at += sizeof(T);
                }
            }
        });
    });
}

/// Writes particles packed by packParticles (bytes [data, data + size)) into the particles `at`
/// of s, one index per packed particle.
template <int Dim>
void unpackParticles(sph::Storage<Dim>& s, const char* data, std::size_t size,
                     std::span<const sph::Size> at, QuantityIds only = {}) {
    if (size != at.size() * bytesPerParticle(s, only))
        throw std::logic_error("unpackParticles: the bytes do not match the storage's quantities");
    std::size_t from = 0;
    s.forEach([&](sph::QuantityId id, sph::Quantity<Dim>& q) {
        if (!selected(only, id)) return;
        q.visit([&](auto& b) {
            using T = typename std::decay_t<decltype(b.value)>::value_type;
            for (int k = 0; k < q.levels(); ++k) {
                T* level = b.level(k).data();
                for (sph::Size i : at) {
                    std::memcpy(level + i, data + from, sizeof(T));
                    from += sizeof(T);
                }
            }
        });
    });
}

/// One quantity's level (value, dt or d2t) in the packed layout: `bytes` per particle.
struct Block {
    sph::QuantityId id;
    int level;
    std::size_t bytes;
};

/// The blocks of the packed layout, in order (the particles of a pack are block after block).
template <int Dim>
std::vector<Block> blocksOf(const sph::Storage<Dim>& s, QuantityIds only = {}) {
    std::vector<Block> blocks;
    s.forEach([&](sph::QuantityId id, const sph::Quantity<Dim>& q) {
        if (!selected(only, id)) return;
        q.visit([&](const auto& b) {
            for (int k = 0; k < q.levels(); ++k) blocks.push_back({id, k, sizeof(b.value[0])});
        });
    });
    return blocks;
}

/// Writes one block of packed particles (`data`: one element per index of `at`) into s.
template <int Dim>
void unpackBlock(sph::Storage<Dim>& s, const Block& block, const char* data,
                 std::span<const sph::Size> at) {
    s.get(block.id).visit([&](auto& b) {
        using T = typename std::decay_t<decltype(b.value)>::value_type;
        T* level = b.level(block.level).data();
        for (std::size_t n = 0; n < at.size(); ++n)
            std::memcpy(level + at[n], data + n * sizeof(T), sizeof(T));
    });
}

/// Appends the particles packed in `bytes` to s; returns the index of the first.
template <int Dim>
sph::Size appendParticles(sph::Storage<Dim>& s, const Bytes& bytes) {
    const std::size_t per = bytesPerParticle(s);
    const sph::Size first = s.size(), count = sph::Size(per ? bytes.size() / per : 0);
    s.resize(first + count);
    std::vector<sph::Size> at(count);
    for (sph::Size k = 0; k < count; ++k) at[k] = first + k;
    unpackParticles(s, bytes.data(), bytes.size(), at);
    return first;
}

}  // namespace num::parallel
