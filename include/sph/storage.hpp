// Storage<Dim>: structure-of-arrays particle storage keyed by QuantityId.
//
// Each quantity holds a value array and, by its order, a first (dt) and second (d2t) time
// derivative array, all of one value type: Float, Vector<Dim> or int. Adding, removing and
// reordering particles applies to every quantity at once, so they stay consistent.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "sph/settings.hpp"
#include "sph/types.hpp"

namespace num::sph {

/// The value, dt and d2t buffers of one quantity (dt/d2t empty below their order).
template <class T>
struct QuantityBuffers {
    std::vector<T> value, dt, d2t;
    std::vector<T>& level(int k) { return k == 0 ? value : k == 1 ? dt : d2t; }
    const std::vector<T>& level(int k) const { return k == 0 ? value : k == 1 ? dt : d2t; }
};

template <int Dim>
class Quantity {
  public:
    using Data =
        std::variant<QuantityBuffers<Float>, QuantityBuffers<Vector<Dim>>, QuantityBuffers<int>>;

    Quantity(OrderEnum order, Data data) : order_(order), data_(std::move(data)) {}

    OrderEnum order() const { return order_; }
    int levels() const { return int(order_) + 1; }

    template <class T>
    bool holds() const {
        return std::holds_alternative<QuantityBuffers<T>>(data_);
    }

    template <class T>
    QuantityBuffers<T>& buffers() {
        if (auto* b = std::get_if<QuantityBuffers<T>>(&data_)) return *b;
        throw std::logic_error("quantity accessed with the wrong value type");
    }
    template <class T>
    const QuantityBuffers<T>& buffers() const {
        return const_cast<Quantity*>(this)->buffers<T>();
    }

    /// Raises the order (never lowers it); new derivative buffers start at zero.
    void raiseOrder(OrderEnum order, std::size_t n) {
        if (order <= order_) return;
        order_ = order;
        visit([&](auto& b) {
            for (int k = 1; k < levels(); ++k) b.level(k).resize(n);
        });
    }

    /// Calls f(buffers) with the typed buffers.
    template <class F>
    decltype(auto) visit(F&& f) {
        return std::visit(std::forward<F>(f), data_);
    }
    template <class F>
    decltype(auto) visit(F&& f) const {
        return std::visit(std::forward<F>(f), data_);
    }

  private:
    OrderEnum order_;
    Data data_;
};

/// A quantity asked of a storage that does not hold it. Terms and derivatives that meet it
/// during an evaluation say who needs the quantity (EquationHolder, DerivativeHolder).
struct MissingQuantity : std::out_of_range {
    explicit MissingQuantity(QuantityId id_, const std::string& message = "")
        : std::out_of_range(message.empty() ? "no quantity with id " + std::to_string(int(id_)) +
                                                  " in the storage"
                                            : message),
          id(id_),
          attributed(!message.empty()) {}
    QuantityId id;
    bool attributed;  ///< the message names who needs the quantity
};

/// The message for `who` that needs a quantity missing from the storage: what to call.
inline std::string missingQuantityMessage(const std::string& who, QuantityId id) {
    return who + " needs quantity " + std::to_string(int(id)) +
           ", which the storage does not hold: the terms' create() has not run on this storage "
           "since the term was added. Add the term before the storage is made (for a fluid: to "
           "FluidModel::extraTerms before makeFluidStorage), or call solver.create(storage, "
           "material) after adding it";
}

/// Runs f(); a MissingQuantity from it that names nobody yet is thrown again naming `who()`.
template <class F, class Who>
void attributingMissingQuantity(F&& f, Who&& who) {
    try {
        f();
    } catch (const MissingQuantity& e) {
        if (e.attributed) throw;
        throw MissingQuantity(e.id, missingQuantityMessage(who(), e.id));
    }
}

template <int Dim>
class Storage {
  public:
    using Vec = Vector<Dim>;

    /// Number of particles.
    Size size() const { return size_; }
    bool has(QuantityId id) const { return quantities_.count(id) != 0; }
    OrderEnum order(QuantityId id) const { return get(id).order(); }

    /// Creates the quantity with every particle at `value`, or, if it exists, keeps its values
    /// and raises its order when `order` is higher.
    template <class T>
    Quantity<Dim>& insert(QuantityId id, OrderEnum order, const T& value) {
        return insert<T>(id, order, std::vector<T>(size_, value));
    }

