#include <femto/film/phasor_film.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <femto/base/error.h>
#include <femto/core/log.h>
#include <femto/film/npy_volume.h>
#include <femto/film/transient_render.h>
#include <femto/image/write_atomically.inl>
#include <femto/loop/render_loop.h>
#include <femto/math/constants.h>
#include <femto/render/emitter.h>
#include <femto/render/image_block.h>
#include <femto/render/medium.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/render/transient_integrator.h>

namespace femto {
namespace {

/// One camera sample's phasors: the recorder transient integrators report to.
class PhasorRecorder final : public RadianceRecorder {
 public:
  PhasorRecorder(const std::vector<double>& frequencies, double start) : frequencies_(frequencies), start_(start) {}
  void reset(double origin) {
    origin_ = origin;
    std::fill(sums_.begin(), sums_.end(), 0.0);
  }
  void add(double opl, const Color3f& value) override { addInterval(opl, opl, value); }
  void addInterval(double opl0, double opl1, const Color3f& value) override {
    const double rgb[3] = {value.r, value.g, value.b};
    for (int c = 0; c < 3; ++c) sums_[c] += rgb[c];
    const double t0 = opl0 - origin_ - start_, t1 = opl1 - origin_ - start_;
    for (size_t k = 0; k < frequencies_.size(); ++k) {
      // v exp(-2 pi i f t), averaged over [t0, t1] for an interval:
      // exp(-i pi f (t0 + t1)) sinc(pi f (t1 - t0)).
      const double f = frequencies_[k];
      const double phase = -Pi * f * (t0 + t1), x = Pi * f * (t1 - t0);
      const double sinc = std::abs(x) < 1e-8 ? 1.0 : std::sin(x) / x;
      const double re = std::cos(phase) * sinc, im = std::sin(phase) * sinc;
      for (int c = 0; c < 3; ++c) {
        sums_[3 + k * 6 + c] += rgb[c] * re;
        sums_[3 + k * 6 + 3 + c] += rgb[c] * im;
      }
    }
  }
  void addPulsed(double opl0, double opl1, const Color3f& value, const EmissionPulse& pulse) override {
    // Non-Dirac pulses were refused before rendering (renderPhasor).
    addInterval(opl0 + pulse.offset(), opl1 + pulse.offset(), value);
  }
  double horizon() const override { return Infinity; }
  const TimeGrid& timeGrid() const override { return steady_; }
  /// The sample's values (weighted by the sensor's importance) into `out`.
  void write(const Color3f& weight, float* out) const {
    const float w[3] = {weight.r, weight.g, weight.b};
    for (size_t i = 0; i < sums_.size(); ++i) out[i] = float(sums_[i] * w[i < 3 ? i : (i - 3) % 3]);
  }
  void resize() { sums_.assign(3 + 6 * frequencies_.size(), 0.0); }

