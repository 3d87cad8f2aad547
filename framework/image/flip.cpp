#include <shadelgraph/image/flip.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace sg::image {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// ---- Colour transforms (D65; the matrices are the reference's) ------------------------------------------

struct Color {
  float x, y, z;
};

constexpr Color kIlluminant{0.950428545f, 1.0f, 1.088900371f};
constexpr Color kInvIlluminant{1.052156925f, 1.0f, 0.918357670f};

Color linearRgbToXyz(Color c) {
  return {(10135552.0f / 24577794.0f) * c.x + (8788810.0f / 24577794.0f) * c.y + (4435075.0f / 24577794.0f) * c.z,
          (2613072.0f / 12288897.0f) * c.x + (8788810.0f / 12288897.0f) * c.y + (887015.0f / 12288897.0f) * c.z,
          (1425312.0f / 73733382.0f) * c.x + (8788810.0f / 73733382.0f) * c.y + (70074185.0f / 73733382.0f) * c.z};
}

Color xyzToLinearRgb(Color c) {
  return {3.241003275f * c.x - 1.537398934f * c.y - 0.498615861f * c.z,
          -0.969224334f * c.x + 1.875930071f * c.y + 0.041554224f * c.z,
          0.055639423f * c.x - 0.204011202f * c.y + 1.057148933f * c.z};
}

