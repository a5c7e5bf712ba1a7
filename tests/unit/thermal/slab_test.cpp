// Tests of the 1-D implicit slab solver against analytic heat-conduction solutions.
#include "thermal/slab.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../record_property.hpp"
#include "core/error.hpp"

namespace th = sigchain::thermal;

namespace {

constexpr double kPi = std::numbers::pi;

// Fourier component of the surface temperature at angular frequency w over one period
// of samples (time t_s, temperature); returns amplitude and phase (rad).
struct Harmonic {
    double amplitude = 0;
    double phase_rad = 0;
};

}  // namespace

// Periodic absorbed flux q0 cos(wt) on a thick slab with a linear surface loss h:
// the classical semi-infinite solution (Carslaw & Jaeger, Conduction of Heat in
// Solids, 2nd ed., 1959, sec. 2.6) gives the surface amplitude
// q0 / sqrt((h + k/d)^2 + (k/d)^2) and lag atan((k/d)/(h + k/d)) / w, d = sqrt(2 alpha/w).
// For k = 1.4, rho c = 2e6, h = 20, q0 = 400, 24 h: 12.60 K and 1.24 h.
TEST(Slab, PeriodicSurfaceFluxMatchesSemiInfiniteSolution) {
    const double k = 1.4, rho_c = 2e6, h = 20, q0 = 400, period_s = 86400;
    const double w = 2 * kPi / period_s;
    const double d = std::sqrt(2 * (k / rho_c) / w);
    const double kd = k / d;
    const double amp_ref = q0 / std::hypot(h + kd, kd);
    const double lag_ref_s = std::atan(kd / (h + kd)) / w;
    ASSERT_NEAR(amp_ref, 12.60, 0.005);
    ASSERT_NEAR(lag_ref_s / 3600, 1.24, 0.005);

    // 1 m thick (7.2 damping depths: the back face sees exp(-7.2) = 7e-4 of the wave),
    // insulated at the back; 60 cells growing by 1.08 from each face (2.3 mm at the front).
    th::SlabProperties p{1.0, 2000.0, 1000.0, k, 0.0};
    const double t_air = 300;
    th::Slab slab(p, th::slab_nodes(1.0, 60, 1.08), t_air);
    const double dt = 60;
    const int steps_per_period = static_cast<int>(period_s / dt);
    Harmonic hm;
    // Eight periods: the start transient (from a uniform profile) decays; the last is fitted.
    for (int period = 0; period < 8; ++period) {
        double a = 0, b = 0;
        for (int s = 1; s <= steps_per_period; ++s) {
            double t = (period * steps_per_period + s) * dt;
            slab.step(dt, {q0 * std::cos(w * t) + h * t_air, h}, {0, 0});
            a += (slab.front_k() - t_air) * std::cos(w * t);
            b += (slab.front_k() - t_air) * std::sin(w * t);
        }
        hm.amplitude = 2 * std::hypot(a, b) / steps_per_period;
        hm.phase_rad = std::atan2(b, a);
    }
    // Requirement: amplitude within 1 %. Phase: backward Euler lags by about
    // dt/2 = 30 s and the grid adds a little; 2 % of the lag (89 s) bounds both.
    EXPECT_NEAR(hm.amplitude, amp_ref, 0.01 * amp_ref);
    EXPECT_NEAR(hm.phase_rad / w, lag_ref_s, 0.02 * lag_ref_s);
    sigchain::unit::record("amplitude_K", hm.amplitude);
    sigchain::unit::record("lag_h", hm.phase_rad / w / 3600);
    sigchain::unit::record("reference_amplitude_K", amp_ref);
    sigchain::unit::record("reference_lag_h", lag_ref_s / 3600);
    sigchain::unit::record("amplitude_limit_relative", 0.01);
    sigchain::unit::record("lag_limit_relative", 0.02);
    std::printf("amplitude %.4f K (ref %.4f), lag %.4f h (ref %.4f)\n", hm.amplitude, amp_ref,
                hm.phase_rad / w / 3600, lag_ref_s / 3600);
}

// A thin, highly conductive plate is a lumped capacity: with a surface conductance h
// on both faces toward T_inf, T - T_inf decays as exp(-2 h t / (rho c L)).
TEST(Slab, ThinPlateDecaysLikeLumpedCapacity) {
    const double h = 10, L = 0.002, rho = 2700, c = 900, k = 237;
    th::SlabProperties p{L, rho, c, k, 0.0};
    th::Slab slab(p, th::slab_nodes(L, 4, 1.0), 350);
    const double t_inf = 300, dt = 1;
    const double tau = rho * c * L / (2 * h);  // 243 s
    for (int s = 0; s < 600; ++s) slab.step(dt, {h * t_inf, h}, {h * t_inf, h});
    double expect = t_inf + 50 * std::exp(-600 / tau);
    // Biot number h L / k = 8e-5, so the plate is isothermal; backward Euler with
    // dt = tau/243 errs by about (dt/tau)/2 per unit time constant: 0.5 % of 4.2 K.
    EXPECT_NEAR(slab.front_k(), expect, 0.01 * (expect - t_inf));
    EXPECT_NEAR(slab.front_k(), slab.back_k(), 1e-3);
}

// Conservation: with any fluxes, stored energy changes by exactly the net flux in
// (backward Euler on finite volumes conserves to rounding).
TEST(Slab, StoredEnergyChangesByNetFlux) {
    th::SlabProperties p{0.1, 2300, 880, 1.4, 50.0};
    th::Slab slab(p, th::slab_nodes(0.1, 12, 1.2), 290);
    double in = 0, e0 = slab.stored_j_m2();
    for (int s = 0; s < 500; ++s) {
        th::FaceFlux f{300 + 20 * 290, 20}, b{5 * 280, 5};
        slab.step(30, f, b);
        in += 30 * (f.source_w_m2 - f.conductance_w_m2_k * slab.front_k() + b.source_w_m2 -
                    b.conductance_w_m2_k * slab.back_k() + slab.internal_power_w_m2());
    }
    // Rounding of sums of ~6e7 J m-2: relative 1e-9 is far above double precision.
    EXPECT_NEAR(slab.stored_j_m2() - e0, in, 1e-9 * slab.stored_j_m2());
}

TEST(Slab, RejectsNonPhysicalProperties) {
    EXPECT_THROW(th::Slab(th::SlabProperties{0.1, 0, 880, 1.4, 0}, th::slab_nodes(0.1, 4, 1), 300),
                 sigchain::Error);
    EXPECT_THROW(th::slab_nodes(0, 4, 1), sigchain::Error);
}
