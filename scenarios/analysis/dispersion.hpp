#pragma once
/// Dispersion of particles along one axis: the mean squared displacement (MSD) since a start
/// instant, and the dispersion coefficient D (m^2/s) fitted to it, either from its early growth
/// MSD ~ 2 D t before a bounded bed saturates it (fit_dispersion) or from the exact saturating
/// curve of tracers that fill a bed between reflecting ends (fit_confined_dispersion). Pure
/// functions on plain data; the run loop calls them at each sample.
#include <cstddef>
#include <vector>

#include "core/vec3.hpp"

namespace carom {

/// Mean over particles of (now_i[axis] - start_i[axis])^2, m^2: the positions must be unwrapped
/// (no periodic folding along `axis` between start and now). NaN for no particles.
/// Throws std::invalid_argument if now and start differ in length or the axis is not 0-2.
double mean_squared_displacement(const std::vector<Vec3>& now, const std::vector<Vec3>& start,
                                 int axis);

/// A dispersion coefficient fitted to a mean-squared-displacement curve.
struct Dispersion {
  double coefficient;  ///< D, m^2/s; NaN with too few points (see each fit).
  double fit_start;    ///< Time of the first sample in the fit window, s.
  double fit_end;      ///< Time of the last sample in the fit window, s.
  std::size_t points;  ///< Samples in the fit window.
  /// fit_dispersion: at least 3 samples in the window and D > 0; fit_confined_dispersion: at
  /// least 2 samples at t > 0 and D inside the search range.
  bool valid;
};

/// Dispersion coefficient from MSD(t) = a + 2 D t, fitted by least squares to the samples
/// (times in s from the start instant, msd in m^2) inside the window:
///   from the first sample with t > 0 up to the last sample before the MSD first exceeds
///   window_fraction * saturation_msd,
/// non-finite samples skipped, the others taken in time order.
///
/// saturation_msd (m^2) is where a bounded bed saturates the MSD: for tracers spread uniformly
/// over a height H it tends to H^2/6. Pass +inf (or 0) for an unbounded direction: the window is
/// then every sample with t > 0.
///
/// Why a line with an intercept: at short times the motion is ballistic (MSD ~ <v^2> t^2) and
/// the diffusive asymptote is MSD = 2 D (t - tau), tau the velocity correlation time; a line
/// through the origin would turn that offset into a slope error of order tau/t_window, the
/// intercept a = -2 D tau absorbs it. The t = 0 sample (MSD = 0 by construction) lies off that
/// asymptote and is left out.
/// Why the window ends early: the ends of the bed fold the walk back. For tracers that fill the
/// bed uniformly between reflecting ends, MSD = 2 D t [1 - (8/(3 sqrt(2 pi))) sqrt(2 D t)/H] up to
/// exponentially small terms, so the fitted D comes out low by about 0.45 sqrt(window_fraction)
/// (10 % at the default 0.05, 4.5 % at 0.01); tracers that stay more than ~4 sqrt(window_fraction
/// * saturation_msd) from the ends during the window are not biased. The window must hold at
/// least 3 samples (two parameters and a residual), so the MSD has to be sampled at intervals
/// below about window_fraction * saturation_msd / (6 D); otherwise valid is false.
/// Throws std::invalid_argument if times and msd differ in length or window_fraction is not in
/// (0, 1].
Dispersion fit_dispersion(const std::vector<double>& times, const std::vector<double>& msd,
                          double saturation_msd, double window_fraction = 0.05);

/// Mean squared displacement (m^2) at `time` (s) of tracers spread uniformly over a bed of
/// height H between reflecting ends, dispersing with a homogeneous coefficient D (m^2/s):
///   MSD(t) = S [1 - (96/pi^4) sum_{m odd} m^-4 exp(-m^2 pi^2 D t/H^2)],   S = H^2/6,
/// S = saturation_msd (m^2). (The modes cos(m pi x/H) of the diffusion equation with zero flux
/// at the ends; only odd m survive the uniform average.) It grows as 2 D t at first and tends to
/// S, reaching 90 % of it at D t/H^2 = 0.23. Evaluated to about 1e-14 relative: the series where
/// D t/H^2 >= 0.01 (its terms fall as exp(-m^2 pi^2 D t/H^2)), below that the short-time form
/// S [12 tau - (32/sqrt(pi)) tau^(3/2)], tau = D t/H^2, whose neglected image terms are
/// O(exp(-1/(4 tau))). NaN for a negative or non-finite time.
double confined_mean_squared_displacement(double time, double coefficient, double saturation_msd);

/// Dispersion coefficient from the whole MSD record of tracers that fill a bounded bed: the D
/// that minimizes sum_i (msd_i - confined_mean_squared_displacement(t_i, D, saturation_msd))^2
/// over the samples with finite t_i >= 0 and finite msd_i (times in s from the start instant,
/// msd in m^2; the window is every such sample: fit_start and fit_end are the first and last of
/// them, points their number).
///
/// Assumptions, all of the exact curve: the tracers start spread uniformly over the bed (e.g.
/// every particle of a bed along its height, not a tagged layer); the ends reflect (the floor,
/// and the free surface of a bed that does not lose particles), with no periodic folding along
/// the axis; D is the same everywhere in the bed; the motion is diffusive from t = 0. A ballistic
/// start with velocity correlation time tau_c acts as a delay of about tau_c, which biases D low
/// by a relative amount of order tau_c over the fitted times: negligible when tau_c << H^2/D.
/// saturation_msd must be the plateau H^2/6 of the height the tracers actually fill.
///
/// Which estimator: this one when the tracers fill the bed uniformly between reflecting ends. It
/// has no wall bias (fit_dispersion's is about -0.45 sqrt(window_fraction), -10 % at the default
/// window), uses every sample, and works with sparse sampling: a few samples over the saturation
/// time H^2/D suffice (fit_dispersion needs 3 below 5 % of saturation, i.e. sampling intervals
/// below about 0.0015 H^2/D). fit_dispersion when the direction is unbounded or periodic, when the
/// tracers are a layer far from the ends, when D varies over the bed (e.g. with height in a
/// bubbling bed: then the early slope is the tracers' mean D and the saturating shape is not this
/// one), or when the ballistic start lasts a noticeable part of the record.
/// Standard error, measured on exact random walks of N uniform tracers (test_dispersion.cpp):
/// about 1.1 sqrt(2/N) D sampled densely up to 0.1 H^2/D (as fit_dispersion's there), about
/// 1.6 sqrt(2/N) D from 5 samples up to 0.25 H^2/D.
///
/// The solver cannot diverge: the sum of squares is scanned over a logarithmic grid of D from
/// 1e-8 H^2/t_max (no dispersion seen within the record) to 1e2 H^2/t_min (t_min the first
/// positive time: saturated before it), 40 points per decade, and the best grid point is refined
/// by bisection in ln D on the normal equation between its neighbours, which brackets it (a
/// golden-section search on the sum of squares where the signs do not bracket it); that
/// converges to round-off. When the best grid point is an end of the range, D is reported as 0
/// (no dispersion seen) or +inf (saturated from the first sample) and valid is false. With fewer
/// than 2 samples at t > 0 (one parameter and a residual), D is NaN and valid is false.
/// Throws std::invalid_argument if times and msd differ in length or saturation_msd is not
/// finite and positive (an unbounded direction has no saturation: use fit_dispersion).
Dispersion fit_confined_dispersion(const std::vector<double>& times, const std::vector<double>& msd,
                                   double saturation_msd);

}  // namespace carom
