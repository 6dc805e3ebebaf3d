// Pairwise sums: IDerivative computes what neighbours contribute to a particle; results go to
// Accumulated buffers (one set per block of particles), summed in a fixed order after the loop.
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <typeindex>
#include <utility>
#include <vector>

#include "sph/accumulated.hpp"
#include "sph/derivative_arguments.hpp"
#include "sph/formulas/pair_geometry.hpp"
#include "sph/settings.hpp"
#include "sph/storage.hpp"
#include "sph/type_name.hpp"

namespace num::sph {

/// The geometry of all neighbours of a particle, parallel to its neighbour and gradient lists.
template <int Dim>
struct NeighbourGeometry {
    ArrayView<const Vector<Dim>> dx;
    ArrayView<const Float> r;
    ArrayView<const Float> w;
    ArrayView<const Float> laplacian;
    ArrayView<const Float> inverseR2;
    PairGeometry<Dim> pair(std::size_t k) const {
        return {dx[k], r[k], w.empty() ? 0.0 : w[k], laplacian[k], inverseR2[k]};
    }
};

/// A pairwise sum over neighbours. The solver calls create once per block, initialize once per
/// evaluation, then evalSymmetric or evalAsymmetric for every particle of the block.
/// Symmetric: `neighs` holds each pair once (j after i in the cell order of the neighbour search)
/// and the derivative writes both i and j.
/// Asymmetric: `neighs` holds all neighbours and the derivative writes only i.
/// `grads[k]` = grad_i W(x_i - x_j); `geometry` carries x_i - x_j (nearest periodic image),
/// distances and, if asked for, kernel values. (The seed's signature, plus the geometry that
/// periodic boundaries need.)
template <int Dim>
class IDerivative {
  public:
    virtual ~IDerivative() = default;
    virtual void create(Accumulated<Dim>& results) = 0;
    virtual void initialize(const Storage<Dim>& input, Accumulated<Dim>& results) = 0;
    /// Initialises this block's derivative from `first`, the same derivative of block 0,
    /// initialised for this evaluation just before: a derivative that precomputes per-particle
    /// arrays shares those of `first` instead of computing them once per block. `first` has
    /// this derivative's type. By default the derivative initialises itself.
    virtual void initializeLike(const IDerivative& first, const Storage<Dim>& input,
                                Accumulated<Dim>& results) {
        (void)first;
        initialize(input, results);
    }
    virtual void evalSymmetric(Size i, ArrayView<const Size> neighs,
                               ArrayView<const Vector<Dim>> grads,
                               const NeighbourGeometry<Dim>& geometry) = 0;
    virtual void evalAsymmetric(Size i, ArrayView<const Size> neighs,
                                ArrayView<const Vector<Dim>> grads,
                                const NeighbourGeometry<Dim>& geometry) = 0;
    /// True if eval needs kernel values W (e.g. density summation), not only gradients.
    virtual bool needsKernelValues() const { return false; }
    /// Gather (asymmetric) evaluation: true if this derivative adds anything for boundary
    /// particle i (a wall or body). The pair loop skips the boundary particles for which no
    /// derivative of the pass does; a derivative is still called for one that another needs.
    /// True by default; called after initialize.
    virtual bool gathersAtBoundary(Size i) const {
        (void)i;
        return true;
    }
};

/// CRTP helper: write one `template <bool Symmetric> void eval(Size i, Size j, const Vector& grad)`
/// (or with a fourth `const PairGeometry<Dim>&` argument) and get both evaluations, with the
/// per-pair call inlined.
template <class Derived, int Dim>
class DerivativeTemplate : public IDerivative<Dim> {
  public:
    void evalSymmetric(Size i, ArrayView<const Size> neighs, ArrayView<const Vector<Dim>> grads,
                       const NeighbourGeometry<Dim>& geometry) final {
        static_cast<Derived&>(*this).template evalNeighbours<true>(i, neighs, grads, geometry);
    }
    void evalAsymmetric(Size i, ArrayView<const Size> neighs, ArrayView<const Vector<Dim>> grads,
                        const NeighbourGeometry<Dim>& geometry) final {
        static_cast<Derived&>(*this).template evalNeighbours<false>(i, neighs, grads, geometry);
    }