    /// Creates the quantity with the given values (one per particle). The first quantity of an
    /// empty storage sets the particle count. An existing quantity keeps its values.
    template <class T>
    Quantity<Dim>& insert(QuantityId id, OrderEnum order, std::vector<T> values) {
        if (auto it = quantities_.find(id); it != quantities_.end()) {
            if (!it->second.template holds<T>())
                throw std::logic_error("quantity " + std::to_string(int(id)) +
                                       " exists with another value type");
            it->second.raiseOrder(order, size_);
            return it->second;
        }
        if (quantities_.empty()) size_ = Size(values.size());
        if (values.size() != size_)
            throw std::invalid_argument("quantity " + std::to_string(int(id)) + " has " +
                                        std::to_string(values.size()) + " values, storage has " +
                                        std::to_string(size_) + " particles");
        QuantityBuffers<T> b;
        b.value = std::move(values);
        if (order >= OrderEnum::FIRST) b.dt.assign(size_, T{});
        if (order >= OrderEnum::SECOND) b.d2t.assign(size_, T{});
        return quantities_.emplace(id, Quantity<Dim>(order, std::move(b))).first->second;
    }

    template <class T>
    ArrayView<T> getValue(QuantityId id) {
        return level<T>(id, 0);
    }
    template <class T>
    ArrayView<const T> getValue(QuantityId id) const {
        return level<T>(id, 0);
    }
    template <class T>
    ArrayView<T> getDt(QuantityId id) {
        return level<T>(id, 1);
    }
    template <class T>
    ArrayView<const T> getDt(QuantityId id) const {
        return level<T>(id, 1);
    }
    template <class T>
    ArrayView<T> getD2t(QuantityId id) {
        return level<T>(id, 2);
    }
    template <class T>
    ArrayView<const T> getD2t(QuantityId id) const {
        return level<T>(id, 2);
    }

    /// Several values of one type at once: `std::tie(u, m, rho) = s.getValues<Float>(...)`.
    template <class T, class... Ids>
    auto getValues(QuantityId first, Ids... rest) {
        return std::make_tuple(getValue<T>(first), getValue<T>(rest)...);
    }
    template <class T, class... Ids>
    auto getValues(QuantityId first, Ids... rest) const {
        return std::make_tuple(getValue<T>(first), getValue<T>(rest)...);
    }

    Quantity<Dim>& get(QuantityId id) {
        auto it = quantities_.find(id);
        if (it == quantities_.end()) throw MissingQuantity(id);
        return it->second;
    }
    const Quantity<Dim>& get(QuantityId id) const { return const_cast<Storage*>(this)->get(id); }

    /// Calls f(id, quantity) for every quantity in ascending id order.
    template <class F>
    void forEach(F&& f) {
        for (auto& [id, q] : quantities_) f(id, q);
    }
    template <class F>
    void forEach(F&& f) const {
        for (const auto& [id, q] : quantities_) f(id, q);
    }

    /// Appends the particles of `other`, which must have the same quantities and types (halo
    /// particles, a new inlet...). Its materials join this storage's table (a material both
    /// share is kept once) and the appended QuantityId::MATERIAL indices are renumbered.
    void append(const Storage& other) {
        if (other.quantities_.empty()) return;
        if (quantities_.empty()) {
            *this = other;
            return;
        }
        if (other.quantities_.size() != quantities_.size())
            throw std::invalid_argument("append: storages hold different quantities");
        for (auto& [id, q] : quantities_) {
            auto it = other.quantities_.find(id);
            if (it == other.quantities_.end())
                throw std::invalid_argument("append: quantity " + std::to_string(int(id)) +
                                            " missing in the appended storage");
            const Quantity<Dim>& o = it->second;
            q.raiseOrder(o.order(), size_);
            // Init-captures: clang before 16 cannot capture a structured binding.
            q.visit([&, &q = q](auto& b) {
                using T = typename std::decay_t<decltype(b.value)>::value_type;
                if (!o.template holds<T>())
                    throw std::invalid_argument("append: value types differ");
                const auto& ob = o.template buffers<T>();
                for (int k = 0; k < q.levels(); ++k) {
                    auto& dst = b.level(k);
                    const auto& src = ob.level(k);
                    if (src.empty())
                        dst.resize(dst.size() + other.size_);
                    else
                        dst.insert(dst.end(), src.begin(), src.end());
                }
            });
        }
        std::vector<int> materialIndex(other.materials_.size());
        for (std::size_t m = 0; m < other.materials_.size(); ++m) {
            auto it = std::find(materials_.begin(), materials_.end(), other.materials_[m]);
            materialIndex[m] = int(it - materials_.begin());
            if (it == materials_.end()) materials_.push_back(other.materials_[m]);
        }
        if (has(QuantityId::MATERIAL) && !materialIndex.empty()) {
            auto& ids = get(QuantityId::MATERIAL).template buffers<int>().value;
            for (std::size_t i = size_; i < ids.size(); ++i)
                if (ids[i] >= 0 && std::size_t(ids[i]) < materialIndex.size())
                    ids[i] = materialIndex[ids[i]];
        }
        size_ += other.size_;
    }

