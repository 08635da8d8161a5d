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
    // Window statistics over counted pixels only: blur(m·f) / blur(m), m = mask (0/1), so pixels
    // outside the mask influence nothing, not even the windows of their counted neighbours.
    std::vector<double> m(a.size()), ma(a.size()), mb(a.size()), maa(a.size()), mbb(a.size()), mab(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        m[i] = mask.counts[i] ? 1.0 : 0.0;
        ma[i] = m[i] * a[i];
        mb[i] = m[i] * b[i];
        maa[i] = m[i] * a[i] * a[i];
        mbb[i] = m[i] * b[i] * b[i];
        mab[i] = m[i] * a[i] * b[i];
    }
    const auto weight = blur(m, w, h);
    const auto sA = blur(ma, w, h), sB = blur(mb, w, h);
    const auto sAA = blur(maa, w, h), sBB = blur(mbb, w, h), sAB = blur(mab, w, h);
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!mask.counts[i]) continue;
        const double muA = sA[i] / weight[i], muB = sB[i] / weight[i];
        const double varA = sAA[i] / weight[i] - muA * muA;
        const double varB = sBB[i] / weight[i] - muB * muB;
        const double cov = sAB[i] / weight[i] - muA * muB;
        sum += (2.0 * muA * muB + kC1) * (2.0 * cov + kC2) / ((muA * muA + muB * muB + kC1) * (varA + varB + kC2));
    }
    return sum / double(mask.countedPixels);
}

}  // namespace vct::metrics
