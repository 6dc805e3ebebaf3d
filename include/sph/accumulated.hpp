// Accumulated: the buffers a pair loop sums into, one set per block, added up in a fixed order.
#pragma once

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "sph/storage.hpp"

namespace num::sph {

/// Buffers a pair loop accumulates into. Each buffer names the storage level it goes to after
/// the loop: the value (OrderEnum::ZERO) of its quantity is replaced by the sum; dt (FIRST) or
/// d2t (SECOND) is added to (the solver zeroes the highest derivatives before initialize, so
/// the terms' own contributions and the pair sums add up whatever their order).
/// With sumInStorage() (the gather loop, where each particle's sums are written by the one
/// block that gathers it) no target has a buffer: the derivatives sum into the stored arrays
/// themselves, which saves a copy of each per particle and the additions after the loop. A
/// value target keeps its previous value until startSums() zeroes it just before the pair loop
/// (a derivative reads the previous value in initialize, never in its pair sums); a dt or d2t
/// target holds what terms added in their initialize, and the pair sums add on from there
/// (the built-in terms add to rates in finalize, so their sums start from 0 as in a buffer:
/// results bitwise the same; a term that adds in initialize changes only the round-off).
template <int Dim>
class Accumulated {
  public:
    template <class T>
    void insert(QuantityId id, OrderEnum target = OrderEnum::ZERO) {
        for (auto& b : buffers_)
            if (b.id == id) {
                if (!std::holds_alternative<std::vector<T>>(b.data) || b.target != target)
                    throw std::logic_error("accumulated quantity " + std::to_string(int(id)) +
                                           " requested twice with different types or targets");
                return;
            }
        buffers_.push_back({id, target, std::vector<T>(inStorage_ ? 0 : size_), owner_});
    }

    /// Targets inserted from now on are summed in the storage (see above). Call before insert.
    void sumInStorage() { inStorage_ = true; }

    /// Names the derivative whose buffers the next insert() calls make (for messages).
    void setOwner(std::string owner) { owner_ = std::move(owner); }

    template <class T>
    ArrayView<T> getValue(QuantityId id) {
        for (auto& b : buffers_)
            if (b.id == id) {
                if (inStorage_) return bind<T>(b);
                auto& v = std::get<std::vector<T>>(b.data);
                return ArrayView<T>(v.data(), v.size());
            }
        throw std::out_of_range("no accumulated quantity " + std::to_string(int(id)));
    }

    /// Sets every buffer to n zeros.
    void reset(Size n) {
        size_ = n;
        if (!inStorage_)
            for (auto& b : buffers_)
                std::visit(
                    [&](auto& v) { v.assign(n, typename std::decay_t<decltype(v)>::value_type{}); },
                    b.data);
    }

    /// Sets every buffer to zeros, one per particle of `storage`; the targets summed in the
    /// storage are its arrays from now on (values stay as they are until startSums).
    void reset(Storage<Dim>& storage) {
        reset(storage.size());
        storage_ = &storage;
    }

    /// Zeroes the value targets summed in the storage: call after the derivatives' initialize,
    /// before the pair loop. forRanges as for addInto.
    template <class ForRanges>
    void startSums(ForRanges&& forRanges) {
        if (!inStorage_) return;
        for (auto& b : buffers_)
            if (b.target == OrderEnum::ZERO)
                std::visit(
                    [&](const auto& v) {
                        using T = typename std::decay_t<decltype(v)>::value_type;
                        ArrayView<T> view;
                        attributingMissingQuantity([&] { view = bind<T>(b); },
                                                   [&] { return "the pair sum of " + b.owner; });
                        forRanges(Size(view.size()), [&](Size begin, Size end) {
                            std::fill(view.begin() + begin, view.begin() + end, T{});
                        });
                    },
                    b.data);
    }

    /// Number of buffers.
    Size bufferCount() const { return Size(buffers_.size()); }
    /// True if a buffer for `id` exists.
    bool has(QuantityId id) const {
        for (const auto& b : buffers_)
            if (b.id == id) return true;
        return false;
    }

    /// Moves the sum over blocks into the storage, block 0 first, so that the order of the
    /// additions never depends on threads: value targets become the sum, dt and d2t targets
    /// get the sum added. Every block must have been created by the same derivatives.
    static void addInto(Storage<Dim>& storage, std::span<const Accumulated> blocks) {
        addInto(storage, blocks, [](Size n, const auto& range) { range(Size(0), n); });
    }

    /// addInto with the particles split into ranges run by forRanges(n, range), which calls
    /// range(begin, end) on chunks of [0, n) (in parallel, e.g. IScheduler::parallelFor). Each
    /// particle's sum is the same whatever the split.
    template <class ForRanges>
    static void addInto(Storage<Dim>& storage, std::span<const Accumulated> blocks,
                        ForRanges&& forRanges) {
        if (blocks.empty() || blocks[0].inStorage_) return;  // summed there already
        for (std::size_t k = 0; k < blocks[0].buffers_.size(); ++k) {
            const SumBuffer& b0 = blocks[0].buffers_[k];
            std::visit(
                [&](const auto& v0) {
                    using T = typename std::decay_t<decltype(v0)>::value_type;
                    ArrayView<T> dst;
                    attributingMissingQuantity([&] { dst = target<T>(storage, b0); },
                                               [&] { return "the pair sum of " + b0.owner; });
                    if (v0.size() != dst.size())
                        throw std::logic_error("accumulated quantity " +
                                               std::to_string(int(b0.id)) +
                                               " does not match the particle count");
                    const bool replace = b0.target == OrderEnum::ZERO;
                    forRanges(Size(dst.size()), [&](Size begin, Size end) {
                        if (replace) std::fill(dst.begin() + begin, dst.begin() + end, T{});
                        for (const Accumulated& blk : blocks) {
                            const T* v = std::get<std::vector<T>>(blk.buffers_[k].data).data();
                            for (Size i = begin; i < end; ++i) dst[i] += v[i];
                        }
                    });
                },
                b0.data);
        }
    }

  private:
    struct SumBuffer {
        QuantityId id;
        OrderEnum target;
        std::variant<std::vector<Float>, std::vector<Vector<Dim>>> data;  ///< empty in storage
        std::string owner;  ///< the derivative that made the buffer
    };
    /// The storage's array of a target summed in the storage (MissingQuantity if it has none).
    template <class T>
    ArrayView<T> bind(const SumBuffer& b) {
        if (!storage_) throw std::logic_error("Accumulated: reset(storage) before the sums");
        return target<T>(*storage_, b);
    }
    template <class T>
    static ArrayView<T> target(Storage<Dim>& s, const SumBuffer& b) {
        switch (b.target) {
            case OrderEnum::ZERO:
                return s.template getValue<T>(b.id);
            case OrderEnum::FIRST:
                return s.template getDt<T>(b.id);
            default:
                return s.template getD2t<T>(b.id);
        }
    }
    std::vector<SumBuffer> buffers_;
    Size size_ = 0;
    bool inStorage_ = false;
    Storage<Dim>* storage_ = nullptr;  ///< of the last reset(storage)
    std::string owner_ = "a derivative";
};

}  // namespace num::sph
