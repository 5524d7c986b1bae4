#include "dynamics/object_tracker.hpp"

// Moving or standing: what holds a track still and what releases it, after the frame's update
// (object_tracker.cpp).
namespace dynanav {

void ObjectTracker::judgeStill(Track& track, const Instance* instance,
                               const std::optional<Vec3>& v_walk, bool verified_static,
                               const ObjectTrackerInput& input) {
  // Moving or not: the dynamics verdicts of the instance (a carried object keeps its state).
  if (instance) {
    const bool moving = input.dynamics.foundMoving(instance->id);
    track.still = moving ? 0 : track.still + 1;
  } else if (!track.prior_dynamic) {
    // Missed by the segmenter and carried by its flow points: no evidence that it moves, which
    // an object that does not move by itself needs (Bonn's chairs, missed every few frames,
    // were carried as moving on flow dragged by the walkers passing in front).
    ++track.still;
  }
  // Not found moving for a while and measured slow, or not found moving for three times as
  // long: static (a verdict that flickers off for a few frames of a walker does not stop it;
  // a chair's noisy speed does not keep it moving).
  // Slow: the filtered speed, or this frame's rigid motion of the points — after a stop the
  // points stop at once while the filtered velocity would decay over the filter's memory.
  // A new track's filtered velocity is its prior (0 +- 1 m/s): that says nothing of slowness (a
  // walker far down a hall, not yet flagged moving, was held still for its first frames).
  const bool slow = filterKnownSlow(track) || (v_walk && isSlow(*v_walk));
  // Not found moving is not found still: the dynamics stage gives no verdict on an object it
  // cannot judge (a person walking in at the image's side was made static after 9 frames while
  // its points measured 0.5-0.7 m/s, and then held still). So "three times as long" needs the
  // track's own velocity measured, and not clearly above the static speed (by one sigma).
  const bool fast =
      filterVelocityKnown(track) &&
      track.filter.velocity().norm() - track.filter.velocitySigma() > config_.static_speed_mps;
  const bool long_unmoved =
      track.still >= 3 * config_.static_after_frames && filterVelocityKnown(track) && !fast;
  // A person held still has the filtered velocity held at zero, so only the points can show them
  // setting off: as many frames in a row of clearly moving points as it took to be held still.
  // Only prior-dynamic classes (people, animals) set off by themselves: a chair's or a box's rigid
  // motion is mostly its mask's jitter (for every class, Bonn crowd's chairs were reported moving
  // in more frames), and one that is pushed is found moving by the dynamics stage.
  // A frame whose points give no motion (no depth, too few inliers) says nothing either way: the
  // count waits for the next one.
  if (v_walk) track.points_moving = isSlow(*v_walk) ? 0 : track.points_moving + 1;
  const bool sets_off = track.prior_dynamic && track.points_moving >= config_.static_after_frames;
  // An object that does not move by itself is static once the dynamics stage has not found it
  // moving for a while, unless its own velocity is clearly fast: its points' jitter says little
  // (Bonn crowd's chairs: most of their frames reported moving came from that jitter and from a
  // new track's unknown velocity). Missed by the segmenter, its velocity comes from points
  // carried by a flow that a walker in front drags along: no evidence either (Bonn: 38 of the
  // 121 chair frames still reported moving, docs/tracking.md "Session 13").
  const bool unmoved_object = !track.prior_dynamic && (!fast || !instance);
  // The dynamics stage's "verified static" is the scene flow of the points sampled in the mask a
  // few frames back; a mask grown over a static occluder or the background reads their flow
  // (simulated office, masks grown 5 px: a walker coming into view, partly hidden, was held
  // still in 3 of 5 frames while its points read 0.8-1.0 m/s). It does not hold a person whose own
  // points have clearly moved for as many frames in a row as it takes to set off and, this frame,
  // go on nearer the track's speed than a standstill. A person who stops is still held at once:
  // the frame of the stop already reads slower than half the walk (office, grown masks: 0.32
  // against 0.69 m/s). Speeds, not velocities: in a turn the filtered velocity lags the walker's
  // heading, and a walker turning at 1.2 m/s whose points read 0.78 m/s some 50 degrees off the
  // filter's 1.08 m/s was held still for a frame (simulated office seed 3, frame 138).
  const bool goes_on = v_walk && v_walk->norm() > 0.5 * track.filter.velocity().norm();
  const bool held_by_verdict = verified_static && !(sets_off && goes_on);
  // A person who stops: the points' rigid motion reads it in the next frame, while the dynamics
  // stage's verdict (the scene flow over a gap of frames) still says moving for as many frames
  // as the gap holds, and the filtered velocity decays over its memory (simulated office, a
  // walker stopping from 0.7 m/s: the points read 0.16 and 0.03 m/s in the two frames after the
  // stop, the filter 0.64 and 0.57, held still only in the third). Two slow frames in a row, not
  // one: a walker's one-frame motion reads slow now and then (6 single frames in the clean runs
  // of the tracking table's eight sequences, none two in a row; and no walker slows from 0.7 to
  // 0.16 m/s within a frame, 16 m/s^2: one slow frame held Bonn walkers still, docs/tracking.md
  // "Session 36"). And only where the points read the walker's speed before they read it stop:
  // points whose flow under-reads the object (smooth clothes, a part the flow drags with the
  // background) read slow all along while its centre moves.
  // And only from a walk clearly faster than "slow" (twice static_speed_mps): a dawdler's points
  // read slow now and then without a stop (Bonn crowd: a walker filtered at 0.33 m/s, its centre
  // moving on at that pace, was held still for 8 frames). Once held, slow points keep it held.
  // And a stop is read only on a mask the segmenter found: points carried on without one may have
  // slid onto the background, which reads slow (Bonn crowd: a walker leaving the view, missed, was
  // held still on 16 carried points, and its velocity stayed unknown for the rest of its track).
  // They do keep one already held.
  const bool points_slow = v_walk && isSlow(*v_walk);
  const double filtered_mps = track.filter.velocity().norm();
  const bool stops = track.prior_dynamic && config_.stop_after_slow_frames > 0 && points_slow &&
                     (instance != nullptr || track.stationary) &&
                     track.points_slow + 1 >= config_.stop_after_slow_frames &&
                     track.points_agree >= config_.static_after_frames &&
                     (track.stationary || filtered_mps >= 2.0 * config_.static_speed_mps);
  track.points_slow = points_slow ? track.points_slow + 1 : 0;
  if (!points_slow) {
    const bool agrees = v_walk && !track.stationary && v_walk->norm() < 1.5 * filtered_mps &&
                        filtered_mps < 1.5 * v_walk->norm();
    // Counted up and down (to twice the frames it takes): one odd frame does not undo it (the
    // frame of a stop itself read 1.25 m/s for a walker at 0.70 in simulated office seed 3).
    track.points_agree = agrees ? std::min(track.points_agree + 1, 2 * config_.static_after_frames)
                                : std::max(track.points_agree - 1, 0);
  }
  const bool was_held = track.stationary;
  track.stationary = held_by_verdict || stops ||
                     (!sets_off && track.still >= config_.static_after_frames &&
                      (slow || long_unmoved || unmoved_object));
  // A person released from being held still: the held state was an assumption, not a
  // measurement. Its velocity (clamped at zero with a tight covariance) would otherwise ramp up
  // over the filter's memory, and its centre (predicted at a standstill while the points were
  // already moving, for as many frames as it took to release it) lags behind: both are reopened,
  // the velocity to a new track's prior and the centre by a body's size, so the next frames
  // measure them afresh instead of reading the lag as speed. (Bonn crowd: moving person-frames
  // in the speed band 968 -> 988 of 1,050; docs/tracking.md "Session 14".) A rigid object found
  // moving has its velocity reopened before the update, above.
  if (was_held && !track.stationary && track.prior_dynamic)
    track.filter.reopen(kUnmeasuredSigmaM, kInitialVelocitySigmaMps);
  if (track.stationary) {
    track.filter.holdStill();
    // When it sets off again its velocity starts afresh: the rigid motion measures it first.
    track.whole_centre_frames = 0;
  }
}

}  // namespace dynanav