    /// Evaluates one pair (used by fused derivatives).
    template <bool Symmetric>
    void evalPair(Size i, Size j, const Vector<Dim>& grad, const PairGeometry<Dim>& pair) {
        Derived& d = static_cast<Derived&>(*this);
        if constexpr (requires { d.template eval<Symmetric>(i, j, grad, pair); })
            d.template eval<Symmetric>(i, j, grad, pair);
        else
            d.template eval<Symmetric>(i, j, grad);
    }

    /// Evaluates every neighbour of particle i (used by fused derivatives). For the gather
    /// (asymmetric) evaluation a derived class may provide a loop of its own,
    /// `void gatherNeighbours(i, neighs, grads, geometry)`, which must give eval's result.
    template <bool Symmetric>
    void evalNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vector<Dim>> grads,
                        const NeighbourGeometry<Dim>& geometry) {
        Derived& d = static_cast<Derived&>(*this);
        if constexpr (!Symmetric && requires { d.gatherNeighbours(i, neighs, grads, geometry); }) {
            d.gatherNeighbours(i, neighs, grads, geometry);
        } else {
            for (std::size_t k = 0; k < neighs.size(); ++k)
                evalPair<Symmetric>(i, neighs[k], grads[k], geometry.pair(k));
        }
    }
};

/// Several DerivativeTemplates evaluated in one pass over the pairs: the per-pair calls are
/// composed at compile time, so a fused loop costs no virtual call per pair.
template <int Dim, class... Parts>
class FusedDerivative : public DerivativeTemplate<FusedDerivative<Dim, Parts...>, Dim> {
  public:
    explicit FusedDerivative(Parts... parts) : parts_(std::move(parts)...) {}
    void create(Accumulated<Dim>& r) override {
        std::apply([&](auto&... p) { ((r.setOwner(typeName(p)), p.create(r)), ...); }, parts_);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        std::apply(
            [&](auto&... p) {
                (attributingMissingQuantity([&] { p.initialize(s, r); },
                                            [&] { return "the derivative " + typeName(p); }),
                 ...);
            },
            parts_);
    }
    void initializeLike(const IDerivative<Dim>& first, const Storage<Dim>& s,
                        Accumulated<Dim>& r) override {
        const auto& firstParts = static_cast<const FusedDerivative&>(first).parts_;
        [&]<std::size_t... k>(std::index_sequence<k...>) {
            (attributingMissingQuantity(
                 [&] { std::get<k>(parts_).initializeLike(std::get<k>(firstParts), s, r); },
                 [&] { return "the derivative " + typeName(std::get<k>(parts_)); }),
             ...);
        }
        (std::index_sequence_for<Parts...>());
    }
    bool needsKernelValues() const override {
        return std::apply([](const auto&... p) { return (p.needsKernelValues() || ...); }, parts_);
    }
    bool gathersAtBoundary(Size i) const override {
        return std::apply([i](const auto&... p) { return (p.gathersAtBoundary(i) || ...); },
                          parts_);
    }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector<Dim>& grad, const PairGeometry<Dim>& pair) {
        std::apply([&](auto&... p) { (p.template evalPair<Symmetric>(i, j, grad, pair), ...); },
                   parts_);
    }
    /// Per particle, each part's loop over the neighbours in turn: the neighbour list, its
    /// geometry and the particle's own data are shared while hot in cache, and each part's
    /// loop stays small enough to keep its sums in registers (measured faster than one loop
    /// calling every part per pair; see docs/performance.md).
    template <bool Symmetric>
    void evalNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vector<Dim>> grads,
                        const NeighbourGeometry<Dim>& geometry) {
        std::apply(
            [&](auto&... p) {
                (p.template evalNeighbours<Symmetric>(i, neighs, grads, geometry), ...);
            },
            parts_);
    }

  private:
    std::tuple<Parts...> parts_;
};

