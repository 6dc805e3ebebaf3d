// The kick-drift-kick leapfrog's updates of one particle, written once for the CPU engine
// (integrators/leapfrog_kdk.hpp) and the CUDA back end's device step (device/fluid_passes.hpp):
//     v += dt/2 a_n;  x += dt v;  evaluate;  v += dt/2 a_{n+1}           (second order)
//     q* = q_n + dt dq_n;  evaluate;  q_{n+1} = q* + dt/2 (dq* - dq_n)   (first order, Heun)
// (Hairer, Lubich & Wanner 2003, sec. I.1.4). half = dt / 2.
#pragma once

#include "sph/host_device.hpp"
#include "sph/types.hpp"

namespace num::sph::formulas {

/// The first kick and the drift of a second-order quantity x with rate v and acceleration a.
template <class V>
NUMERICS_HD void kickDrift(V& x, V& v, const V& a, Float half, Float dt) {
    v += a * half;
    x += v * dt;
}

/// The second kick, with the new acceleration.
template <class V>
NUMERICS_HD void kick(V& v, const V& a, Float half) {
    v += a * half;
}

/// Heun's predictor of a first-order quantity q with rate dq; the rate is kept in `old`.
template <class T>
NUMERICS_HD void heunPredict(T& q, T& old, const T& dq, Float dt) {
    old = dq;
    q += dq * dt;
}

/// Heun's corrector, with the rate dq at the predicted state.
template <class T>
NUMERICS_HD void heunCorrect(T& q, const T& dq, const T& old, Float half) {
    q += (dq - old) * half;
}

}  // namespace num::sph::formulas
