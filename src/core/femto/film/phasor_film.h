#pragma once
// mitransient's phasor film (phasor_hdr_film): each pixel's time profile as
// Fourier coefficients at a few frequencies, accumulated per sample without
// storing a time axis (phasor-field NLOS, continuous-wave ToF). A sample's
// contribution v arriving at OPL tau adds v exp(-2 pi i f (tau - start_opl))
// for each frequency f (mitransient's sign); OPL counts from each camera
// ray's near-clip point, as mitransient's films do. The frequencies are
// mitransient's: np.fft.fftfreq(temporal_bins, bin_width_opl) between the
// indices nt bw / wl_mean -+ 3 nt bw / (6 wl_sigma) (clamped to [0, nt/2]).
// Outputs: <stem>.exr (the steady image, the f = 0 term), <stem>.npy float32
// (height, width, frequencies, 2 = real and imaginary, 3 = RGB) and
// <stem>.json (the frequencies, wavelengths and the convention).
#include <filesystem>
#include <vector>

#include <femto/render/film.h>
#include <femto/render/integrator.h>

namespace femto {

class Scene;
class TransientIntegrator;

class PhasorFilm final : public Film {
 public:
  explicit PhasorFilm(const Properties& props);
  bool timeResolved() const override { return true; }
  std::string defaultExtension() const override { return ".npy"; }
  void develop(const ImageBlock& image, const std::filesystem::path& path) const override;
  std::string toString() const override;

  const std::vector<double>& frequencies() const { return frequencies_; }
  double startOpl() const { return startOpl_; }
  /// Channels per sample: steady RGB, then (re, im) x RGB per frequency.
  int channels() const { return 3 + 6 * int(frequencies_.size()); }

 private:
  double wlMean_, wlSigma_, binWidth_, startOpl_;
  int bins_;
  std::vector<double> frequencies_;
};

/// mitransient's frequency selection (see the header), in cycles per OPL unit.
std::vector<double> phasorFrequencies(int bins, double binWidth, double wlMean, double wlSigma);

/// Render into a phasor film: `passes` passes of `passIntegrator(pass,
/// Infinity)` (every arrival counts), averaged; output as the header says.
RenderStats renderPhasor(const Scene& scene, const PhasorFilm& film, const RenderOptions& options, int passes,
                         const std::function<std::shared_ptr<const TransientIntegrator>(int, double)>& passIntegrator);

}  // namespace femto