// YCxCz: the linear (no cube root) opponent space the CSFs are applied in.
Color xyzToYcxcz(Color c) {
  const float x = c.x * kInvIlluminant.x, y = c.y * kInvIlluminant.y, z = c.z * kInvIlluminant.z;
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

Color ycxczToXyz(Color c) {
  const float y = (c.x + 16.0f) / 116.0f;
  return {(y + c.y / 500.0f) * kIlluminant.x, y * kIlluminant.y, (y - c.z / 200.0f) * kIlluminant.z};
}

Color xyzToLab(Color c) {
  constexpr float delta = 6.0f / 29.0f;
  constexpr float deltaCube = delta * delta * delta;
  constexpr float factor = 1.0f / (3.0f * delta * delta);
  auto f = [&](float v) { return v > deltaCube ? std::pow(v, 1.0f / 3.0f) : factor * v + 4.0f / 29.0f; };
  const float fx = f(c.x * kInvIlluminant.x), fy = f(c.y * kInvIlluminant.y), fz = f(c.z * kInvIlluminant.z);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// Hunt adjustment: chroma scaled by 0.01·L.
Color huntAdjustedLab(Color linearRgb) {
  const Color lab = xyzToLab(linearRgbToXyz(linearRgb));
  return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z};
}

float hyab(Color a, Color b) {
  const float da = a.y - b.y, db = a.z - b.z;
  return std::abs(a.x - b.x) + std::sqrt(da * da + db * db);
}

constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kQf = 0.5f, kFeatureWidth = 0.082f;

float colorDistanceMax() {
  static const float cmax =
      std::pow(hyab(huntAdjustedLab({0.0f, 1.0f, 0.0f}), huntAdjustedLab({0.0f, 0.0f, 1.0f})), kQc);
  return cmax;
}

// ΔE_c: HyAB^qc remapped to [0, 1] (see the header).
float remapColorError(float hyabDistance, float cmax) {
  const float e = std::pow(hyabDistance, kQc);
  const float knee = kPc * cmax;
  return e < knee ? (kPt / knee) * e : kPt + (e - knee) / (cmax - knee) * (1.0f - kPt);
}

const std::array<float, 256>& srgbDecodeTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (size_t i = 0; i < t.size(); ++i) {
      const double s = double(i) / 255.0;
      t[i] = float(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table;
}

// ---- Planar images and separable filtering ------------------------------------------------------------

struct Plane {
  uint32_t width = 0, height = 0;
  std::vector<float> v;
  Plane(uint32_t w, uint32_t h) : width(w), height(h), v(size_t(w) * h, 0.0f) {}
};

using Kernel = std::vector<float>;  // odd length, centred

// out[x] (=|+=) weight · Σ_j k[j]·rows[j][x], the taps summed in kernel order. Blocks of a fixed width keep
// the accumulators in registers and let the compiler vectorise them. With a centre row (for kernels that sum
// to zero) the sum is taken over rows[j][x] - centre[x] instead: the same in exact arithmetic, and exactly
// zero where the input is flat, where float rounding would otherwise leave a residue that ꟻLIP's square
// root on feature differences magnifies.
void weightedRowSum(const std::vector<const float*>& rows, const Kernel& k, const float* centre, float* out,
                    size_t w, float weight, bool accumulate) {
  constexpr size_t kBlock = 16;
  auto finish = [&](size_t x, float sum) { out[x] = accumulate ? out[x] + weight * sum : weight * sum; };
  size_t x = 0;
  if (centre) {
    for (; x + kBlock <= w; x += kBlock) {
      std::array<float, kBlock> acc{};
      for (size_t j = 0; j < k.size(); ++j) {
        const float kj = k[j];
        const float* in = rows[j] + x;
        for (size_t l = 0; l < kBlock; ++l) acc[l] += kj * (in[l] - centre[x + l]);
      }
      for (size_t l = 0; l < kBlock; ++l) finish(x + l, acc[l]);
    }
  } else {
    for (; x + kBlock <= w; x += kBlock) {
      std::array<float, kBlock> acc{};
      for (size_t j = 0; j < k.size(); ++j) {
        const float kj = k[j];
        const float* in = rows[j] + x;
        for (size_t l = 0; l < kBlock; ++l) acc[l] += kj * in[l];
      }
      for (size_t l = 0; l < kBlock; ++l) finish(x + l, acc[l]);
    }
  }
  for (; x < w; ++x) {
    float sum = 0.0f;
    for (size_t j = 0; j < k.size(); ++j) sum += k[j] * (centre ? rows[j][x] - centre[x] : rows[j][x]);
    finish(x, sum);
  }
}

struct FilterScratch {
  std::vector<float> pad;
  std::vector<const float*> rows;
};

// Correlates each row with k, clamping at the borders. zeroSum: k sums to zero (see weightedRowSum).
void filterRows(const Plane& src, Plane& dst, const Kernel& k, FilterScratch& scratch, bool zeroSum = false) {
  const size_t w = src.width, r = k.size() / 2;
  scratch.pad.resize(w + 2 * r);
  scratch.rows.resize(k.size());
  for (size_t j = 0; j < k.size(); ++j) scratch.rows[j] = scratch.pad.data() + j;
  for (size_t y = 0; y < src.height; ++y) {
    const float* in = &src.v[y * w];
    std::fill_n(scratch.pad.begin(), r, in[0]);
    std::copy_n(in, w, scratch.pad.begin() + ptrdiff_t(r));
    std::fill_n(scratch.pad.begin() + ptrdiff_t(r + w), r, in[w - 1]);
    weightedRowSum(scratch.rows, k, zeroSum ? in : nullptr, &dst.v[y * w], w, 1.0f, false);
  }
}

// Correlates each column with k, clamping at the borders; dst = k * src, or dst += weight · (k * src).
void filterColumns(const Plane& src, Plane& dst, const Kernel& k, FilterScratch& scratch, bool zeroSum = false,
                   bool accumulate = false, float weight = 1.0f) {
  const size_t w = src.width, h = src.height;
  const ptrdiff_t r = ptrdiff_t(k.size() / 2);
  scratch.rows.resize(k.size());
  for (size_t y = 0; y < h; ++y) {
    for (size_t j = 0; j < k.size(); ++j) {
      const ptrdiff_t sy = std::clamp(ptrdiff_t(y) + ptrdiff_t(j) - r, ptrdiff_t(0), ptrdiff_t(h) - 1);
      scratch.rows[j] = &src.v[size_t(sy) * w];
    }
    weightedRowSum(scratch.rows, k, zeroSum ? &src.v[y * w] : nullptr, &dst.v[y * w], w, weight, accumulate);
  }
}

// ---- Filters -------------------------------------------------------------------------------------------

// One channel's CSF as a weighted sum of separable, unit-sum Gaussians (terms with a = 0 dropped). The 2D
// kernel a1·sqrt(pi/b1)·g1(x)g1(y) + a2·sqrt(pi/b2)·g2(x)g2(y), normalised to unit sum, is exactly
// Σ_i w_i·(g_i/S_i)(x)·(g_i/S_i)(y) with S_i = Σ g_i and w_i = a_i·sqrt(pi/b_i)·S_i² / total.
struct Csf {
  std::vector<std::pair<float, Kernel>> terms;
};

struct CsfParameters {
  float a1, b1, a2, b2;
};
constexpr std::array<CsfParameters, 3> kCsf{{{1.0f, 0.0047f, 0.0f, 1e-5f},  // achromatic
                                              {1.0f, 0.0053f, 0.0f, 1e-5f},  // red-green
                                              {34.1f, 0.04f, 13.5f, 0.025f}}};  // blue-yellow

std::array<Csf, 3> makeCsfFilters(float ppd) {
  float maxB = 0.0f;
  for (const CsfParameters& p : kCsf) maxB = std::max({maxB, p.b1, p.b2});
  const int radius = int(std::ceil(3.0f * std::sqrt(maxB / (2.0f * kPi * kPi)) * ppd));
  const float dx = 1.0f / ppd;
  std::array<Csf, 3> filters;
  for (size_t c = 0; c < 3; ++c) {
    const CsfParameters& p = kCsf[c];
    const std::array<std::pair<float, float>, 2> gaussians{{{p.a1, p.b1}, {p.a2, p.b2}}};
    float total = 0.0f;
    for (const auto& [a, b] : gaussians) {
      if (a == 0.0f) continue;
      Kernel g(size_t(2 * radius + 1));
      float sum = 0.0f;
      for (int i = -radius; i <= radius; ++i) {
        const float x = float(i) * dx;
        g[size_t(i + radius)] = std::exp(-kPi * kPi * x * x / b);
        sum += g[size_t(i + radius)];
      }
      for (float& v : g) v /= sum;
      const float weight = a * std::sqrt(kPi / b) * sum * sum;
      total += weight;
      filters[c].terms.emplace_back(weight, std::move(g));
    }
    for (auto& term : filters[c].terms) term.first /= total;
  }
  return filters;
}

struct FeatureKernels {
  Kernel gaussian, edge, point;  // gaussian sums to 1; edge and point: positives sum to 1, negatives to -1
};

FeatureKernels makeFeatureKernels(float ppd) {
  const float sd = 0.5f * kFeatureWidth * ppd;
  const int radius = int(std::ceil(3.0f * sd));
  FeatureKernels k;
  float gaussianSum = 0.0f;
  for (int i = -radius; i <= radius; ++i) {
    const float x = float(i);
    const float g = std::exp(-(x * x) / (2.0f * sd * sd));
    k.gaussian.push_back(g);
    k.edge.push_back(-x * g);
    k.point.push_back((x * x / (sd * sd) - 1.0f) * g);
    gaussianSum += g;
  }
  for (float& v : k.gaussian) v /= gaussianSum;
  for (Kernel* kernel : {&k.edge, &k.point}) {
    float positive = 0.0f, negative = 0.0f;
    for (float v : *kernel) (v > 0.0f ? positive : negative) += v;
    for (float& v : *kernel) v = v > 0.0f ? v / positive : (v < 0.0f ? v / -negative : 0.0f);
  }
  return k;
}

// ---- Pipelines -----------------------------------------------------------------------------------------

struct Scratch {
  Plane a, b;
  FilterScratch filter;
  Scratch(uint32_t w, uint32_t h) : a(w, h), b(w, h) {}
};

std::array<Plane, 3> toYcxcz(const Rgba8Image& image) {
  const auto& decode = srgbDecodeTable();
  std::array<Plane, 3> out{Plane(image.width, image.height), Plane(image.width, image.height),
                           Plane(image.width, image.height)};
  for (size_t i = 0; i < out[0].v.size(); ++i) {
    const uint8_t* p = &image.pixels[4 * i];
    const Color c = xyzToYcxcz(linearRgbToXyz({decode[p[0]], decode[p[1]], decode[p[2]]}));
    out[0].v[i] = c.x;
    out[1].v[i] = c.y;
    out[2].v[i] = c.z;
  }
  return out;
}

// Colour pipeline, one image: CSF-filtered, clamped to the linear RGB cube, Hunt-adjusted L*a*b*.
std::array<Plane, 3> filteredHuntLab(const std::array<Plane, 3>& ycxcz, const std::array<Csf, 3>& csf,
                                     Scratch& scratch) {
  const uint32_t w = ycxcz[0].width, h = ycxcz[0].height;
  std::array<Plane, 3> out{Plane(w, h), Plane(w, h), Plane(w, h)};
  for (size_t c = 0; c < 3; ++c) {
    bool first = true;
    for (const auto& [weight, kernel] : csf[c].terms) {
      filterRows(ycxcz[c], scratch.a, kernel, scratch.filter);
      filterColumns(scratch.a, out[c], kernel, scratch.filter, false, !first, weight);
      first = false;
    }
  }
  for (size_t i = 0; i < out[0].v.size(); ++i) {
    Color rgb = xyzToLinearRgb(ycxczToXyz({out[0].v[i], out[1].v[i], out[2].v[i]}));
    rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f), std::clamp(rgb.z, 0.0f, 1.0f)};
    const Color lab = huntAdjustedLab(rgb);
    out[0].v[i] = lab.x;
    out[1].v[i] = lab.y;
    out[2].v[i] = lab.z;
  }
  return out;
}

