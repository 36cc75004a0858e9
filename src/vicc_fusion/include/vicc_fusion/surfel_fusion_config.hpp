#pragma once
// Parameters of the surfel model update. Defaults are tuned for the pico flexx (224x171,
// wide field of view): large points, more noise and fewer observations per point than the
// Kinect-class cameras Keller et al. designed for (thesis 5.3).

namespace vicc_fusion {

struct SurfelFusionConfig {
  int supersampling = 4;               ///< index map resolution factor (Keller: 4x4)
  double max_depth_difference = 0.01;  ///< m along the view ray for a correspondence
  double max_normal_angle_deg = 20.0;  ///< between measured and model normal
  double max_radius_growth = 0.5;      ///< a measurement with radius > (1+x)*r only confirms
  double confidence_sigma = 0.8;       ///< Gaussian weight over the normalised radial distance
                                       ///< (Keller: 0.6; wider for the wide-FOV pico flexx)
  double stable_confidence =
      3.0;  ///< counter threshold for "stable" (Keller: 10 at 30 Hz; tuned on hen/office)
  int unstable_lifetime = 15;       ///< frames an unstable surfel may go unconfirmed
  double free_space_margin = 0.03;  ///< m; a surfel this far in front of a measurement is
                                    ///< in space the camera sees through
  double max_view_distance = 4.0;   ///< m; no fusion beyond (pico flexx range)
  int max_surfels = 1000000;        ///< memory bound: ~48 MB at 48 bytes per surfel
  /// Frames between re-sorts of the model into the camera's pixel order (0 = never). Speed
  /// only: the per-frame passes then read the model sequentially instead of at random.
  int sort_interval = 4;
  void validate() const;            ///< throws std::invalid_argument naming the field
};

}  // namespace vicc_fusion
