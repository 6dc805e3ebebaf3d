// DomainDecomposition's halo: its build, the particles added since, the refresh of its copies.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

#include "parallel/domain_decomposition.hpp"

namespace num::parallel {

template <int Dim>
void DomainDecomposition<Dim>::exchangeHalo(sph::Storage<Dim>& s, QuantityIds only) {
    if (comm_.size() == 1) return;
    checkDisplacement(s);
    const std::vector<Block> blocks = blocksOf(s, only);
    std::vector<Bytes> out(comm_.size());
    for (int r = 0; r < comm_.size(); ++r)
        if (!sendTo_[r].empty()) out[r] = changedBlocks(s, r, blocks, only);
    const std::vector<Bytes> in = comm_.exchange(out);
    for (int r = 0; r < comm_.size(); ++r) {
        if (receiveAt_[r].empty()) continue;
        const std::size_t n = receiveAt_[r].size();
        Bytes& record = lastReceived_[r];
        const bool recorded = record.size() == n * bytesPerParticle(s);
        const std::vector<std::size_t> recordAt =
            recorded ? offsets(s, blocks, n) : std::vector<std::size_t>{};
        // A flag per block, then the blocks that changed.
        const char* data = in[r].data() + blocks.size();
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            const std::size_t size = blocks[b].bytes * n;
            const char* block = data;
            if (in[r][b]) {
                if (recorded) std::memcpy(record.data() + recordAt[b], data, size);
                data += size;
            } else {
                block = record.data() + recordAt[b];  // flagged when nothing is recorded
            }
            unpackBlock(s, blocks[b], block, receiveAt_[r]);
        }
        if (!recorded && only.empty()) record.assign(in[r].begin() + blocks.size(), in[r].end());
        haloBytes_ += in[r].size();
    }
    ++exchanges_;
}

template <int Dim>
void DomainDecomposition<Dim>::buildHalo(sph::Storage<Dim>& s) {
    const int me = comm_.rank(), ranks = comm_.size();
    const Size owned = s.size();
    sendTo_.assign(ranks, {});
    {
        const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
        for (Size i = 0; i < owned; ++i)
            for (int r = 0; r < ranks; ++r)
                if (r != me && nearBox(domain_.wrap(x[i]), r)) sendTo_[r].push_back(i);
    }
    std::vector<Bytes> out(ranks);
    for (int r = 0; r < ranks; ++r) packParticles(s, sendTo_[r], out[r]);
    const std::vector<Bytes> in = comm_.exchange(out);
    lastSent_ = out;  // what each process's copies hold now
    lastReceived_ = in;
    receiveAt_.assign(ranks, {});
    for (int r = 0; r < ranks; ++r) {
        const Size first = appendParticles(s, in[r]);
        for (Size i = first; i < s.size(); ++i) receiveAt_[r].push_back(i);
    }
    // Sorting moves every particle; the lists follow it.
    const std::vector<Size> order = sph::sortByOrderKey(s);
    std::vector<Size> newIndex(order.size());
    for (Size k = 0; k < order.size(); ++k) newIndex[order[k]] = k;
    for (auto* lists : {&sendTo_, &receiveAt_})
        for (auto& list : *lists)
            for (Size& i : list) i = newIndex[i];
    const auto ownerOf = s.template getValue<int>(sph::QuantityId::OWNER);
    owned_.resize(s.size());
    for (Size i = 0; i < s.size(); ++i) owned_[i] = char(ownerOf[i] == me);
    const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
    reference_.assign(x.begin(), x.end());
    const auto id = s.template getValue<int>(sph::QuantityId::PARTICLE_ID);
    ids_.assign(id.begin(), id.end());
    tooFar_ = false;
}

template <int Dim>
bool DomainDecomposition<Dim>::onlyAdded(const sph::Storage<Dim>& s) const {
    const auto id = s.template getValue<int>(sph::QuantityId::PARTICLE_ID);
    return id.size() >= ids_.size() && std::equal(ids_.begin(), ids_.end(), id.begin());
}