// Feature pipeline, one image: edge and point detector magnitudes on the normalised luminance.
struct Features {
  Plane edge, point;
};

Features detectFeatures(const Plane& ycxczY, const FeatureKernels& k, Scratch& scratch) {
  const uint32_t w = ycxczY.width, h = ycxczY.height;
  Plane luminance(w, h);
  for (size_t i = 0; i < luminance.v.size(); ++i) luminance.v[i] = (ycxczY.v[i] + 16.0f) / 116.0f;

  // Each detector is derivative(x)·gaussian(y) for the x component and gaussian(x)·derivative(y) for y.
  Features f{Plane(w, h), Plane(w, h)};
  Plane& smoothedRows = scratch.a;
  Plane& derivativeRows = scratch.b;
  Plane yComponent(w, h);
  filterRows(luminance, smoothedRows, k.gaussian, scratch.filter);
  for (auto [derivative, magnitude] : {std::pair{&k.edge, &f.edge}, std::pair{&k.point, &f.point}}) {
    filterRows(luminance, derivativeRows, *derivative, scratch.filter, true);
    filterColumns(derivativeRows, *magnitude, k.gaussian, scratch.filter);
    filterColumns(smoothedRows, yComponent, *derivative, scratch.filter, true);
    for (size_t i = 0; i < magnitude->v.size(); ++i)
      magnitude->v[i] = std::sqrt(magnitude->v[i] * magnitude->v[i] + yComponent.v[i] * yComponent.v[i]);
  }
  return f;
}