/// A part of a FusedDerivative that may be absent: it forwards everything to the part it holds,
/// or does nothing. Lets one fused type serve every subset of its parts (one predictable
/// branch per pair and part instead of one instantiation per subset).
template <class Part, int Dim>
class OptionalPart : public DerivativeTemplate<OptionalPart<Part, Dim>, Dim> {
  public:
    OptionalPart() = default;
    explicit OptionalPart(Part part) : part_(std::move(part)) {}
    bool present() const { return part_.has_value(); }
    void create(Accumulated<Dim>& r) override {
        if (part_) r.setOwner(typeName(*part_)), part_->create(r);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) override {
        if (part_)
            attributingMissingQuantity([&] { part_->initialize(s, r); },
                                       [&] { return "the derivative " + typeName(*part_); });
    }
    void initializeLike(const IDerivative<Dim>& first, const Storage<Dim>& s,
                        Accumulated<Dim>& r) override {
        const auto& firstPart = static_cast<const OptionalPart&>(first).part_;
        if (part_)
            attributingMissingQuantity([&] { part_->initializeLike(*firstPart, s, r); },
                                       [&] { return "the derivative " + typeName(*part_); });
    }
    bool needsKernelValues() const override { return part_ && part_->needsKernelValues(); }
    bool gathersAtBoundary(Size i) const override { return part_ && part_->gathersAtBoundary(i); }
    template <bool Symmetric>
    void eval(Size i, Size j, const Vector<Dim>& grad, const PairGeometry<Dim>& pair) {
        if (part_) part_->template evalPair<Symmetric>(i, j, grad, pair);
    }
    template <bool Symmetric>
    void evalNeighbours(Size i, ArrayView<const Size> neighs, ArrayView<const Vector<Dim>> grads,
                        const NeighbourGeometry<Dim>& geometry) {
        if (part_) part_->template evalNeighbours<Symmetric>(i, neighs, grads, geometry);
    }

  private:
    std::optional<Part> part_;
};

/// The derivatives of one block, at most one per type: its results go to fixed quantities, so
/// two of one type would add into the same sums. Two requests for a type with equal
/// constructor arguments share one derivative (two terms that need the same Laplacian); a
/// request with other arguments is an error (std::logic_error): give that derivative a type of
/// its own (e.g. a template parameter) or the same arguments.
template <int Dim>
class DerivativeHolder {
  public:
    /// Adds a derivative made by the caller. Its arguments are unknown here, so a second one of
    /// its type is an error; require<T>(args...) shares equal requests.
    void require(std::unique_ptr<IDerivative<Dim>> derivative) {
        const std::string name = typeName(*derivative);
        if (const std::size_t k = indexOf(typeid(*derivative)); k < derivatives_.size())
            throw std::logic_error("DerivativeHolder::require: " + asker() + " gives a second " +
                                   name + " as an object, after " + requesters_[k] +
                                   " (require<T>(args...) shares requests with equal arguments)");
        derivatives_.push_back(std::move(derivative));
        arguments_.push_back(nullptr);
        requesters_.push_back(asker());
    }
    /// Requires a derivative T(args...), or shares the one required with equal arguments.
    template <class T, class... Args>
    void require(Args&&... args) {
        std::shared_ptr<const detail::DerivativeArguments> key;
        if constexpr ((std::copy_constructible<std::decay_t<Args>> && ...))
            key = std::make_shared<const detail::DerivativeArgumentsOf<std::decay_t<Args>...>>(
                args...);
        if (const std::size_t k = indexOf(typeid(T)); k < derivatives_.size()) {
            if (key && arguments_[k] && arguments_[k]->equals(*key)) {
                if (requesters_[k].find(asker()) == std::string::npos)
                    requesters_[k] += " and " + asker();
                return;
            }
            throw std::logic_error(
                "DerivativeHolder::require: " + asker() + " asks for a " + typeName(typeid(T)) +
                " with constructor arguments other than those of " + requesters_[k] +
                "; both would add into the same sums. Give the second a type of its own, or the "
                "same arguments to share it");
        }
        derivatives_.push_back(std::make_unique<T>(std::forward<Args>(args)...));
        arguments_.push_back(std::move(key));
        requesters_.push_back(asker());
    }

    /// Names the term whose setDerivatives runs next (EquationHolder does), for messages.
    void setRequester(std::string term) { requester_ = std::move(term); }

    /// Replaces the derivatives of the listed types that this holder has (at least two) by one
    /// FusedDerivative of them, evaluated in one pass over the pairs with the per-pair calls
    /// inlined. Parts are evaluated per pair in the listed order; the fused derivative takes the
    /// place of the first of them. Call after every term has required its derivatives (a
    /// FuseDerivatives term placed last does this).
    template <class... Parts>
    void fuse() {
        std::size_t present = 0, first = derivatives_.size();
        (
            [&] {
                const std::size_t k = indexOf<Parts>();
                if (k < derivatives_.size()) ++present, first = std::min(first, k);
            }(),
            ...);
        if (present < 2) return;
        auto fused =
            std::make_unique<FusedDerivative<Dim, OptionalPart<Parts, Dim>...>>(take<Parts>()...);
        derivatives_.insert(derivatives_.begin() + std::ptrdiff_t(first), std::move(fused));
        arguments_.insert(arguments_.begin() + std::ptrdiff_t(first), nullptr);
        requesters_.insert(requesters_.begin() + std::ptrdiff_t(first), std::string());
    }

