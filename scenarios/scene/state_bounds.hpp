#pragma once
/// Bounds on states no scene can mean, applied to initial states (`carom check`, `carom run`)
/// and to checkpoints (`carom resume`).

namespace carom {

/// Largest particle speed carom accepts, m/s, and largest surface speed of a spin (|spin| r).
/// No granular flow comes near it (the speed of sound in steel is 6e3 m/s): a larger speed is a
/// typo or damage, and would make the run crawl (its time step or collision times shrink with
/// 1 / speed) without a result.
inline constexpr double kMaxSpeed = 1e6;

}  // namespace carom
