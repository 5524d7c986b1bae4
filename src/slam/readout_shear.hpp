#pragma once
// Issue 18: the rolling-shutter readout estimated by bundle adjustment, with the map.
//
// Tracking re-times each keypoint to its image's middle row with the readout in use (slam/
// rolling_shutter). With a wrong readout every keyframe is sheared along its own motion, and so
// are the points it creates; a frame tracked against that map sees much of the shear cancel, which
// is why the tracking residuals alone read a readout pulled towards the one in use
// (slam/readout_estimate.hpp: 3 ms in the simulated head turns for a true 25 ms, re-timing with 0).
// Bundle adjustment frees the points and the window's poses: with the readout as one more unknown,
// a keypoint re-timed with R0 is predicted at its projection plus (R - R0) times its row's time
// offset times the point's image motion under its keyframe's own motion, and only the joint fit
// over keyframes that moved differently separates the shear from the map (still attenuated away
// from the truth, far less: a scratch print in docs/dynamics.md, "Session 31"). Each local
// adjustment's estimate, when its standard error is small enough, becomes the readout tracking
// and the next adjustment use, so the map converges with it. The readout is a parameter of every
// residual there, so the solve is slower than without (local BA 1.5 times the time in the head
// turns); a step computed after an adjustment with the readout held fixed was measured instead and
// converged slower and worse: the robust pass at a wrong readout drops the rows the shear moves
// most, the very evidence (docs/dynamics.md, "Session 31").
#include <cstdint>
#include <vector>

#include "slam/bundle_adjuster.hpp"
#include "slam/keyframe.hpp"
#include "slam/map.hpp"

namespace dynanav {

/// One estimate adopted by the online readout: re-timing's readout from `frame` on.
struct ReadoutStage {
  int64_t frame = 0;
  double readout_s = 0.0, sigma_s = 0.0;
  int window_keyframes = 0;  ///< keyframes of the bundle adjustment that estimated it
};

/// Makes `problem` estimate the readout from `readout_s` on (one parameter shared by every
/// observation, BaProblem::estimate_readout). `keyframes` is parallel to problem.keyframes: each
/// observation's shear per second of readout error comes from its keyframe's motion
/// (KeyFrame::motion; none while that is not known) and the readout its keypoints were re-timed
/// with (KeyFrame::readout_used_s).
void addReadoutShear(BaProblem& problem, const std::vector<const KeyFrame*>& keyframes,
                     double readout_s);

/// Standard error (s) of an adjusted problem's readout under the pixel noise model the adjustment
/// weighs with (1 px at level 0), the free poses and every point marginalised (Schur complement
/// over the points, then over the poses), from the observations `outlier` does not flag; infinite
/// when the window's motion leaves the readout undetermined (a still camera).
double readoutSigmaS(const BaProblem& problem, const std::vector<uint8_t>& outlier);

/// Adopts an adjustment's estimate (`problem.readout_s`, standard error `sigma_s`) into
/// `map.readout` when its standard error is below MapReadout::adopt_sigma_s; true when adopted.
/// Call with the map locked.
bool adoptReadout(Map& map, const BaProblem& problem, double sigma_s);

}  // namespace dynanav
