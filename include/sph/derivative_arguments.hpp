// The constructor arguments of a derivative a term required (DerivativeHolder::require<T>),
// kept to compare with later requests for the same type: equal arguments share one derivative.
#pragma once

#include <concepts>
#include <tuple>

namespace num::sph {

namespace detail {

/// The constructor arguments of a required derivative, compared with those of a later request.
struct DerivativeArguments {
    virtual ~DerivativeArguments() = default;
    virtual bool equals(const DerivativeArguments& other) const = 0;
};

template <class... Args>
struct DerivativeArgumentsOf final : DerivativeArguments {
    explicit DerivativeArgumentsOf(const Args&... args) : values(args...) {}
    bool equals(const DerivativeArguments& other) const override {
        const auto* o = dynamic_cast<const DerivativeArgumentsOf*>(&other);
        return o && std::apply(
                        [&](const auto&... a) {
                            return std::apply([&](const auto&... b) { return (same(a, b) && ...); },
                                              o->values);
                        },
                        values);
    }
    /// Arguments without == (e.g. a std::function) never count as equal.
    template <class T>
    static bool same(const T& a, const T& b) {
        if constexpr (std::equality_comparable<T>)
            return a == b;
        else
            return false;
    }
    std::tuple<Args...> values;
};

}  // namespace detail

}  // namespace num::sph
