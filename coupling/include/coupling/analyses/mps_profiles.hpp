#pragma once
// Profiles of a two-phase flow in a tank (analyses.mps.profiles; docs/scene-format.md): at requested times, the
// free surface (the top of all moving material) and the bed (the top of the granular material) along the tank, in
// bins 2 dx wide; and, for a dam break, the figures that can be checked against shallow-water theory (the front
// against Ritter's, the head of the negative wave against the Ritter fan's, the scour at the dam). SI units.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "coupling/scene/tank_scene.hpp"
#include "sph/engine/run_loop.hpp"

namespace coupling {

struct Profile {
  double time = 0;  // [s] the time of the step it was taken at (the first at or after the requested time)
  std::vector<double> x;  // bin centres [m]
  // The top of the moving material and of the granular material in each bin: the highest particle centre whose
  // next one below (in the same bin) lies within 1.5 dx, plus dx/2 (grains or drops thrown clear do not count);
  // the tank floor where there is none [m].
  std::vector<double> surface, bed;
};

// The profile of the moving particles (kind 0) in bins 2 dx wide from the tank's x_min; `granular[m]` says whether
// material m is granular (the bed).
Profile measure_profile(const sph::ParticleSet& p, const Tank& tank, double dx,
                        const std::vector<std::uint8_t>& granular, double time);

// Takes a profile at the first step at or after each of `times` [s] (ascending).
class ProfileObserver : public sph::Observer {
 public:
  ProfileObserver(std::vector<double> times, const Tank& tank, double dx, std::vector<std::uint8_t> granular);
  std::string after_step(const sph::ParticleSet& p, const sph::RunState& state, const sph::Energies&) override;
  const std::vector<Profile>& profiles() const { return profiles_; }
  // On --resume: the profiles of an earlier profiles.csv taken up to `time` [s] are kept, and the requested times
  // up to `time` are not taken again. A file with other columns, or none, keeps nothing.
  void restore(const std::string& csv, double time);

 private:
  std::vector<double> times_;
  std::size_t next_ = 0;
  const Tank& tank_;
  double dx_;
  std::vector<std::uint8_t> granular_;
  std::vector<Profile> profiles_;
};

// A dam break from a reservoir ending at dam_x [m]: the figures of one profile against the one at t = 0 and the
// reservoir's level ahead of the negative wave. NaN where a figure cannot be taken.
struct DamBreakFigures {
  double time = 0;  // [s]
  double depth = 0;  // h0: the water depth above the bed just upstream of the dam at t = 0 [m]
  // the farthest x downstream of the dam where the surface stands at least dx/2 above its level at t = 0, and
  // Ritter's clear-water front dam_x + 2 sqrt(g h0) t (an upper bound on a fixed or erodible bed) [m]
  double front_x = 0, ritter_front_x = 0;
  // The negative wave: the reservoir's level ahead of it (the mean surface over the bins from 2 dx off the back wall
  // to dam_x - 1.2 sqrt(g h0) t, where the wave has not arrived; NaN once it has reached them all), the water depth
  // h there, the farthest x upstream of the dam where the surface (the mean over 5 bins, against the slosh of the
  // release) lies a quarter of h below that level, and where
  // the Ritter fan lowers it by as much: dam_x + (2 c - 3 sqrt(g (h - h/4))) t, c = sqrt(g h) (the fan's head moves
  // upstream at c) [m]
  double level_ahead = 0, depth_ahead = 0, negative_wave_x = 0, ritter_negative_wave_x = 0;
  // the bed at the dam (the mean of the bins within 2 dx of dam_x) and at t = 0 [m]; their difference is the scour
  double bed_at_dam = 0, bed_at_dam_start = 0;
};
DamBreakFigures dam_break_figures(const Profile& start, const Profile& now, double dam_x, double dx, double g);


}  // namespace coupling