// Sorts non-negative floats (whose bit patterns order like the values): two 16-bit LSD radix passes.
std::vector<float> sortedNonNegative(const std::vector<float>& values) {
  std::vector<uint32_t> keys(values.size()), other(values.size());
  for (size_t i = 0; i < values.size(); ++i) keys[i] = std::bit_cast<uint32_t>(std::max(values[i], 0.0f));
  std::vector<size_t> offsets(65536);
  for (int shift : {0, 16}) {
    std::fill(offsets.begin(), offsets.end(), 0);
    for (uint32_t k : keys) ++offsets[(k >> shift) & 0xffff];
    size_t start = 0;
    for (size_t& o : offsets) start += std::exchange(o, start);
    for (uint32_t k : keys) other[offsets[(k >> shift) & 0xffff]++] = k;
    keys.swap(other);
  }
  std::vector<float> sorted(values.size());
  for (size_t i = 0; i < keys.size(); ++i) sorted[i] = std::bit_cast<float>(keys[i]);
  return sorted;
}

void pool(FlipResult& r) {
  const size_t n = r.errorMap.size();
  if (n == 0) return;
  double sum = 0.0;
  for (float e : r.errorMap) sum += double(e);
  r.mean = sum / double(n);
  const std::vector<float> sorted = sortedNonNegative(r.errorMap);
  r.max = double(sorted.back());
  r.median = n % 2 ? double(sorted[n / 2]) : 0.5 * (double(sorted[n / 2 - 1]) + double(sorted[n / 2]));
  // The reference tool's weighted percentile: the first index whose running sum reaches half the total,
  // averaged with the next value.
  const double half = 0.5 * sum;
  double running = 0.0;
  size_t i = 0;
  for (; i < n; ++i) {
    running += double(sorted[i]);
    if (running >= half) break;
  }
  i = std::min(i, n - 1);
  r.weightedMedian = 0.5 * (double(sorted[i]) + double(sorted[std::min(i + 1, n - 1)]));
}