    /// A storage with the same quantities, orders and materials and no particles.
    Storage emptyCopy() const {
        Storage out;
        for (const auto& [id, q] : quantities_)
            q.visit([&, &id = id, &q = q](const auto& b) {
                using T = typename std::decay_t<decltype(b.value)>::value_type;
                out.quantities_.emplace(id, Quantity<Dim>(q.order(), QuantityBuffers<T>{}));
            });
        out.materials_ = materials_;
        return out;
    }

    /// Sets the number of particles: new ones at the end are zero (value-initialised) in every
    /// quantity and level; particles beyond n are dropped.
    void resize(Size n) {
        for (auto& [id, q] : quantities_)
            q.visit([&, &q = q](auto& b) {
                for (int k = 0; k < q.levels(); ++k) b.level(k).resize(n);
            });
        size_ = n;
    }

    /// Removes the particles whose indices are listed (any order, duplicates ignored).
    void remove(std::vector<Size> indices) {
        std::vector<char> drop(size_, 0);
        for (Size i : indices) {
            if (i >= size_) throw std::out_of_range("remove: particle index out of range");
            drop[i] = 1;
        }
        std::vector<Size> keep;
        keep.reserve(size_);
        for (Size i = 0; i < size_; ++i)
            if (!drop[i]) keep.push_back(i);
        gather(keep);
    }

    /// Reorders particles: the new particle k is the old particle permutation[k].
    void reorder(const std::vector<Size>& permutation) {
        if (permutation.size() != size_)
            throw std::invalid_argument("reorder: permutation has the wrong length");
        std::vector<char> seen(size_, 0);
        for (Size p : permutation) {
            if (p >= size_ || seen[p])
                throw std::invalid_argument("reorder: not a permutation of the particles");
            seen[p] = 1;
        }
        // In place, cycle by cycle: a copy of each array (gather's) would raise the peak memory
        // of every reordering by the largest array.
        for (auto& [id, q] : quantities_) {
            q.visit([&, &q = q](auto& b) {
                for (int k = 0; k < q.levels(); ++k) {
                    auto& v = b.level(k);
                    std::fill(seen.begin(), seen.end(), char(0));
                    for (std::size_t start = 0; start < permutation.size(); ++start) {
                        if (seen[start]) continue;
                        auto first = std::move(v[start]);
                        std::size_t n = start;
                        for (seen[n] = 1; permutation[n] != start; n = permutation[n]) {
                            v[n] = std::move(v[permutation[n]]);
                            seen[permutation[n]] = 1;
                        }
                        v[n] = std::move(first);
                    }
                }
            });
        }
    }

    /// Keeps the particles listed, in the order listed (indices may repeat: copies).
    void gather(const std::vector<Size>& order) {
        for (Size i : order)
            if (i >= size_) throw std::out_of_range("gather: particle index out of range");
        for (auto& [id, q] : quantities_) {
            q.visit([&, &q = q](auto& b) {
                for (int k = 0; k < q.levels(); ++k) {
                    auto& v = b.level(k);
                    std::remove_reference_t<decltype(v)> out(order.size());
                    for (std::size_t n = 0; n < order.size(); ++n) out[n] = v[order[n]];
                    v = std::move(out);
                }
            });
        }
        size_ = Size(order.size());
    }

    /// Materials referenced by QuantityId::MATERIAL.
    std::vector<std::shared_ptr<IMaterial>>& materials() { return materials_; }
    const std::vector<std::shared_ptr<IMaterial>>& materials() const { return materials_; }

  private:
    template <class T>
    ArrayView<T> level(QuantityId id, int k) {
        Quantity<Dim>& q = get(id);
        if (k > int(q.order()))
            throw std::logic_error("quantity " + std::to_string(int(id)) +
                                   " has no time derivative of order " + std::to_string(k));
        auto& v = q.template buffers<T>().level(k);
        return ArrayView<T>(v.data(), v.size());
    }
    template <class T>
    ArrayView<const T> level(QuantityId id, int k) const {
        return const_cast<Storage*>(this)->template level<T>(id, k);
    }

    std::map<QuantityId, Quantity<Dim>> quantities_;
    Size size_ = 0;
    std::vector<std::shared_ptr<IMaterial>> materials_;
};

}  // namespace num::sph
