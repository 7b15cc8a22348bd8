// Checks that an image's mean (first channel) matches the mean p of a
// Bernoulli estimator, within 6 standard deviations of the mean of
// `trials per pixel` x pixels independent 0/1 trials: sigma^2 = p(1-p)/n.
// Also checks every pixel is within [0, 1], as a fraction must be.
//   check_bernoulli_mean IMAGE EXPECTED_MEAN TRIALS_PER_PIXEL
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <femto/image/image_io.h>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s IMAGE EXPECTED_MEAN TRIALS_PER_PIXEL\n", argv[0]);
    return 2;
  }
  try {
    femto::Bitmap image = femto::readImage(argv[1]);
    const double p = std::atof(argv[2]);
    const double trials = double(image.width) * image.height * std::atof(argv[3]);
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        float v = image.pixel(x, y)[0];
        if (!(v >= -1e-6f && v <= 1.0f + 1e-6f)) {
          std::fprintf(stderr, "pixel (%d, %d) = %g is not a fraction in [0, 1]\n", x, y, v);
          return 1;
        }
        sum += v;
      }
    const double mean = sum / (double(image.width) * image.height);
    const double sigma = std::sqrt(p * (1.0 - p) / trials);
    std::printf("mean %.5f, expected %.5f, sigma %.5f (%.0f trials)\n", mean, p, sigma, trials);
    if (std::abs(mean - p) > 6.0 * sigma) {
      std::fprintf(stderr, "mean is %.1f sigma from the closed form\n", std::abs(mean - p) / sigma);
      return 1;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