void checkImage(const Rgba8Image& image, const char* role) {
  if (image.pixels.size() != size_t(image.width) * image.height * 4)
    throw std::invalid_argument(std::string("flipLdr: ") + role + " pixel buffer does not match its size");
}

// matplotlib's magma colour map (van der Walt and Smith, CC0), the table the reference tool uses, as 8-bit sRGB.
constexpr uint8_t kMagma[256][3] = {
    {0, 0, 4}, {1, 0, 5}, {1, 1, 6}, {1, 1, 8}, {2, 1, 9}, {2, 2, 11}, {2, 2, 13}, {3, 3, 15},
    {3, 3, 18}, {4, 4, 20}, {5, 4, 22}, {6, 5, 24}, {6, 5, 26}, {7, 6, 28}, {8, 7, 30}, {9, 7, 32},
    {10, 8, 34}, {11, 9, 36}, {12, 9, 38}, {13, 10, 41}, {14, 11, 43}, {16, 11, 45}, {17, 12, 47}, {18, 13, 49},
    {19, 13, 52}, {20, 14, 54}, {21, 14, 56}, {22, 15, 59}, {24, 15, 61}, {25, 16, 63}, {26, 16, 66}, {28, 16, 68},
    {29, 17, 71}, {30, 17, 73}, {32, 17, 75}, {33, 17, 78}, {34, 17, 80}, {36, 18, 83}, {37, 18, 85}, {39, 18, 88},
    {41, 17, 90}, {42, 17, 92}, {44, 17, 95}, {45, 17, 97}, {47, 17, 99}, {49, 17, 101}, {51, 16, 103}, {52, 16, 105},
    {54, 16, 107}, {56, 16, 108}, {57, 15, 110}, {59, 15, 112}, {61, 15, 113}, {63, 15, 114}, {64, 15, 116}, {66, 15, 117},
    {68, 15, 118}, {69, 16, 119}, {71, 16, 120}, {73, 16, 120}, {74, 16, 121}, {76, 17, 122}, {78, 17, 123}, {79, 18, 123},
    {81, 18, 124}, {82, 19, 124}, {84, 19, 125}, {86, 20, 125}, {87, 21, 126}, {89, 21, 126}, {90, 22, 126}, {92, 22, 127},
    {93, 23, 127}, {95, 24, 127}, {96, 24, 128}, {98, 25, 128}, {100, 26, 128}, {101, 26, 128}, {103, 27, 128}, {104, 28, 129},
    {106, 28, 129}, {107, 29, 129}, {109, 29, 129}, {110, 30, 129}, {112, 31, 129}, {114, 31, 129}, {115, 32, 129}, {117, 33, 129},
    {118, 33, 129}, {120, 34, 129}, {121, 34, 130}, {123, 35, 130}, {124, 35, 130}, {126, 36, 130}, {128, 37, 130}, {129, 37, 129},
    {131, 38, 129}, {132, 38, 129}, {134, 39, 129}, {136, 39, 129}, {137, 40, 129}, {139, 41, 129}, {140, 41, 129}, {142, 42, 129},
    {144, 42, 129}, {145, 43, 129}, {147, 43, 128}, {148, 44, 128}, {150, 44, 128}, {152, 45, 128}, {153, 45, 128}, {155, 46, 127},
    {156, 46, 127}, {158, 47, 127}, {160, 47, 127}, {161, 48, 126}, {163, 48, 126}, {165, 49, 126}, {166, 49, 125}, {168, 50, 125},
    {170, 51, 125}, {171, 51, 124}, {173, 52, 124}, {174, 52, 123}, {176, 53, 123}, {178, 53, 123}, {179, 54, 122}, {181, 54, 122},
    {183, 55, 121}, {184, 55, 121}, {186, 56, 120}, {188, 57, 120}, {189, 57, 119}, {191, 58, 119}, {192, 58, 118}, {194, 59, 117},
    {196, 60, 117}, {197, 60, 116}, {199, 61, 115}, {200, 62, 115}, {202, 62, 114}, {204, 63, 113}, {205, 64, 113}, {207, 64, 112},
    {208, 65, 111}, {210, 66, 111}, {211, 67, 110}, {213, 68, 109}, {214, 69, 108}, {216, 69, 108}, {217, 70, 107}, {219, 71, 106},
    {220, 72, 105}, {222, 73, 104}, {223, 74, 104}, {224, 76, 103}, {226, 77, 102}, {227, 78, 101}, {228, 79, 100}, {229, 80, 100},
    {231, 82, 99}, {232, 83, 98}, {233, 84, 98}, {234, 86, 97}, {235, 87, 96}, {236, 88, 96}, {237, 90, 95}, {238, 91, 94},
    {239, 93, 94}, {240, 95, 94}, {241, 96, 93}, {242, 98, 93}, {242, 100, 92}, {243, 101, 92}, {244, 103, 92}, {244, 105, 92},
    {245, 107, 92}, {246, 108, 92}, {246, 110, 92}, {247, 112, 92}, {247, 114, 92}, {248, 116, 92}, {248, 118, 92}, {249, 120, 93},
    {249, 121, 93}, {249, 123, 93}, {250, 125, 94}, {250, 127, 94}, {250, 129, 95}, {251, 131, 95}, {251, 133, 96}, {251, 135, 97},
    {252, 137, 97}, {252, 138, 98}, {252, 140, 99}, {252, 142, 100}, {252, 144, 101}, {253, 146, 102}, {253, 148, 103}, {253, 150, 104},
    {253, 152, 105}, {253, 154, 106}, {253, 155, 107}, {254, 157, 108}, {254, 159, 109}, {254, 161, 110}, {254, 163, 111}, {254, 165, 113},
    {254, 167, 114}, {254, 169, 115}, {254, 170, 116}, {254, 172, 118}, {254, 174, 119}, {254, 176, 120}, {254, 178, 122}, {254, 180, 123},
    {254, 182, 124}, {254, 183, 126}, {254, 185, 127}, {254, 187, 129}, {254, 189, 130}, {254, 191, 132}, {254, 193, 133}, {254, 194, 135},
    {254, 196, 136}, {254, 198, 138}, {254, 200, 140}, {254, 202, 141}, {254, 204, 143}, {254, 205, 144}, {254, 207, 146}, {254, 209, 148},
    {254, 211, 149}, {254, 213, 151}, {254, 215, 153}, {254, 216, 154}, {253, 218, 156}, {253, 220, 158}, {253, 222, 160}, {253, 224, 161},
    {253, 226, 163}, {253, 227, 165}, {253, 229, 167}, {253, 231, 169}, {253, 233, 170}, {253, 235, 172}, {252, 236, 174}, {252, 238, 176},
    {252, 240, 178}, {252, 242, 180}, {252, 244, 182}, {252, 246, 184}, {252, 247, 185}, {252, 249, 187}, {252, 251, 189}, {252, 253, 191},
};

}  // namespace

