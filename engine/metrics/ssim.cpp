#include "metrics/ssim.hpp"

#include <cmath>
#include <limits>

namespace vct::metrics {
namespace {

constexpr int kRadius = 5;  // 11×11 window
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;
constexpr double kC2 = 0.03 * 0.03;

// Separable Gaussian blur with the window clipped at the borders and renormalized: the 2D
// weights are products of 1D weights, so dividing each 1D pass by its own weight sum equals
// renormalizing the clipped 2D window.
std::vector<double> blur(const std::vector<double>& in, int width, int height) {
    double w[2 * kRadius + 1];
    for (int i = -kRadius; i <= kRadius; ++i) w[i + kRadius] = std::exp(-0.5 * i * i / (kSigma * kSigma));
    std::vector<double> tmp(in.size()), out(in.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0.0, weight = 0.0;
            for (int i = std::max(-kRadius, -x); i <= std::min(kRadius, width - 1 - x); ++i) {
                sum += w[i + kRadius] * in[std::size_t(y) * width + x + i];
                weight += w[i + kRadius];
            }
            tmp[std::size_t(y) * width + x] = sum / weight;
        }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0.0, weight = 0.0;
            for (int i = std::max(-kRadius, -y); i <= std::min(kRadius, height - 1 - y); ++i) {
                sum += w[i + kRadius] * tmp[std::size_t(y + i) * width + x];
                weight += w[i + kRadius];
            }
            out[std::size_t(y) * width + x] = sum / weight;
        }
    return out;
}

}  // namespace

std::vector<double> displayLuma(const ImageF& image, double exposureEV, TonemapCurve curve) {
    std::vector<double> luma(std::size_t(image.width) * image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.at(x, y);
            const glm::vec3 d = displayTransform({p[0], p[1], p[2]}, exposureEV, curve);
            luma[std::size_t(y) * image.width + x] = 0.2126 * d.x + 0.7152 * d.y + 0.0722 * d.z;
        }
    return luma;
}

double psnr(const std::vector<double>& a, const std::vector<double>& b, const PixelMask& mask) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (mask.counts[i]) sum += (a[i] - b[i]) * (a[i] - b[i]);
    const double mse = sum / double(mask.countedPixels);
    if (mse == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(1.0 / mse);
}

double ssim(const std::vector<double>& a, const std::vector<double>& b, const PixelMask& mask) {
    const int w = mask.width, h = mask.height;
    std::vector<double> aa(a.size()), bb(a.size()), ab(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const auto muA = blur(a, w, h), muB = blur(b, w, h);
    const auto eAA = blur(aa, w, h), eBB = blur(bb, w, h), eAB = blur(ab, w, h);
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!mask.counts[i]) continue;
        const double varA = eAA[i] - muA[i] * muA[i];
        const double varB = eBB[i] - muB[i] * muB[i];
        const double cov = eAB[i] - muA[i] * muB[i];
        sum += (2.0 * muA[i] * muB[i] + kC1) * (2.0 * cov + kC2) /
               ((muA[i] * muA[i] + muB[i] * muB[i] + kC1) * (varA + varB + kC2));
    }
    return sum / double(mask.countedPixels);
}

}  // namespace vct::metrics