template <int Dim>
void DomainDecomposition<Dim>::adoptAdded(sph::Storage<Dim>& s) {
    const int me = comm_.rank();
    const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
    auto owner = s.template getValue<int>(sph::QuantityId::OWNER);
    std::vector<Size> keep(ids_.size());
    std::iota(keep.begin(), keep.end(), Size(0));
    for (Size i = Size(ids_.size()); i < s.size(); ++i) {
        const Vec p = domain_.wrap(x[i]);
        const int r = boxOwner(p);
        const Size at = Size(keep.size());
        if (r == me) {
            for (int q = 0; q < comm_.size(); ++q)
                if (q != me && nearBox(p, q)) sendTo_[q].push_back(at);
        } else if (nearBox(p, me)) {
            receiveAt_[r].push_back(at);
        } else {
            continue;
        }
        owner[i] = r;
        keep.push_back(i);
        owned_.push_back(char(r == me));
        reference_.push_back(x[i]);
    }
    s.gather(keep);
    const auto id = s.template getValue<int>(sph::QuantityId::PARTICLE_ID);
    ids_.assign(id.begin(), id.end());
    // The records no longer match the lists: the next refresh sends every block.
    for (Bytes& sent : lastSent_) sent.clear();
    for (Bytes& received : lastReceived_) received.clear();
}

template <int Dim>
std::vector<std::size_t> DomainDecomposition<Dim>::offsets(const sph::Storage<Dim>& s,
                                                           const std::vector<Block>& blocks,
                                                           std::size_t n) {
    std::vector<std::size_t> at(blocks.size());
    std::size_t offset = 0;
    for (const Block& whole : blocksOf(s)) {
        for (std::size_t b = 0; b < blocks.size(); ++b)
            if (blocks[b].id == whole.id && blocks[b].level == whole.level) at[b] = offset;
        offset += whole.bytes * n;
    }
    return at;
}

template <int Dim>
Bytes DomainDecomposition<Dim>::changedBlocks(const sph::Storage<Dim>& s, int r,
                                              const std::vector<Block>& blocks, QuantityIds only) {
    const std::size_t n = sendTo_[r].size();
    Bytes now;
    packParticles(s, sendTo_[r], now, only);
    Bytes& sent = lastSent_[r];
    const bool recorded = sent.size() == n * bytesPerParticle(s);
    const std::vector<std::size_t> recordAt =
        recorded ? offsets(s, blocks, n) : std::vector<std::size_t>{};
    Bytes message(blocks.size(), 0);
    std::size_t from = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const std::size_t size = blocks[b].bytes * n;
        const char* block = now.data() + from;
        if (!recorded || std::memcmp(sent.data() + recordAt[b], block, size) != 0) {
            message[b] = 1;
            message.insert(message.end(), block, block + size);
            if (recorded) std::memcpy(sent.data() + recordAt[b], block, size);
        }
        from += size;
    }
    if (!recorded && only.empty()) sent = std::move(now);
    return message;
}

template <int Dim>
double DomainDecomposition<Dim>::maxDisplacement(const sph::Storage<Dim>& s) const {
    const auto x = s.template getValue<Vec>(sph::QuantityId::POSITION);
    if (x.size() != reference_.size()) return std::numeric_limits<double>::infinity();
    double d2 = 0;
    for (Size i = 0; i < x.size(); ++i)
        d2 = std::max(d2, normSqr(domain_.minimumImage(x[i] - reference_[i])));
    return std::sqrt(d2);
}

template <int Dim>
void DomainDecomposition<Dim>::checkDisplacement(const sph::Storage<Dim>& s) {
    tooFar_ = tooFar_ || !(maxDisplacement(s) < 0.5 * (haloRadius_ - radius_));
}

}  // namespace num::parallel