float srgbToLinear(uint8_t encoded) { return srgbDecodeTable()[encoded]; }

FlipResult flipLdr(const Rgba8Image& reference, const Rgba8Image& test, double pixelsPerDegree) {
  checkImage(reference, "reference");
  checkImage(test, "test");
  if (reference.width != test.width || reference.height != test.height)
    throw std::invalid_argument("flipLdr: images differ in size");
  if (!(pixelsPerDegree > 0.0)) throw std::invalid_argument("flipLdr: pixels per degree must be positive");

  FlipResult result;
  result.width = reference.width;
  result.height = reference.height;
  if (reference.pixels.empty()) return result;

  const float ppd = float(pixelsPerDegree);
  const std::array<Csf, 3> csf = makeCsfFilters(ppd);
  const FeatureKernels featureKernels = makeFeatureKernels(ppd);
  Scratch scratch(reference.width, reference.height);

  const std::array<Plane, 3> refYcxcz = toYcxcz(reference), testYcxcz = toYcxcz(test);
  const std::array<Plane, 3> refLab = filteredHuntLab(refYcxcz, csf, scratch);
  const std::array<Plane, 3> testLab = filteredHuntLab(testYcxcz, csf, scratch);
  const Features refFeatures = detectFeatures(refYcxcz[0], featureKernels, scratch);
  const Features testFeatures = detectFeatures(testYcxcz[0], featureKernels, scratch);

  const float cmax = colorDistanceMax();
  const float invSqrt2 = 1.0f / std::numbers::sqrt2_v<float>;
  result.errorMap.resize(refLab[0].v.size());
  for (size_t i = 0; i < result.errorMap.size(); ++i) {
    const float colorError = remapColorError(hyab({refLab[0].v[i], refLab[1].v[i], refLab[2].v[i]},
                                                  {testLab[0].v[i], testLab[1].v[i], testLab[2].v[i]}),
                                             cmax);
    const float edgeDifference = std::abs(refFeatures.edge.v[i] - testFeatures.edge.v[i]);
    const float pointDifference = std::abs(refFeatures.point.v[i] - testFeatures.point.v[i]);
    const float featureError = std::pow(invSqrt2 * std::max(edgeDifference, pointDifference), kQf);
    result.errorMap[i] = std::pow(colorError, 1.0f - featureError);
  }
  pool(result);
  return result;
}

Rgba8Image flipHeatmap(const FlipResult& result) {
  Rgba8Image image;
  image.width = result.width;
  image.height = result.height;
  image.pixels.resize(result.errorMap.size() * 4);
  for (size_t i = 0; i < result.errorMap.size(); ++i) {
    const float e = std::clamp(result.errorMap[i], 0.0f, 1.0f);
    const uint8_t* c = kMagma[size_t(std::lround(e * 255.0f))];
    image.pixels[4 * i + 0] = c[0];
    image.pixels[4 * i + 1] = c[1];
    image.pixels[4 * i + 2] = c[2];
    image.pixels[4 * i + 3] = 255;
  }
  return image;
}

}  // namespace sg::image