 private:
  const std::vector<double>& frequencies_;
  double start_, origin_ = 0.0;
  std::vector<double> sums_;
  TimeGrid steady_;  // no time axis: integrators gate nothing and trace to the end
};

std::string number(double x) {
  std::ostringstream out;
  out << std::setprecision(17) << x;
  return out.str();
}

}  // namespace

std::vector<double> phasorFrequencies(int bins, double binWidth, double wlMean, double wlSigma) {
  const double span = double(bins) * binWidth;
  const double meanIndex = span / wlMean, sigmaIndex = span / (wlSigma * 6.0);
  const long first = std::max(0L, long(std::floor(meanIndex - 3.0 * sigmaIndex)));
  const long last = std::min(long(bins / 2), long(std::ceil(meanIndex + 3.0 * sigmaIndex)));
  std::vector<double> f;
  for (long k = first; k <= last; ++k) {
    // numpy's fftfreq: index k is k / (n d) up to (n - 1) / 2, then (k - n) / (n d).
    const long signedIndex = k <= (bins - 1) / 2 ? k : k - bins;
    f.push_back(double(float(double(signedIndex) / span)));  // mitransient keeps them as float32
  }
  return f;
}

PhasorFilm::PhasorFilm(const Properties& props) : Film(props, "gaussian") {
  wlMean_ = props.getFloat("wl_mean", 100.0f, Range::positive());
  wlSigma_ = props.getFloat("wl_sigma", 1000.0f, Range::positive());
  bins_ = props.getInt("temporal_bins", 4096, 2, 1 << 28);
  binWidth_ = props.getFloat("bin_width_opl", 0.003f, Range::positive());
  startOpl_ = props.getFloat("start_opl", 0.0f);
  frequencies_ = phasorFrequencies(bins_, binWidth_, wlMean_, wlSigma_);
  if (frequencies_.empty())
    props.raise("wl_mean", "selects no frequency: wl_mean must be within the range temporal_bins x bin_width_opl resolves");
  props.getBool("sample_border", false);
}

void PhasorFilm::develop(const ImageBlock&, const std::filesystem::path&) const {
  throw Error("the phasor film is developed by a transient integrator's render (renderPhasor)");
}

std::string PhasorFilm::toString() const {
  std::string f;
  for (double x : frequencies_) f += (f.empty() ? "" : ", ") + number(x);
  return str("PhasorFilm[size=", size().x, "x", size().y, ", frequencies=[", f, "], start_opl=", startOpl_, "]");
}

RenderStats renderPhasor(const Scene& scene, const PhasorFilm& film, const RenderOptions& options, int passes,
                         const std::function<std::shared_ptr<const TransientIntegrator>(int, double)>& passIntegrator) {
  for (const auto& emitter : scene.emitters())
    if (!emitter->pulse().isDelta())
      throw Error(str(emitter->toString(), " emits a ", emitter->pulse().type() == EmissionPulse::Type::Gaussian ? "gaussian" : "continuous",
                      " pulse: the phasor film takes Dirac pulses (a pulse's phasor is the film's times the pulse's "
                      "Fourier transform; multiply by it after rendering)"));
  if (options.timeLimit > 0.0) throw Error("the phasor film renders a fixed number of passes: give --passes, not --time-limit");
  const int channels = film.channels();
  const Sensor& sensor = scene.sensor();
  const Medium* cameraMedium = sensor.medium();
  const Point2i crop = film.cropSize();
  std::vector<double> mean(size_t(crop.x) * size_t(crop.y) * size_t(channels), 0.0);
  RenderStats total;
  const int passCount = std::max(1, options.passes > 0 ? options.passes : passes);
  for (int pass = 0; pass < passCount; ++pass) {
    std::shared_ptr<const TransientIntegrator> integrator = passIntegrator(pass, Infinity);
    const bool counts = integrator->countsCameraSegment();
    auto sampleFn = [&](const Point2f& filmPos, Sampler& sampler, float* out) {
      PhasorRecorder local(film.frequencies(), film.startOpl());
      local.resize();
      Ray ray;
      Color3f weight = sensor.sampleRay(filmPos, sampler.next2D(), ray);
      // mitransient's origin: the ray's near-clip point (transient_tile.cpp's nearClipOrigin).
      local.reset(counts ? double(ray.tmin) * (cameraMedium ? double(cameraMedium->eta()) : 1.0) : 0.0);
      if (!weight.isBlack()) integrator->sample(scene, ray, sampler, local);
      local.write(weight, out);
    };
    ImageBlock block(film.cropOffset(), crop, film.filter(), channels);
    RenderOptions passOptions = options;
    passOptions.seed = passSeed(options.seed, pass);
    passOptions.passes = 0;
    passOptions.output.clear();
    accumulatePassStats(total, renderChannelTiles(scene, passOptions, sampleFn, block));
    if (!total.completed) break;
    ++total.passes;
    std::vector<float> v(static_cast<size_t>(channels), 0.0f);
    for (int y = 0; y < crop.y; ++y)
      for (int x = 0; x < crop.x; ++x) {
        block.values(Point2i(x, y), v.data());
        double* m = &mean[(size_t(y) * size_t(crop.x) + size_t(x)) * size_t(channels)];
        for (int c = 0; c < channels; ++c) m[c] += (double(v[c]) - m[c]) / double(pass + 1);
      }
  }
  if (options.output.empty()) return total;
  namespace fs = std::filesystem;
  fs::path base = options.output;
  base.replace_extension();
  const size_t frequencies = film.frequencies().size();
  // The steady image (the f = 0 term of every frequency set).
  Bitmap steady(crop.x, crop.y, 3);
  for (int y = 0; y < crop.y; ++y)
    for (int x = 0; x < crop.x; ++x)
      for (int c = 0; c < 3; ++c)
        steady.pixel(x, y)[c] = float(mean[(size_t(y) * size_t(crop.x) + size_t(x)) * size_t(channels) + size_t(c)]);
  Film::writeExrWithPreview(fs::path(base.string() + ".exr"), steady);
  // (height, width, frequency, re/im, rgb) float32.
  writeAtomically(fs::path(base.string() + ".npy"), [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    const std::vector<char> header = npyHeader({crop.y, crop.x, int64_t(frequencies), 2, 3});
    out.write(header.data(), std::streamsize(header.size()));
    std::vector<float> row;
    for (size_t p = 0; p < size_t(crop.x) * size_t(crop.y); ++p)
      for (size_t i = 3; i < size_t(channels); ++i) {
        const float v = float(mean[p * size_t(channels) + i]);
        out.write(reinterpret_cast<const char*>(&v), sizeof v);
      }
    if (!out) throw Error(str("cannot write \"", tmp.string(), "\""));
  });
  // An NLOS capture's geometry, as a transient film's sidecar holds it.
  const auto nlos = describeNlosCapture(scene, film, fs::path(base.string() + ".npy"));
  writeAtomically(fs::path(base.string() + ".json"), [&](const fs::path& tmp) {
    std::ofstream out(tmp);
    out << "{\n  \"film\": \"phasor_hdr_film\",\n  \"layout\": \"height, width, frequency, (real, imaginary), rgb\",\n"
        << "  \"convention\": \"sum over contributions of value * exp(-2 pi i f (opl - start_opl)), opl from each camera "
           "ray's near-clip point; averaged per pixel as the steady image\",\n"
        << "  \"start_opl\": " << number(film.startOpl()) << ",\n  \"width\": " << crop.x << ",\n  \"height\": " << crop.y
        << ",\n  \"frequencies\": [";
    for (size_t k = 0; k < frequencies; ++k) out << (k ? ", " : "") << number(film.frequencies()[k]);
    out << "],\n  \"wavelengths\": [";
    for (size_t k = 0; k < frequencies; ++k) {
      const double f = film.frequencies()[k];
      out << (k ? ", " : "") << (f != 0.0 ? number(1.0 / f) : std::string("null"));
    }
    out << "],\n  \"passes\": " << total.passes << ",\n  \"seed\": " << options.seed;
    for (const auto& [key, value] : nlos) out << ",\n  \"" << key << "\": " << value;
    out << "\n}\n";
    if (!out) throw Error(str("cannot write \"", tmp.string(), "\""));
  });
  logInfo("phasor film: ", frequencies, " frequencies written to ", base.string(), ".npy");
  return total;
}

}  // namespace femto