    Size size() const { return Size(derivatives_.size()); }
    bool needsKernelValues() const {
        for (const auto& d : derivatives_)
            if (d->needsKernelValues()) return true;
        return false;
    }
    /// True if a derivative adds anything for boundary particle i in the gather evaluation.
    bool gathersAtBoundary(Size i) const {
        for (const auto& d : derivatives_)
            if (d->gathersAtBoundary(i)) return true;
        return false;
    }
    void create(Accumulated<Dim>& r) {
        for (auto& d : derivatives_) r.setOwner(typeName(*d)), d->create(r);
    }
    void initialize(const Storage<Dim>& s, Accumulated<Dim>& r) {
        for (std::size_t k = 0; k < derivatives_.size(); ++k)
            attributingMissingQuantity(
                [&] { derivatives_[k]->initialize(s, r); },
                [&] {
                    return "the derivative " + typeName(*derivatives_[k]) +
                           (requesters_[k].empty() ? "" : " (required by " + requesters_[k] + ")");
                });
    }
    /// initialize, sharing what each derivative precomputed in `first`, the holder of block 0
    /// made by the same terms and initialised for this evaluation just before (see
    /// IDerivative::initializeLike). A derivative whose type differs initialises itself.
    void initializeLike(const DerivativeHolder& first, const Storage<Dim>& s, Accumulated<Dim>& r) {
        for (std::size_t k = 0; k < derivatives_.size(); ++k)
            attributingMissingQuantity(
                [&] {
                    IDerivative<Dim>& d = *derivatives_[k];
                    if (k < first.derivatives_.size() &&
                        typeid(d) == typeid(*first.derivatives_[k]))
                        d.initializeLike(*first.derivatives_[k], s, r);
                    else
                        d.initialize(s, r);
                },
                [&] {
                    return "the derivative " + typeName(*derivatives_[k]) +
                           (requesters_[k].empty() ? "" : " (required by " + requesters_[k] + ")");
                });
    }
    void evalSymmetric(Size i, ArrayView<const Size> n, ArrayView<const Vector<Dim>> g,
                       const NeighbourGeometry<Dim>& geo) {
        for (auto& d : derivatives_) d->evalSymmetric(i, n, g, geo);
    }
    void evalAsymmetric(Size i, ArrayView<const Size> n, ArrayView<const Vector<Dim>> g,
                        const NeighbourGeometry<Dim>& geo) {
        for (auto& d : derivatives_) d->evalAsymmetric(i, n, g, geo);
    }

  private:
    std::size_t indexOf(const std::type_info& type) const {
        for (std::size_t k = 0; k < derivatives_.size(); ++k)
            if (std::type_index(typeid(*derivatives_[k])) == std::type_index(type)) return k;
        return derivatives_.size();
    }
    template <class T>
    std::size_t indexOf() const {
        return indexOf(typeid(T));
    }
    /// Moves the derivative of type T out of the holder (an empty part if there is none).
    template <class T>
    OptionalPart<T, Dim> take() {
        const std::size_t k = indexOf<T>();
        if (k == derivatives_.size()) return OptionalPart<T, Dim>();
        OptionalPart<T, Dim> part(std::move(static_cast<T&>(*derivatives_[k])));
        derivatives_.erase(derivatives_.begin() + std::ptrdiff_t(k));
        arguments_.erase(arguments_.begin() + std::ptrdiff_t(k));
        requesters_.erase(requesters_.begin() + std::ptrdiff_t(k));
        return part;
    }

    std::vector<std::unique_ptr<IDerivative<Dim>>> derivatives_;
    std::string asker() const { return requester_.empty() ? "a caller" : requester_; }

    /// The constructor arguments of each derivative (null: unknown or not comparable).
    std::vector<std::shared_ptr<const detail::DerivativeArguments>> arguments_;
    std::vector<std::string> requesters_;  ///< the terms that asked for each derivative
    std::string requester_;
};

}  // namespace num::sph
